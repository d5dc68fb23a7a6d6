# The last panel: the time axis with its numbers.
set tmargin at screen @top@
set bmargin at screen @bottom@
set title @title@ font ',11' offset 0, -0.4
set xlabel 'run time (s), minimum over repetitions'
set format x '10^{%L}'
