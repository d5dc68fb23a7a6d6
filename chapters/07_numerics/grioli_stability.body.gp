# One body's three curves in the left panel of grioli_perturbations.svg, one per δ (@curves@ in grioli_stability.perturbations.gp).
'-' with lines lc rgb '@colour@' lw 1.5 dt 1 title @title@, '-' with lines lc rgb '@colour@' lw 1.5 dt 2 notitle, '-' with lines lc rgb '@colour@' lw 1.5 dt 3 notitle
