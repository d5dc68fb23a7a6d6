# The moments A, B, C at O and the eigen-solver's; the scene sends its table once per curve.
plot '-' using 1:2 with lines ls 1 title 'A', '' using 1:3 with lines ls 2 title 'B = B_g + h', '' using 1:4 with lines ls 3 title 'C', '' using 1:5 every 12 with points ls 7 pt 6 title 'eigen-solver', '' using 1:6 every 12 with points ls 7 pt 6 notitle, '' using 1:7 every 12 with points ls 7 pt 6 notitle
