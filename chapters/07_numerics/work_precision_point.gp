# work_precision_point.svg (work_precision_point.cpp): one run's error and energy drift, the
# largest up to each output time (the last point of the error is the run's point on the
# work-precision diagram), and the double-precision floor of the scenario.
set title @title@
set xrange [0:@T@]
set logscale y
set format y '10^{%L}'
set xlabel 't'
set ylabel 'largest up to t'
set key outside right top font ',9'
plot '-' with linespoints lc rgb '#0072B2' pt 7 lw 2 title 'error (R and Ω against the reference)', '-' with linespoints lc rgb '#D55E00' pt 5 lw 1.5 title 'energy drift', '-' with lines lc rgb '#777777' dt 2 lw 1.2 title 'double-precision floor'
