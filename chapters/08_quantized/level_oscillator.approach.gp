# level_approach.svg (level_oscillator.cpp): E(t) - E_n from each start (@curves@:
# level_oscillator.approach_start.gp, one each), and the averaged asymptote where there is one
# (@asymptotes@: level_oscillator.asymptote.gp).
set title 'Approach to the levels: E(t) - E_{n} (solid), the averaged asymptote (dashed)'
set xrange [1:@T@]
set logscale xy
set format y '10^{%L}'
set xlabel 't'
set ylabel '(E - E_{n}) / E_{0}'
set key outside right top font ',9'
plot @curves@@asymptotes@
