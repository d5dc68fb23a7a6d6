# One stencil's curve of omega_fd_error_vs_step.svg (@stencils@ in omega_finite_difference.error_vs_step.gp).
'-' using 1:2 with linespoints ls @ls@ title '@title@'
