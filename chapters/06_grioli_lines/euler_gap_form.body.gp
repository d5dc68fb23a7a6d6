# One body's three curves in a panel of euler_gap_form.svg: the gap form, the naive form, and the gap form's
# × points (@curves@ in euler_gap_form.error.gp and euler_gap_form.time.gp).
'-' with linespoints ls @ls@ title @gaps@, '-' with linespoints ls @ls@ dt 2 pt 6 title @naive@, '-' with points ls @ls@ pt 2 ps 1.2 notitle
