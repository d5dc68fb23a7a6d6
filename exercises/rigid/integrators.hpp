// Integrators the student writes (Chapter 3; reused in Chapter 7). The library solvers are in
// rigid/ode.hpp (GSL odeiv2); this file holds the fixed-step classical Runge-Kutta method, with
// the same right-hand side and observer types, so the two can be swapped and compared.
//
// Conventions for this file
//   * dy/dt = f(t, y) with f an OdeRhs (rigid/ode.hpp); states are Eigen::VectorXd.
//   * Bad input (a step that is not finite and > 0; no output times, or output times that are
//     not finite and strictly increasing; an empty or non-finite initial state) throws
//     std::invalid_argument.
//
// How it is graded (tests/grading/README.md): each test calls your functions in a sandboxed
// process of their own, which keeps its state between the calls of one test; the grader runs in
// another. Threads are allowed (up to 16 besides the main one); starting a process or another
// program is not.
#pragma once

#include <vector>

#include "rigid/ode.hpp"

namespace rigid {

// snippet: rk4_step
// One step of the classical fourth-order Runge-Kutta method from (t, y) to t + h:
//   k1 = f(t, y),             k2 = f(t + h/2, y + h/2 k1),
//   k3 = f(t + h/2, y + h/2 k2),  k4 = f(t + h, y + h k3),
//   y(t + h) ~ y + h/6 (k1 + 2 k2 + 2 k3 + k4).      Four calls of f; local error O(h^5).
VecX rk4_step(const OdeRhs& f, double t, const VecX& y, double h);
// end snippet

// snippet: integrate_rk4
// Integrates with rk4_step from y(times.front()) = y0 and calls observe(t, y) at every time in
// `times` (the first call is y0 itself). Between two output times t_k < t_k+1 it takes
// n = ceil((t_k+1 - t_k) / h) equal steps of (t_k+1 - t_k) / n <= h, so that it lands exactly
// on every output time. Returns the number of steps taken (f is called 4 times per step).
long integrate_rk4(const OdeRhs& f, const VecX& y0, const std::vector<double>& times, const OdeObserver& observe,
                   double h);
// end snippet

}  // namespace rigid
