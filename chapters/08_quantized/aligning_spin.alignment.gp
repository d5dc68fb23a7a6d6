# spin_alignment.svg (aligning_spin.cpp): the angle between S and B against time, by (6.2)
# (solid) and with β = 0 (dashed), one curve per start (the scene writes them).
set title '(6.2) with β = @beta@, |{/:Bold B}| = @B@, e/mc = @e_over_mc@: the angle between {/:Bold S} and {/:Bold B}'
set xlabel 't'
set ylabel 'angle (degrees)'
set yrange [0:180]
set ytics 30
set key outside right top font ',9'
plot @curves@
