# precession_cones.svg (precession_cones.cpp): three panels (precession_cones.panel.gp), one
# per case; the kit ends the multiplot.
set multiplot layout 1, 3 title 'Space cone (about b, fixed), body cone (about R(t*)a, carried by the body) and the path of a body point'
set view 68, 30, 1.0, 1.25
set view equal xyz
set xyplane 0
unset grid
unset key
set xtics 1
set ytics 1
set ztics 1
set border 4095
