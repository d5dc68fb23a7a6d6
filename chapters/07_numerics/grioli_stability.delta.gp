# The most unstable body's curve for one δ in the right panel of grioli_perturbations.svg (@curves@ in grioli_stability.unstable.gp).
'-' using 1:($2*@delta@) with lines lc rgb '#D55E00' lw 1.5 dt @dt@ title 'δ = 10^{@exponent@}'
