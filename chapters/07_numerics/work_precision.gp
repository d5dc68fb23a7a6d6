# wp_<scenario>.svg (work_precision.cpp): error against run time, one panel per family of
# methods (work_precision.panel.gp, the last one work_precision.bottom_panel.gp, each with
# work_precision.plot.gp), sharing the time axis; the kit ends the multiplot.
set multiplot title @title@
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set ylabel 'error: R (rad), Ω (rel.)'
set yrange [1e-16:10]
set ytics 100
set xrange [@tmin@:@tmax@]
set lmargin at screen 0.1
set rmargin at screen 0.62
set key at screen 0.64, graph 1 left top Left reverse font ',10' spacing 1.05 samplen 2.5 nobox
