# grioli_two_senses.svg (grioli_frequency.cpp): the distance from the precession when Ω(0)
# is scaled by λ, both senses (two branches, broken by a blank line).
set title 'Ω(0) scaled by λ: distance from R^b(λαt) R^a(λαt), two periods, body (@A@, @B@, @C@)'
set xlabel 'λ'
set ylabel 'max geodesic angle (rad)'
set logscale y
set format y '10^{%L}'
set yrange [1e-15:10]
set xrange [-1.65:1.65]
set key bottom center font ',9'
set arrow from -1, graph 0 to -1, graph 1 nohead dt 3 lc rgb '#999999'
set arrow from 1, graph 0 to 1, graph 1 nohead dt 3 lc rgb '#999999'
set label 'clockwise' at -1.05, 1e-14 right font ',10'
set label 'counter-clockwise' at 1.05, 1e-14 font ',10'
unset key
plot '-' with linespoints ls 1 pt 7 ps 0.5 notitle
