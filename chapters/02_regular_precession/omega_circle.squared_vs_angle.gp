# omega_squared_vs_angle.svg (omega_circle.cpp): |Ω|^2 as (1.6) prints it, corrected, and
# measured, against the angle between a and b.
set title 'Is |Ω|^2 = (α + β)^2? [P, (1.6)] against direct evaluation'
set xlabel 'angle between a and b (degrees)'
set ylabel '|Ω|^2'
set key bottom left
set xrange [0:180]
set xtics 30
plot '-' using 1:2 with lines ls 9 lw 2 title '(α + β)^2, as printed in (1.6)', '-' using 1:2 with lines ls 1 title 'α^2 + β^2 + 2αβ({/:Bold a}, {/:Bold b})', '-' using 1:2 with points ls 2 pt 7 ps 0.6 title 'measured from R(t)'
