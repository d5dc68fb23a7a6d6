# One panel, after its arrows: the angle θ, the path of G over a period (a circle about b), G,
# and the plane of k and b (the paper sheet, here the x-z plane).
set label 20 'θ' at @theta_at@
set title @title@
splot '-' with lines lc rgb '#E69F00' dt 3 lw 1.5 title 'path of G: a circle about b', '-' with points pt 7 ps 1.5 lc rgb '#D55E00' title 'centre of mass G', '-' with lines lc rgb '#bbbbbb' lw 1 title 'plane of k and b (the paper sheet)', keyentry with lines lc rgb '#555555' lw 1.5 dt 2 title 'dashed: lab vectors (e_1, e_2, e_3; a, b)', keyentry with lines lc rgb '#555555' lw 2.5 title 'solid: inertia axes'
