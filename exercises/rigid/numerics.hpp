// Chapter 7: geometric integrators for the heavy top [P, (3.1)-(3.2)]: a Lie-group method that
// keeps R on SO(3), and a splitting method that keeps more (the vertical angular momentum, and
// the energy up to a bounded error), with its fourth-order composition.
//
// Conventions for this file
//   * The state is rigid::BodyState {Omega, R}; the heavy top is rigid::HeavyTop {J, f, k, z0}
//     (rigid/heavy_top.hpp). A free body is a heavy top with f = 0.
//   * Every step is in increment form (rigid/stepping.hpp): it returns d = (dOmega, E) with
//     new state (Omega + dOmega, R (1 + E)); integrate_steps adds it, with compensated summation.
//     E is always exp(hat(theta)) - 1 for some theta, so R (1 + E) is a rotation whenever R is.
//   * The splitting functions (free_rotation, strang_step) need J diagonal: the body axes are the
//     principal axes (this is how every scene of the chapter sets up its bodies). They do not
//     check it, nor anything else: they run millions of times.
//
// How it is graded (tests/grading/README.md): each test calls your functions in a sandboxed
// process of their own, which keeps its state between the calls of one test; the grader runs in
// another. Threads are allowed (up to 16 besides the main one); starting a process or another
// program is not.
#pragma once

#include "rigid/heavy_top.hpp"
#include "rigid/stepping.hpp"
#include "rigid/types.hpp"

namespace rigid {

// snippet: expm1_so3
// exp(hat(w)) - 1: the rotation by the angle |w| about w, minus the identity (Rodrigues),
//   expm1_so3(w) = sin|w| / |w| hat(w) + (1 - cos|w|) / |w|^2 hat(w)^2,
// with 1 - cos x computed as 2 sin^2(x/2): every entry keeps its relative accuracy for small
// |w|, where the result is about hat(w) + hat(w)^2 / 2. expm1_so3(0) is the zero matrix.
Mat3 expm1_so3(const Vec3& w);
// end snippet

// snippet: dexpinv
// The inverse of the derivative of the exponential map of SO(3) at u, applied to v:
//   dexpinv(u, v) = v - 1/2 u x v + c(|u|) u x (u x v),   c(x) = (1 - (x/2) cot(x/2)) / x^2,
// with c(x) -> 1/12 + x^2/720 as x -> 0 (use the series below |u| = 1e-3). Valid for |u| < 2 pi.
// Its use: R(t) = R0 exp(hat(theta(t))) solves R^T dR/dt = hat(Omega) exactly when
//   d theta/dt = dexpinv(-theta, Omega).
Vec3 dexpinv(const Vec3& u, const Vec3& v);
// end snippet

// snippet: combine
// The increment of "first, then second": (Omega + d1 + d2, R (1 + E1)(1 + E2)), i.e.
//   dOmega = d1 + d2,   E = E1 + E2 + E1 E2,
// with no identity added and subtracted, so that the small E keeps its digits.
Increment combine(const Increment& first, const Increment& second);
// end snippet

// snippet: rkmk4_step
// One step of the Runge-Kutta-Munthe-Kaas method with the classical RK4 tableau on
// SO(3) x R^3. With F(R, Omega) the Omega part of euler_poisson_rhs and R_i = R (1 + E(theta_i)):
//   theta_1 = 0,          W_1 = Omega,              K_1 = W_1,  L_1 = F(R, W_1)
//   theta_2 = h/2 K_1,    W_2 = Omega + h/2 L_1,    K_i = dexpinv(-theta_i, W_i),  L_i = F(R_i, W_i)
//   theta_3 = h/2 K_2,    W_3 = Omega + h/2 L_2
//   theta_4 = h K_3,      W_4 = Omega + h L_3
//   E = expm1_so3(h/6 (K_1 + 2 K_2 + 2 K_3 + K_4)),   dOmega = h/6 (L_1 + 2 L_2 + 2 L_3 + L_4).
// Fourth order; R (1 + E) is a rotation by construction.
Increment rkmk4_step(const HeavyTop& top, const BodyState& s, double h);
// end snippet

// snippet: splitting
// The heavy top's energy is H = T1 + T2 + T3 + V: the kinetic energy about each principal axis,
// T_i = m_i^2 / (2 J_ii) with m = J Omega, and the potential V = f (k, R z(0)). The flow of
// each part is exact and simple:
//   torque_kick, the flow of V for a time h: R stays, J Omega gains h f [R^T k, z(0)];
//   free_rotation, the flow of T_i for a time h: with phi = h Omega_i,
//     R -> R exp(phi hat(e_i)),   J Omega -> exp(-phi hat(e_i)) J Omega   (Omega_i stays);
//     axis is 0, 1 or 2 (else std::invalid_argument).
Increment torque_kick(const HeavyTop& top, const BodyState& s, double h);
Increment free_rotation(const HeavyTop& top, const BodyState& s, int axis, double h);

// Strang's symmetric splitting, second order: the flows for h/2, h/2, h/2, h, h/2, h/2, h/2 of
//   V, T1, T2, T3, T2, T1, V,
// combined into one increment. Each part is a rotation or a kick, so R stays on SO(3), the
// vertical angular momentum (k, R J Omega) is kept to round-off, and so is |R^T k| = 1.
Increment strang_step(const HeavyTop& top, const BodyState& s, double h);
// end snippet

// snippet: triple_jump
// Yoshida's fourth-order composition of a symmetric second-order step:
//   step(g1 h), then step(g2 h), then step(g1 h),   g1 = 1 / (2 - 2^(1/3)),  g2 = 1 - 2 g1 < 0,
// each substep taken from the state the previous ones reached; the increments are combined.
Increment triple_jump(const IncrementStepper& step, const BodyState& s, double h);
// end snippet

// A derivation exercise (Chapter 7, "Exercises"): the relative energy that one step of the
// classical fourth-order Runge-Kutta method loses on the harmonic oscillator q'' = -omega^2 q,
// 1 - E(h) / E(0) with E = (q'^2 + omega^2 q^2) / 2, as a function of x = h omega alone (it is
// the same for every starting state). Derive it in closed form on paper: the function must not
// take a step. It must keep its relative digits for x down to 1e-3, where the loss is of the
// order of 1e-20 and no step taken in double precision can measure it; it is negative where a
// step gains energy. x finite and >= 0 (std::invalid_argument otherwise).
double rk4_energy_loss(double x);

}  // namespace rigid
