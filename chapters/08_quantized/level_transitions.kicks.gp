# level_transitions.svg (level_transitions.cpp): energy against time without kicks and with
# kicks, one curve per seed (@seeds@: level_transitions.seed.gp, one each); dotted lines at the levels.
set title 'Kicks q'' += @eps@ N(0,1) every @tau@, starting on E = @n_start@ E_{0}: energy against time'
set xlabel 't'
set ylabel 'E / E_{0}'
set key at graph 0.98, graph 0.8 right top font ',9' box opaque
set yrange [0:@Emax@]
do for [n = 0:@n_start@] {
    set arrow from graph 0, first n to graph 1, first n nohead dt 3 lc rgb '#999999'
}
plot '-' with lines lc rgb 'black' dt 2 lw 2 title 'no kicks'@seeds@
