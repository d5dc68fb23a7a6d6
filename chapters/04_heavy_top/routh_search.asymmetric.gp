# An asymmetric body's curve of routh_min_residual.svg (@asymmetric@ in routh_search.gp), one per ratio β/α.
'-' using 1:2 with linespoints ls @ls@ title 'asymmetric, β/α = @ratio@'
