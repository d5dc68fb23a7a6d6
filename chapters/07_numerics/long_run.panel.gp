set title @title@
set ylabel @ylabel@
set yrange [1e-17:10]
unset key
plot @curves@
