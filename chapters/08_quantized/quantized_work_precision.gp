# quantized_work_precision.svg (quantized_work_precision.cpp): one panel per problem
# (quantized_work_precision.panel.gp; the second, quantized_work_precision.key_panel.gp, has
# the key, where there is room); the kit ends the multiplot.
set multiplot layout 1, 3 title 'Error against run time (min over repetitions), T = @T@'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'run time (s)'
