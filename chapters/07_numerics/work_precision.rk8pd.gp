# rk8pd in a panel it does not belong to, after the panel's curves (@comparison@ in work_precision.plot.gp).
, '-' with lines lc rgb '#b0b0b0' lw 3 title 'GSL rk8pd, for comparison'
