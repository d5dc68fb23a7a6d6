# One method's curve in integrators_error_vs_time.svg (@curves@ in grioli_integrators.gp).
'-' using 1:2 with linespoints ls @ls@ title '@title@'
