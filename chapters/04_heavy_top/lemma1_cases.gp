# lemma1_min_residual.svg (lemma1_cases.cpp): the smallest residual of E = f T found, against
# the angle γ, one curve per ratio β/α (@curves@: lemma1_cases.curve.gp, one each).
set title 'Smallest residual of E = f T found, asymmetric body (A, B, C) = (@moments@)'
set logscale y
set format y '10^{%L}'
set yrange [1e-17:3]
set xrange [20:160]
set xlabel 'angle γ between a and b (degrees)'
set ylabel 'min RMS |E - fT| / f'
set xtics 30
set key bottom left
set label 1 'Case 3, b_3 = 0: the Grioli precession' at 93, 1e-15 tc rgb '#0072B2'
plot @curves@
