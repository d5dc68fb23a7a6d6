# two_precessions.svg (grioli_paths.cpp): the two senses of Theorem 1 side by side, one panel
# each (grioli_paths.panel.gp); the kit ends the multiplot.
set multiplot layout 1,2 title 'The two regular precessions of Theorem 1, one period, in a lab with k up'
set view 66, 32, 1.45, 1.0
set view equal xyz
unset border
unset tics
unset grid
set xrange [-1.2:1.2]
set yrange [-1.2:1.2]
set zrange [-1.2:1.4]
set key at screen 0.5, 0.1 center center horizontal maxrows 2 font ',10'
