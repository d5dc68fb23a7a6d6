# routh_min_residual.svg (routh_search.cpp): precession about the vertical, the smallest
# residual of E = f T found against the angle γ, for asymmetric and symmetric bodies, one curve
# per ratio β/α each (routh_search.asymmetric.gp, routh_search.symmetric.gp).
set title 'Precession about the vertical (b = k): smallest residual of E = f T found'
set logscale y
set format y '10^{%L}'
set yrange [1e-17:3]
set xrange [0:180]
set xtics 30
set xlabel 'angle γ between the rotation vector a and the vertical (degrees)'
set ylabel 'min RMS |E - fT| / f'
set key center right
plot @asymmetric@, @symmetric@
