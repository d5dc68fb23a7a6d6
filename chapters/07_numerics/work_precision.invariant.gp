# One method's curve in a panel of invariants_grioli_100.svg (@curves@ in work_precision.invariants_panel.gp
# and work_precision.invariants_key_panel.gp).
'-' with linespoints @style@ lw 1.4 ps 0.6 title @title@
