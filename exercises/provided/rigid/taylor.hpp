// The reference integrator of Chapter 7: the Taylor-series method for the Euler-Poisson
// equations of the heavy top [P, (3.1)-(3.2)], in double or in long double (x86: 64-bit
// significand, eps = 1.1e-19). Provided, not an exercise: it is what the chapter measures every
// method against where no closed form exists, and how it finds the double-precision floor.
//
// Conventions for this file
//   * The top and the initial state are given in double (rigid::HeavyTop, rigid::BodyState) and
//     converted exactly; every operation after that is in Real. J may be any symmetric positive
//     definite matrix (it is inverted once, in Real).
//   * Fixed steps, as integrate_rk4 takes them: n = ceil((t_k+1 - t_k) / h) equal steps between
//     output times, each step the Taylor polynomial of degree `order` evaluated by Horner's rule.
//   * Summation::plain adds the whole polynomial to the state at once: one rounding of the state
//     per step. Summation::compensated evaluates the increment (the terms of degree 1 and up)
//     on its own and adds it with Kahan's compensation, carried from step to step: the state is
//     then rounded once per output, not once per step, and over a long run the error grows as
//     round-off that does not correlate does (Brouwer's law; Chapter 7).
#pragma once

#include <functional>
#include <vector>

#include "rigid/heavy_top.hpp"
#include "rigid/ode.hpp"
#include "rigid/stepping.hpp"
#include "rigid/types.hpp"

namespace rigid {

template <class Real>
struct TaylorState {
    Eigen::Matrix<Real, 3, 1> Omega;
    Eigen::Matrix<Real, 3, 3> R;
};

// The state rounded to double.
template <class Real>
BodyState to_double(const TaylorState<Real>& s) {
    return {s.Omega.template cast<double>(), s.R.template cast<double>()};
}

// snippet: taylor
// Both equations are quadratic in (Omega, R), so the Taylor coefficients of the solution about
// the start of a step, Omega(t0 + tau) = sum_n Omega_n tau^n and R(t0 + tau) = sum_n R_n tau^n,
// follow from Cauchy products, with no derivative formula to derive or check:
//   (n + 1) Omega_{n+1} = J^-1 ( sum_{i=0..n} (J Omega_i) x Omega_{n-i} + f (R_n^T k) x z(0) ),
//   (n + 1) R_{n+1}     = sum_{i=0..n} R_i hat(Omega_{n-i}).
// A step of degree N costs about 12 N^2 multiply-adds. Returns the number of steps taken.
// Throws std::invalid_argument for h not finite and > 0, order outside 1..60, bad times (as
// integrate_rk4) or a non-finite state.
template <class Real>
long integrate_taylor(const HeavyTop& top, const BodyState& s0, const std::vector<double>& times,
                      const std::function<void(double t, const TaylorState<Real>& s)>& observe, double h, int order,
                      Summation summation = Summation::plain);
// end snippet

extern template long integrate_taylor<double>(const HeavyTop&, const BodyState&, const std::vector<double>&,
                                              const std::function<void(double, const TaylorState<double>&)>&, double,
                                              int, Summation);
extern template long integrate_taylor<long double>(const HeavyTop&, const BodyState&, const std::vector<double>&,
                                                   const std::function<void(double, const TaylorState<long double>&)>&,
                                                   double, int, Summation);

}  // namespace rigid
