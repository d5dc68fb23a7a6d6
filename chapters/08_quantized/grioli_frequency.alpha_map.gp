# grioli_alpha_map.svg (grioli_frequency.cpp): the Grioli frequency over the admissible
# bodies, their border, the bodies integrated in both senses, and the body of part (b).
set title 'The Grioli frequency α (C/f)^{1/2} = (S/C)^{-1/2} over the admissible bodies'
set xlabel 'A / C'
set ylabel 'B / C'
set xrange [0:1]
set yrange [0.45:1.02]
set size ratio -1
set cbrange [1:2.2]
set cblabel 'α (C/f)^{1/2}'
set palette defined (0 '#440154', 1 '#3b528b', 2 '#21908d', 3 '#5dc963', 4 '#fde725')
set key at graph 0.98, graph 0.12 right bottom font ',9' opaque box
set label 'A + B = C (flat)' at 0.12, 0.72 rotate by -45 font ',10'
set label 'A = B' at 0.8, 0.76 rotate by 45 font ',10'
set label 'B = C' at 0.55, 1.01 font ',10'
plot '-' with image pixels notitle, '-' with lines lc rgb 'black' lw 1.5 notitle, '-' with points pt 6 ps 1.2 lc rgb 'black' title 'integrated in both senses', '-' with points pt 7 ps 1.8 lc rgb '#d55e00' title 'the body of part (b)'
