# The second panel of free_body_drift.svg: how far R is from a rotation.
set title 'orthogonality of R'
set ylabel '‖R^T R − 1‖_F'
plot '-' with linespoints ls 1 title 'student RK4', '-' with linespoints ls 2 title 'rkf45', '-' with linespoints ls 3 title 'rk8pd'
