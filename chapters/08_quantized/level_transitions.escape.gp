# level_escape.svg (level_transitions.cpp): the time to leave the level after one disturbance,
# integrated and by the averaged equation, one pair of curves per power p (@curves@:
# level_transitions.power.gp, one each).
set title 'Leaving the level E_{n} = 2 E_{0} after one disturbance δ below it'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'δ / E_{0}'
set ylabel 'time to fall below E_{n} - E_{0}/2'
set key top right font ',9'
plot @curves@
