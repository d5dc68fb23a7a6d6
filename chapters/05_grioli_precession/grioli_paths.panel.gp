# One sense: the arrows of the panel before it gone, its title, the arrows k and b; then the
# scene's arrows along the paths (grioli_paths.sense_arrow.gp) and the curves (grioli_paths.curves.gp).
unset arrow
set title '@title@'
set arrow 1 from 0,0,0 to 0,0,1.3 head filled size 0.08,20 lw 2 lc rgb '#000000'
set label 1 'k' at 0.05,0,1.3
set arrow 2 from 0,0,0 to @b@ head filled size 0.08,20 lw 2 lc rgb '#0072B2'
set label 2 'b' at @b_label@ tc rgb '#0072B2'
