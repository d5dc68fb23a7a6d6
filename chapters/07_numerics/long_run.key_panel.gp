# The orthogonality panel: the key of all four, and Brouwer's law, a random walk of one
# rounding per step.
set title @title@
set ylabel @ylabel@
set yrange [1e-17:1]
set key at screen 0.785, 0.5 left center vertical font ',10' spacing 1.3 width -1
plot @curves@, '-' with lines lc rgb '#777777' dt 4 lw 1 title 'ε √(steps)'
