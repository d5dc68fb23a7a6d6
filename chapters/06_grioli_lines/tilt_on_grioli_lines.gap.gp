# Panel (b): the gap between the two sides, below, above and on the line.
set title '(b) the gap |cos^2 φ - (B - A)/(C - A)|'
set logscale y
set format y '10^{%T}'
set ylabel 'gap'
set yrange [1e-19:1e6]
set xrange [1e-6:1e6]
set key inside top right box opaque font ',10'
plot '-' using 1:6 with lines ls 1 title 'below the line', '' using 1:9 with lines ls 2 title 'above the line', '' using 1:11 with points ls 7 pt 6 title 'on the line, eigen-solver', '' using 1:10 with lines ls 3 lw 3 title 'on the line, closed forms, relative to sin^2 φ'
