# initial_position.svg (grioli_initial_position.cpp): Item II at t = 0, the vectors k, b, a
# and the inertia axes, the inertia ellipsoid with its circular section, the path of G.
set view 66, 58, 1.3, 1.0
set view equal xyz
unset border
unset tics
unset grid
set key at screen 0.01, 0.90 top left font ',10'
set xrange [-1.5:1.5]
set yrange [-1.5:1.5]
set zrange [-1.3:1.6]
set xyplane 0
set title 'Item II at t = 0: k up, b = R_B(0) tilted by θ, a = z(0) along [b, k]'
set arrow 1 from 0,0,0 to @k@ head filled size 0.08,20 lw 2.5 lc rgb '#000000'
set label 1 'k (up)' at @k_label@ tc rgb '#000000'
set arrow 2 from 0,0,0 to @b@ head filled size 0.08,20 lw 2.5 lc rgb '#0072B2'
set label 2 'b = R_B(0)' at @b_label@ tc rgb '#0072B2'
set arrow 3 from 0,0,0 to @a@ head filled size 0.08,20 lw 2.5 lc rgb '#D55E00'
set label 3 'a = z(0)' at @a_label@ tc rgb '#D55E00'
set label 4 'G' at @G_label@ tc rgb '#D55E00'
set label 5 'R_A' at @RA_label@ tc rgb '#555555'
set label 6 'R_C' at @RC_label@ tc rgb '#555555'
set label 7 'O' at 0.04,0,-0.12
set label 8 'θ' at @theta_label@
splot '-' with lines lc rgb '#999999' dt 2 lw 1.2 title 'inertia axes R_A, R_C', '-' with lines lc rgb '#56B4E9' lw 1 title 'inertia ellipsoid at O', '-' with lines lc rgb '#009E73' lw 2.5 title 'its circular section, orthogonal to a', '-' with lines lc rgb '#E69F00' dt 3 lw 1.5 title 'path of G: a circle about b', '-' with points pt 7 ps 1.6 lc rgb '#D55E00' title 'centre of mass G', '-' with lines lc rgb '#bbbbbb' lw 1 title 'plane of k and b (the paper sheet)', '-' with lines lc rgb '#000000' lw 1 notitle
