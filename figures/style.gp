# The workbook's one gnuplot style, at the head of every figure: embedded in the kit (kit::gp::style, chapters/kit/figure.cpp).
set border lw 1 lc rgb '#444444'
set grid lw 0.5 lc rgb '#dddddd'
set key box opaque
set tics nomirror out scale 0.6
set border 3
set format y '%g'
set samples 400
# Line styles 1-8: a colour-blind-safe palette (Okabe-Ito), then dashed guides 9-10.
set style line 1 lc rgb '#0072B2' lw 2 pt 7 ps 0.6
set style line 2 lc rgb '#D55E00' lw 2 pt 5 ps 0.6
set style line 3 lc rgb '#009E73' lw 2 pt 9 ps 0.7
set style line 4 lc rgb '#CC79A7' lw 2 pt 11 ps 0.7
set style line 5 lc rgb '#E69F00' lw 2 pt 13 ps 0.7
set style line 6 lc rgb '#56B4E9' lw 2 pt 3 ps 0.6
set style line 7 lc rgb '#000000' lw 2 pt 1 ps 0.6
set style line 8 lc rgb '#999999' lw 1.5 pt 6 ps 0.6
set style line 9 lc rgb '#777777' lw 1 dt 2
set style line 10 lc rgb '#777777' lw 1 dt 4
