set title 'Each exercise: the share of submissions that pass every test, and that started it'
set xtics rotate by -60 font ',9'
set yrange [0:1.1]
set ylabel 'share of submissions'
set boxwidth 0.7
set key top right
set bmargin 11
set lmargin 10
plot 'exercises.dat' using 1:3:xtic(2) with boxes lc rgb '#228833' title 'pass every test', '' using 1:4 with points pt 7 ps 0.7 lc rgb '#cc3311' title 'started'
