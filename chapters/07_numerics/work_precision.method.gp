# One method's curve in a panel of wp_<scenario>.svg (@curves@ in work_precision.plot.gp).
'-' with linespoints @style@ lw 1.6 ps 0.8 title @title@
