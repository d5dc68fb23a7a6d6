# One start's curve in level_approach.svg (@curves@ in level_oscillator.approach.gp).
'-' with lines ls @ls@ lw 2 title 'E(0) = @start@ E_{0} settles on @level@ E_{0}'
