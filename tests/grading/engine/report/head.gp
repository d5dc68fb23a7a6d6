# A plot of the class report (tests/grading/engine/class_report.cpp), drawn in its folder from the data file of its name.
set terminal svg size @width@,@height@ noenhanced font 'sans,12' background '#ffffff'
set output @svg@
set datafile separator '\t'
set style fill solid 0.85 border rgb '#333333'
set grid ytics lc rgb '#dddddd'
