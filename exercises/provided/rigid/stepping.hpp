// Fixed-step integration of the Euler-Poisson state with steps in increment form: the driver of
// Chapter 7's Lie-group and splitting methods. Provided, not an exercise.
//
// Conventions for this file
//   * A step does not return the new state; it returns the increment d = (dOmega, E) that takes
//     the state (Omega, R) to (Omega + dOmega, R (1 + E)). For a step of size h both parts are
//     small, O(h), and can be computed to a few ulp of their own size.
//   * Adding a small increment to a state of size 1 rounds it to the last bit of the state: one
//     rounding error of about eps = 2.2e-16 per step. After N steps these pile up like
//     eps sqrt(N) (Brouwer's law) in R^T R - 1 and in every invariant, whatever the method.
//     Compensated (Kahan) summation carries the rounded-off part along to the next step, so
//     that only the increments' own errors, eps |d| per step, are left.
#pragma once

#include <functional>
#include <vector>

#include "rigid/ode.hpp"
#include "rigid/types.hpp"

namespace rigid {

// snippet: increment
// One step in increment form: the new state is (Omega + dOmega, R (1 + E)) = apply(s, d).
struct Increment {
    Vec3 dOmega = Vec3::Zero();
    Mat3 E = Mat3::Zero();
};

inline BodyState apply(const BodyState& s, const Increment& d) { return {s.Omega + d.dOmega, s.R + s.R * d.E}; }

// A one-step method in increment form: the increment of one step of size h from s.
using IncrementStepper = std::function<Increment(const BodyState& s, double h)>;
// end snippet

using BodyObserver = std::function<void(double t, const BodyState& s)>;

enum class Summation {
    plain,        // s = apply(s, d): one rounding of the state per step
    compensated,  // the same sum, with Kahan's compensation carried from step to step
};

// snippet: integrate_steps
// Integrates with the stepper from s(times.front()) = s0 and calls observe(t, s) at every time in
// `times` (the first call is s0 itself), taking n = ceil((t_k+1 - t_k) / h) equal steps of
// (t_k+1 - t_k) / n <= h between output times, as integrate_rk4 does. Returns the number of steps.
// Throws std::invalid_argument for a step that is not finite and > 0, output times that are not
// finite and strictly increasing, or a non-finite s0.
long integrate_steps(const IncrementStepper& step, const BodyState& s0, const std::vector<double>& times,
                     const BodyObserver& observe, double h, Summation summation = Summation::compensated);
// end snippet

}  // namespace rigid
