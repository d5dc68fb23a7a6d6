# One start's averaged asymptote in level_approach.svg, after the curves (@asymptotes@ in level_oscillator.approach.gp).
, '-' with lines ls @ls@ dt 2 lw 1 notitle
