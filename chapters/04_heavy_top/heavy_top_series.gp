# series_check.svg (heavy_top_series.cpp): each coefficient of the series (3.5) for E and
# (3.6) for T, as printed in [P] and corrected, against the numerical one.
set title 'The series (3.5) for E and (3.6) for T, coefficient by coefficient'
set logscale y
set format y '10^{%L}'
set yrange [1e-17:10]
set ylabel '|coefficient - numerical| / largest coefficient'
set xtics ('const' 0, 'cos αt' 1, 'sin αt' 2, 'cos 2αt' 3, 'sin 2αt' 4, 'cos βt' 5, 'sin βt' 6, 'cos γ_+t' 7, 'sin γ_+t' 8, 'cos γ_-t' 9, 'sin γ_-t' 10) rotate by -35
set xrange [-0.6:10.6]
set key top left
plot '-' using ($1-0.2):2 with impulses lw 6 lc rgb '#D55E00' title 'E, as printed in [P]', '-' using ($1-0.2):3 with points ls 1 pt 7 ps 1.0 title 'E, corrected', '-' using ($1+0.2):2 with impulses lw 6 lc rgb '#E69F00' title 'T, as printed in [P]', '-' using ($1+0.2):3 with points ls 3 pt 9 ps 1.2 title 'T, corrected'
