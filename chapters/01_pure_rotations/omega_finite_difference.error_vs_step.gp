# omega_fd_error_vs_step.svg (omega_finite_difference.cpp): each stencil's error against its
# step, and the round-off line (@stencils@: one curve per stencil, omega_finite_difference.stencil.gp).
set title 'Ω from finite differences of R(t): truncation meets round-off'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'step h'
set ylabel '|Ω_{fd} − α{/:Bold a}| / α'
set key at graph 0.36, 0.97 left top
set yrange [1e-17:10]
plot @stencils@, '-' using 1:2 with lines ls 9 title 'round-off, ε / (αh)'
