# A start's curve with β = 0 in spin_alignment.svg, after the first (@plain@ in aligning_spin.alignment.gp).
, '-' with lines ls @ls@ dt 2 lw 1 notitle
