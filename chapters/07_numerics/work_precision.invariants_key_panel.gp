set key at screen 0.815, 0.5 left center Left reverse font ',10' spacing 1.1 nobox
set title @title@
set ylabel @ylabel@
plot @curves@
