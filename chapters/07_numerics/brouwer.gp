# brouwer.svg (brouwer.cpp): the root mean square of the ensemble's errors against time, with
# compensated and plain summation, and Brouwer's slopes t^{3/2} and t^{1/2}.
set title 'Grioli (1, 1.5, 2), Taylor-@degree@, @steps@ steps a period: root mean square of @ensemble@ runs'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'time (periods)'
set ylabel 'error'
set key top left
plot '-' with lines lc rgb '#0072B2' lw 2 title 'angle from the exact R, compensated', '-' with lines lc rgb '#0072B2' dt 3 lw 2 title 'angle, plain summation', '-' with lines lc rgb '#D55E00' lw 2 title '|H − H(0)| / f, compensated', '-' with lines lc rgb '#D55E00' dt 3 lw 2 title '|H − H(0)| / f, plain', '-' with lines lc rgb '#777777' dt 4 title 't^{3/2} and t^{1/2} (Brouwer)'
