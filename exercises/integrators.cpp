// Chapter 3 exercises: your own integrator. Contracts in rigid/integrators.hpp; hints in
// exercises/hints.md. Replace each todo(...) with your code.
#include "rigid/integrators.hpp"

#include "rigid/require.hpp"
#include "rigid/todo.hpp"

namespace rigid {

// TODO: one classical Runge-Kutta step: four evaluations of f, weights 1, 2, 2, 1 over 6.
VecX rk4_step(const OdeRhs& f, double t, const VecX& y, double h) { todo("rk4_step"); }

// TODO: equal steps <= h between output times, landing exactly on each; check the input.
long integrate_rk4(const OdeRhs& f, const VecX& y0, const std::vector<double>& times, const OdeObserver& observe,
                   double h) {
    todo("integrate_rk4");
}

}  // namespace rigid
