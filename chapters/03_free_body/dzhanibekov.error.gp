# dzhanibekov_error.svg (dzhanibekov.cpp): the error of rk8pd and of the student's RK4 against
# the exact motion.
set title 'Error against the exact motion: it jumps at every flip'
set xlabel 't'
set ylabel '|Ω − Ω_{exact}| / |Ω(0)|'
set logscale y
set format y '10^{%L}'
set key top left
plot '-' using 1:2 with lines ls 1 title @rk8pd@, '-' using 1:2 with lines ls 2 title @rk4@
