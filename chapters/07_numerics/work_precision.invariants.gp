# invariants_grioli_100.svg (work_precision.cpp): what each method keeps, three panels
# (work_precision.invariants_panel.gp; the last, work_precision.invariants_key_panel.gp, draws
# the one key, on the right of the three); the kit ends the multiplot.
set multiplot layout 1, 3 margins 0.06, 0.8, 0.11, 0.86 spacing 0.06, 0 title 'Grioli, 100 periods: what each method keeps (largest over the run)'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'run time (s)'
set yrange [1e-17:10]
