# spin_sphere.svg (aligning_spin.cpp): the unit sphere in coordinates (e1, e2, b), B up, the
# circle of β = 0 from 60°, and the paths of (6.2) from the starts shown (@paths@:
# aligning_spin.path.gp, one each).
set view 70, 25, 1.45, 1.45
set view equal xyz
set xrange [-1.05:1.05]
set yrange [-1.05:1.05]
set zrange [-1.05:1.45]
unset border
unset tics
unset grid
set xyplane 0
set key at screen 0.99, 0.99 top right font ',9'
set margins 0, 0, 0, 0
set arrow from 0, 0, 1 to 0, 0, 1.4 head filled lw 3 lc rgb 'black'
set label 'B' at 0.08, 0, 1.35 font ',14'
splot '-' with lines lc rgb '#cccccc' lw 0.7 notitle, '-' with lines lc rgb 'black' dt 2 lw 1.5 title 'β = 0 from 60°'@paths@
