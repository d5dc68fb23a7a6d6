# accuracy_nearly_symmetric.svg (closed_form_accuracy.cpp): the same errors for nearly
# symmetric bodies, B_g → A_g; the scene sends its table once per curve.
set encoding utf8
set logscale xy
set format x '10^{%T}'
set format y '10^{%T}'
set xlabel '(B_g - A_g) / (C_g - A_g)   (A_g = 1, C_g = 1.5, L = 0.1 body sizes)'
set ylabel 'relative error against binary128'
set yrange [1e-18:10]
set xrange [*:*] reverse
set key below box opaque maxrows 2 font ',10'
set title 'nearly symmetric bodies: B_g → A_g'
plot '-' using 1:2 with lines ls 3 dt 2 title 'cos^2 φ on the line, printed (5.12)', '' using 1:3 with lines ls 3 title 'cos^2 φ, rewritten', '' using 1:4 with lines ls 2 dt 2 title 'B - A, printed (5.3)', '' using 1:5 with lines ls 2 title 'B - A, rewritten', '' using 1:6 with lines ls 4 dt 2 title 'h_{crit}, printed (5.8)', '' using 1:7 with lines ls 4 title 'h_{crit}, rewritten'
