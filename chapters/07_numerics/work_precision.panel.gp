# A panel above the last: the time axis without its numbers.
set tmargin at screen @top@
set bmargin at screen @bottom@
set title @title@ font ',11' offset 0, -0.4
unset xlabel
set format x ''
