# A start's curve by (6.2) in spin_alignment.svg, after the first (@solid@ in aligning_spin.alignment.gp).
, '-' with lines ls @ls@ lw 2 notitle
