# regions_plane.svg, [P] Figure 5 (regions_plane.cpp): the plane of the smallest and largest
# axes at G, its regions I-VI (regions_plane.label.gp), the hyperbola B = C, the Grioli lines
# and the circular-section normals (regions_plane.plot.gp).
set size ratio -1
set xrange [@xmin@:@xmax@]
set yrange [@ymin@:@ymax@]
set xlabel 'x_A (along the smallest axis at G)'
set ylabel 'x_C (along the largest axis at G)'
set key below maxrows 3 box opaque
set border 15
unset grid
set style fill transparent solid 0.45 noborder
