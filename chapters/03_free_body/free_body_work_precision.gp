# free_body_work_precision.svg (free_body_work_precision.cpp): error against run time, for the
# student's RK4 and GSL's rkf45 and rk8pd.
set title 'Free body, T = @T@: error against run time (min over repetitions)'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'run time (s)'
set ylabel 'max error: Ω (relative) and R (angle, rad)'
set key top right
plot '-' with linespoints ls 1 title 'student RK4, h = 0.2 ... 0.001', '-' with linespoints ls 2 title 'GSL rkf45, tol = 1e-4 ... 1e-13', '-' with linespoints ls 3 title 'GSL rk8pd, tol = 1e-4 ... 1e-14'
