# omega_fd_error_vs_time.svg (omega_finite_difference.cpp): each stencil's best error against
# its run time, labelled with its order.
set title 'Best error against run time per recovery of Ω (labels: order)'
set logscale y
set format y '10^{%L}'
set xlabel 'run time per recovery of Ω (ns)'
set ylabel 'best |Ω_{fd} − α{/:Bold a}| / α'
set key top right
set offsets graph 0.15, graph 0.15, graph 0.3, graph 0.3
plot '-' using 1:2 with linespoints ls 1 title 'central, orders 2-8', '-' using 1:2 with points ls 2 ps 1.2 title 'forward, order 1', '-' using 1:2:(sprintf('%d', $3)) with labels offset 1.2, 0.8 notitle
