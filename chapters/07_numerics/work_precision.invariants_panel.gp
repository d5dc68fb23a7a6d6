unset key
set title @title@
set ylabel @ylabel@
plot @curves@
