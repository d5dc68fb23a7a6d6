# One track's curve in a panel of long_run.svg (@curves@ in long_run.panel.gp and long_run.key_panel.gp).
'-' with lines @style@ lw 1.6 title @title@
