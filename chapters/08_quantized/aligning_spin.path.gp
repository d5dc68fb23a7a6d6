# The path of (6.2) from one start in spin_sphere.svg, after the curves before it (@paths@ in aligning_spin.sphere.gp).
, '-' with lines ls @ls@ lw 2 title '(6.2) from @degrees@ degrees'
