# euler_gap_form.svg (euler_gap_form.cpp), two panels: the error (euler_gap_form.error.gp)
# and the run time (euler_gap_form.time.gp) of both forms, every body; the kit ends the
# multiplot.
set encoding utf8
set multiplot layout 1, 2 title 'A body hung at L on a Grioli line, @periods@ periods of rk8pd: Euler equations naive (open, dashed) and on the moment gaps (filled, solid)'
set logscale y
set format y '10^{%T}'
set xlabel 'log_{10} of L in body sizes sqrt(C_g/μ)'
set xrange [-6.3:8.3]
set xtics 2
set key below font ',9' maxrows 3
