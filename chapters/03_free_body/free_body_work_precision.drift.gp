# free_body_drift.svg (free_body_work_precision.cpp), two panels: the energy's drift, then
# (free_body_work_precision.orthogonality.gp) R's distance from a rotation; the kit ends the
# multiplot.
set multiplot layout 1, 2 title 'What the integrators do to the invariants (max over the run)'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'run time (s)'
set key bottom left font ',9'
set title 'energy (6.9)'
set ylabel '|E(t) - E(0)| / E(0)'
plot '-' with linespoints ls 1 title 'student RK4', '-' with linespoints ls 2 title 'rkf45', '-' with linespoints ls 3 title 'rk8pd'
