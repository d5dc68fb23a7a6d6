# polhodes.svg (polhodes.cpp): the energy ellipsoid, polhodes about the smallest and the
# largest axis, and the separatrix.
set view 58, 32, 1.0, 1.35
set view equal xyz
set xyplane 0
unset grid
set border 4095
set xlabel 'Ω_1'
set ylabel 'Ω_2'
set zlabel 'Ω_3'
set key at screen 0.01, 0.99 top left
splot '-' with lines ls 8 lw 0.5 title 'energy ellipsoid', '-' with lines ls 1 lw 2 title 'polhodes about the smallest axis', '-' with lines ls 2 lw 2 title 'polhodes about the largest axis', '-' with lines ls 7 lw 2.5 title 'separatrix (two plane ellipses)'
