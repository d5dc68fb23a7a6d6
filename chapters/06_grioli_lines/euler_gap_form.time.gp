# The run-time panel: three curves per body (@curves@: euler_gap_form.body.gp, one each).
set title 'run time of one integration'
set ylabel 'run time (s)'
set yrange [1e-4:10]
plot @curves@, 0.05 with lines ls 9 title 'target 50 ms'
