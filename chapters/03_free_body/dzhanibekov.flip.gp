# dzhanibekov_flip.svg (dzhanibekov.cpp): the components of Ω through the flips, exact and by
# the student's RK4. The key goes below when the label of a rounded start is long.
set title 'Spin about the middle axis, perturbed by δ: the body flips (exact motion)'
set xlabel 't'
set ylabel 'components of Ω'
set key @key@
set yrange [@ymin@:@ymax@]
plot '-' using 1:2 with lines ls 3 title 'smallest-axis component × 10', '-' using 1:2 with lines ls 1 lw 2.5 title 'middle-axis component', '-' using 1:2 with lines ls 4 title 'largest-axis component × 10', '-' using 1:2 with lines ls 9 lw 2 title @flips@, '-' using 1:2 with points ls 2 pt 6 ps 0.5 title 'student RK4'
