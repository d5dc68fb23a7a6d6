# grioli_frames.svg (grioli_frames.cpp): [P]'s Figures 2 and 3 side by side, each panel
# (grioli_frames.panel.gp) with its arrows (grioli_frames.arrow.gp); the key is the first
# panel's (grioli_frames.next_panel.gp); the kit ends the multiplot.
set view 72, 28, 1.7, 1.0
set view equal xyz
unset border
unset tics
unset grid
set key at screen 0.5, 0.1 center top horizontal maxrows 2 font ',10'
set xrange [-1.4:1.4]
set yrange [-1.4:1.4]
set zrange [-1.1:1.5]
set xyplane 0
set multiplot layout 1, 2 title 'One counter-clockwise Grioli precession, a quarter period apart (lab of Item II, k up)' margins 0.01, 0.99, 0.12, 0.9 spacing 0.02
