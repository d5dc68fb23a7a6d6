unset key
set title @title@
set ylabel @ylabel@
plot '-' with linespoints ls 1 title 'student RK4, h = 0.2 ... 0.001', '-' with linespoints ls 2 title 'GSL rkf45, tol = 1e-4 ... 1e-13', '-' with linespoints ls 3 title 'GSL rk8pd, tol = 1e-4 ... 1e-14'
