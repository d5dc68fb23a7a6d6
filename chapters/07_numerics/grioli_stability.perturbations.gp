# grioli_perturbations.svg (grioli_stability.cpp), left panel: d / δ for every body but the
# most unstable (@curves@: grioli_stability.body.gp, three per body), against a line proportional to t;
# then the right panel (grioli_stability.unstable.gp); the kit ends the multiplot.
set multiplot layout 1, 2 title 'Grioli precession: deviation after a change δ of Ω(0), at whole periods'
set xlabel 't / P'
set format y '10^{%L}'
set key top left font ',8' spacing 0.85
set logscale xy
set title 'd / δ, log-log (δ = 10^{-8} solid, 10^{-6} dashed, 10^{-4} dotted); slope 1: linear'
set ylabel 'd / δ'
plot @curves@, x with lines lc rgb '#777777' dt 4 title 'proportional to t'
