# The two circular-section normals (to their tips), G, the regions and curves, and the suspension
# point O with a dotted segment from G.
set arrow from 0,0 to @n0@ lw 2.5 lc rgb '#CC79A7' front
set arrow from 0,0 to @n1@ lw 2.5 lc rgb '#CC79A7' front
set label 'G' at 0,0 offset 0.6,-0.6 front
plot '-' using 1:2:3 with filledcurves lc rgb '#56B4E9' title 'I, II: A < B < C at every distance L', '-' using 1:2:3 with filledcurves lc rgb '#56B4E9' notitle, '-' using 1:2:3 with filledcurves lc rgb '#009E73' title 'III, IV: A < B < C up to the hyperbola', '-' using 1:2:3 with filledcurves lc rgb '#009E73' notitle, '-' using 1:2:3 with filledcurves lc rgb '#E69F00' title 'V, VI: A < C < B', '-' using 1:2:3 with filledcurves lc rgb '#E69F00' notitle, '-' with lines ls 7 lw 2.5 title 'hyperbola (5.7): B = C', '-' with lines ls 7 lw 2.5 notitle, '-' with lines ls 2 lw 2 dt 2 title 'Grioli lines (5.15)', '-' with lines ls 2 lw 2 dt 2 notitle, '-' with lines lw 1.5 lc rgb '#000000' dt 3 notitle, '-' with points pt 7 ps 1.4 lc rgb '#000000' title 'the suspension point O (--line, --off, --L)', NaN with lines lw 2.5 lc rgb '#CC79A7' title 'circular-section normals'
