# The error panel. Its title is double-quoted, so that \n breaks its line: its end is empty,
# or a second line when the instability dominates the error at every × point. Three curves per
# body (@curves@: euler_gap_form.body.gp, one each).
set title "error against Theorem 1 (×: unstable, Chapter 7; at 30: naive gave up)@dominated@"
set ylabel 'max angle between R(t) and R^b(αt)R^a(αt) (rad)'
set yrange [1e-12:100]
plot @curves@, 1e-9 with lines ls 9 title 'target 10^{-9}'
