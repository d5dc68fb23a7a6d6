# One seed's curve of level_transitions.svg, after the curve before it (@seeds@ in level_transitions.kicks.gp).
, '-' with lines ls @seed@ lw 1.5 title 'kicks, seed @seed@'
