# omega_circle.svg (omega_circle.cpp): the axis a, the body cone's rays to Ω(t), the circle
# that (1.5)-(1.7) predict, and Ω(t) from finite differences.
set view 62, 38, 0.95, 1.0
set view equal xyz
set xyplane 0
set border 4095
unset grid
set xlabel 'Ω_1'
set ylabel 'Ω_2'
set zlabel 'Ω_3'
set key at screen 0.01, 0.99 top left
splot '-' with lines ls 7 lw 2.5 title 'axis a', '-' with lines ls 8 lw 1 title 'body cone (origin to Ω(t))', '-' with lines ls 1 lw 2 title 'circle predicted from (1.5)-(1.7)', '-' with points ls 2 pt 7 ps 0.5 title 'Ω(t) from finite differences of R(t)'
