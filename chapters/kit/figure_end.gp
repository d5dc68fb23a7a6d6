# The end of every figure's script (Figure::finish, figure.cpp): a multiplot is closed (a figure
# without one is not changed by this), and the output file with it.
unset multiplot
unset output
