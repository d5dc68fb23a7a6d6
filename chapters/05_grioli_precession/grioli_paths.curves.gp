# The paths of G and of the tip of R_B, exact and integrated, and where they start; the curves'
# titles are the first panel's only.
splot '-' with lines ls 2 lw 2 title @G_exact@, '-' with points ls 2 pt 7 ps 0.35 title @G_integrated@, '-' with lines ls 3 lw 2 title @tip_exact@, '-' with points ls 3 pt 7 ps 0.35 title @tip_integrated@, '-' with points pt 6 ps 1.8 lc rgb '#000000' title @start@
