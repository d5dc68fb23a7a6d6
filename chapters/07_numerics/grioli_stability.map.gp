# grioli_stability_map.svg (grioli_stability.cpp): ln|μ| per period over the bodies (u, v),
# and the bodies of the perturbed runs, numbered.
set title 'Grioli precession: growth of the largest Floquet multiplier, ln|μ| per period'
set xlabel 'u = (B - A)/(C - A)   (B = A at the left, B = C at the right)'
set ylabel 'v = (C - A)/B   (v = 1: flat body, A + B = C)'
set xrange [0:1]
set yrange [0:1.02]
set cbrange [0:*]
set cblabel 'ln|μ| per period'
set palette defined (0 'white', 0.02 '#fde0c5', 0.3 '#f39c6b', 1 '#b2182b')
set view map
set key bottom left opaque font ',10'
splot '-' using 1:2:3 with pm3d notitle, '-' using 1:2:(0) with points pt 7 ps 1.2 lc rgb '#0072B2' title 'bodies of the perturbed runs', '-' using 1:2:(0):(sprintf('%d', $3)) with labels offset 0,1 font ',9' notitle
