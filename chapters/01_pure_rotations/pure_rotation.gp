# pure_rotation.svg (pure_rotation.cpp): the axis, the corners' paths, the body at --frames
# instants of one turn and at t = 0.
set view 58, 32, 1.0, 1.2
set view equal xyz
set xyplane 0
set border 4095
set xlabel 'e_1'
set ylabel 'e_2'
set zlabel 'e_3'
set key at screen 0.01, 0.99 top left
unset grid
set xtics 1
set ytics 1
set ztics 1
splot '-' with lines ls 7 lw 2.5 title 'axis a', '-' with lines ls 8 lw 1 title 'paths of the corners', '-' with lines ls 1 lw 1.2 title 'body at t_k = k T / @frames@', '-' with lines ls 2 lw 2.5 title 'body at t = 0'
