# accuracy_vs_distance.svg (closed_form_accuracy.cpp): the closed forms' relative errors
# against binary128 along a Grioli line, printed (dashed) and rewritten (solid); the scene
# sends its table once per curve.
set encoding utf8
set logscale xy
set format x '10^{%T}'
set format y '10^{%T}'
set xlabel 'distance L / body size √(C_g/μ), on a Grioli line'
set ylabel 'relative error against binary128'
set yrange [1e-18:10]
set key below box opaque maxrows 3 font ',10'
set title 'printed forms (dashed) lose what the rewritten ones (solid) keep'
plot '-' using 1:2 with lines ls 1 dt 2 title 'A, printed (5.3)', '' using 1:3 with lines ls 1 title 'A, rewritten', '' using 1:4 with points ls 1 pt 6 title 'A, eigen-solver', '' using 1:5 with lines ls 2 dt 2 title 'C - B, printed (5.3)', '' using 1:6 with lines ls 2 title 'C - B, rewritten', '' using 1:7 with points ls 2 pt 4 title 'C - B, eigen-solver', '' using 1:8 with lines ls 3 dt 2 title 'sin^2 φ, printed (5.12)', '' using 1:9 with lines ls 3 title 'sin^2 φ, rewritten'
