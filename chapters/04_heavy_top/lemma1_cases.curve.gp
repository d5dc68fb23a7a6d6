# One ratio β/α's curve of lemma1_min_residual.svg (@curves@ in lemma1_cases.gp).
'-' using 1:2 with linespoints ls @ls@ title '@title@'
