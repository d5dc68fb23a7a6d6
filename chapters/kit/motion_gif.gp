# The animated GIF beside a --motion FILE (kit/motion.cpp, write_gif): the lab, then one frame
# per sample (motion_gif_frame.gp) with its curves' data.
unset border
unset tics
unset key
set view 62, 38, 1.9
set view equal xyz
set xrange [@xmin@:@xmax@]
set yrange [@ymin@:@ymax@]
set zrange [@zmin@:@zmax@]
# The curves: 1 the body's outline, 2-4 its principal axes, 5 the vertical k, 6 a body cone,
# 7 a space cone, 8 the trail of the centre of mass, 9 the trail of the tip.
set style line 101 lw 1.2 lc rgb '#777777'
set style line 102 lw 2 lc rgb '#009E73'
set style line 103 lw 2 lc rgb '#0072B2'
set style line 104 lw 2 lc rgb '#D55E00'
set style line 105 lw 2 lc rgb '#000000'
set style line 106 lw 1 lc rgb '#E69F00'
set style line 107 lw 1 lc rgb '#999999'
set style line 108 lw 1.5 lc rgb '#CC79A7'
set style line 109 lw 1.5 lc rgb '#56B4E9'
