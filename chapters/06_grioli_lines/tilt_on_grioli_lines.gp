# tilt_on_grioli_lines.svg (tilt_on_grioli_lines.cpp), panel (a): the two sides of Theorem 1's
# condition on a Grioli line and on lines tilted off it; the scene sends its table once per
# curve, then panel (b) (tilt_on_grioli_lines.gap.gp), and the kit ends the multiplot.
set encoding utf8
set multiplot layout 1,2
set logscale x
set format x '10^{%T}'
set xlabel 'distance L / body size √(C_g/μ)'
set key at graph 0.98, graph 0.55 right bottom box opaque font ',10'
set title '(a) the two sides of Theorem 1''s condition (lines ± @off@ rad off)'
set ylabel 'cos^2 φ  and  (B - A)/(C - A)'
set yrange [0.5:1.02]
set xrange [1e-2:1e2]
plot '-' using 1:2 with lines ls 3 lw 3 title 'on the line: cos^2 φ', '' using 1:3 with lines ls 7 dt 2 title '      (B-A)/(C-A)', '' using 1:4 with lines ls 1 title 'below: cos^2 φ', '' using 1:5 with lines ls 1 dt 2 title '      (B-A)/(C-A)', '' using 1:7 with lines ls 2 title 'above: cos^2 φ', '' using 1:8 with lines ls 2 dt 2 title '      (B-A)/(C-A)'
