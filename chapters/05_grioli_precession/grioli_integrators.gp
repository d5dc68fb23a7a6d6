# integrators_error_vs_time.svg (grioli_integrators.cpp): each method's error against its run
# time, one curve per method (@curves@: grioli_integrators.method.gp, one each). The title is double-quoted, so that \n breaks its line: its end
# is empty, or a second line when the instability dominates the errors.
set title "Theorem 1 as a benchmark: @periods@ periods, tolerances 10^{-6} to 10^{-12}@unstable@"
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'run time (s)'
set ylabel 'max geodesic angle between integrated and exact R(t)'
set key outside right top
plot @curves@
