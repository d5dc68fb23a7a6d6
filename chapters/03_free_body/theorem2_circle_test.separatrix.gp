# The second panel of theorem2_residuals.svg: towards the separatrix.
set title 'towards the separatrix (m_c -> 0)'
set xlabel 'complementary parameter m_c = 1 - m'
set xrange [1e-13:1]
plot '-' with linespoints ls 1 title 'plane, about the smallest axis', '-' with linespoints ls 2 title 'plane, about the largest axis', '-' with linespoints ls 3 title 'circle, about the smallest axis', '-' with linespoints ls 4 title 'circle, about the largest axis'
