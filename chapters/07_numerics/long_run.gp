# long_run.svg (long_run.cpp): four panels (long_run.panel.gp; the orthogonality panel,
# long_run.key_panel.gp, has every curve and Brouwer's line, so it draws the one key, on the
# right of the four); the kit ends the multiplot.
set multiplot layout 2, 2 margins 0.07, 0.77, 0.07, 0.92 spacing 0.08, 0.14 title @title@
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'time (periods)'
