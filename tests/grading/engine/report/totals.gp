set title 'Totals of @submissions@ submissions (of @max_total@ points)'
set xlabel 'total score (points)'
set ylabel 'submissions'
set boxwidth @box_width@ absolute
set yrange [0:*]
set xrange [0:@xmax@]
plot 'totals.dat' using ($1+@half_width@):2 with boxes lc rgb '#4477aa' notitle
