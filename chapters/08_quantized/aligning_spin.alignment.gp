# spin_alignment.svg (aligning_spin.cpp): the angle between S and B against time, by (6.2)
# (solid) and with β = 0 (dashed), one curve per start: the first with its key entry, the others
# after it (@solid@, @plain@: aligning_spin.solid.gp, aligning_spin.plain.gp, one each).
set title '(6.2) with β = @beta@, |{/:Bold B}| = @B@, e/mc = @e_over_mc@: the angle between {/:Bold S} and {/:Bold B}'
set xlabel 't'
set ylabel 'angle (degrees)'
set yrange [0:180]
set ytics 30
set key outside right top font ',9'
plot '-' with lines ls 1 lw 2 title '(6.2)'@solid@, '-' with lines ls 1 dt 2 lw 1 title 'β = 0'@plain@
