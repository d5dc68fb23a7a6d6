# A symmetric body's curve of routh_min_residual.svg (@symmetric@ in routh_search.gp), one per ratio β/α.
'-' using 1:2 with linespoints ls @ls@ dt 2 pt 6 title 'symmetric (A = B), β/α = @ratio@'
