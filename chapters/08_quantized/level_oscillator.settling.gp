# level_settling.svg (level_oscillator.cpp): energy against time from each start (@curves@:
# level_oscillator.start.gp, one each), and the averaged equation's from each (the first with its
# key entry, then @averaged@: level_oscillator.averaged.gp); dotted lines at the levels.
set title 'The oscillator (6.1) with k(E) = @kappa@ |sin(πE/E_{0})|^{@power@}: energy against time'
set xrange [0:@tmax@]
set xlabel 't'
set ylabel 'E / E_{0}'
set key outside right top font ',9'
set yrange [0:@Emax@]
do for [n = 0:@levels@] {
    set arrow from graph 0, first n to graph 1, first n nohead dt 3 lc rgb '#999999'
}
plot @curves@, '-' with lines lc rgb 'black' dt 2 lw 1 title 'averaged: dE/dt = -k(E) E/m'@averaged@
