# The right panel: the most unstable body's d for each δ (@curves@: grioli_stability.delta.gp,
# one each), against the Floquet growth δ |μ|^{t/P} = δ exp(growth t/P).
unset logscale x
set title 'the most unstable body of the map: d, and the Floquet growth |μ|^{t/P}'
set ylabel 'd'
set yrange [1e-9:10]
set xrange [0:80]
set key bottom right
plot @curves@, 1e-6*exp(@growth@*x) with lines lc rgb '#777777' dt 4 title 'δ |μ|^{t/P}, δ = 10^{-6}'
