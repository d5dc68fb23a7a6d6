# One start's curve in level_settling.svg (@curves@ in level_oscillator.settling.gp).
'-' with lines ls @ls@ lw 2 title 'E(0) = @start@ E_{0}'
