set title 'Tests of @topic@: the verdicts of the class (numbered as in the table below)'
set style data histograms
set style histogram rowstacked
set boxwidth 0.8
set yrange [0:1]
set ylabel 'share of submissions'
set xtics font ',9'
set key outside right top
plot @data@ using 3:xtic(2) title 'pass' lc rgb '#228833', '' using 4 title 'fail' lc rgb '#ee6677', '' using 5 title 'crash or timeout' lc rgb '#aa3377', '' using 6 title 'build error or missing' lc rgb '#bbbbbb', '' using 7 title 'not started' lc rgb '#66ccee'
