# theorem2_residuals.svg (theorem2_circle_test.cpp), two panels: towards a principal axis,
# then (theorem2_circle_test.separatrix.gp) towards the separatrix; the kit ends the multiplot.
set multiplot layout 1, 2 title 'Free motions: distance of the polhode from a plane and from a circle (relative to its size)'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set yrange [1e-17:10]
set ylabel 'max residual / size of the polhode'
set key bottom left font ',9'
set title 'towards a principal axis (m -> 0)'
set xlabel 'elliptic parameter m'
set xrange [1e-13:1]
plot '-' with linespoints ls 1 title 'plane, about the smallest axis', '-' with linespoints ls 2 title 'plane, about the largest axis', '-' with linespoints ls 3 title 'circle, about the smallest axis', '-' with linespoints ls 4 title 'circle, about the largest axis', '-' with linespoints ls 7 title 'nearly symmetric body: circle residual'
