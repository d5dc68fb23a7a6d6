# Figures 6 and 7 (moments_along_lines.cpp): the principal moments at O along two Grioli lines,
# one panel each (moments_along_lines.panel.gp, .marker.gp, .curves.gp); the kit ends the
# multiplot.
set multiplot layout 1,2
set xlabel 'distance L from G to O'
set ylabel 'moment of inertia at O'
set encoding utf8
set key top left box opaque
set xrange [0:@L_max@]
