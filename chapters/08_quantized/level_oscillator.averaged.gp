# The averaged equation's curve from one more start in level_settling.svg (@averaged@ in level_oscillator.settling.gp).
, '-' with lines lc rgb 'black' dt 2 lw 1 notitle
