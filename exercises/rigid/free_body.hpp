// Chapter 3: the free body, [P, Sect. 3, (6.7)-(6.9)].
//
// Conventions for this file
//   * The body frame is the frame of the principal axes, so the inertia tensor is
//     diag(I1, I2, I3); I is passed as the Vec3 (I1, I2, I3), in any order.
//   * The state (Omega, R) is the 3 + 9 unknowns of the Euler-Poisson equations, packed for
//     the integrators as in rigid/ode.hpp: Omega first, then R row by row (rigid::pack).
//   * euler_rhs and poisson_rhs are pure formulas and do not check their input (they run
//     millions of times inside an integrator). free_body_equations checks the moments once:
//     finite, > 0 and obeying the triangle inequality (rigid::require_principal_moments).
//
// How it is graded (tests/grading/README.md): each test calls your functions in a sandboxed
// process of their own, which keeps its state between the calls of one test; the grader runs in
// another. Threads are allowed (up to 16 besides the main one); starting a process or another
// program is not.
#pragma once

#include "rigid/ode.hpp"
#include "rigid/types.hpp"

namespace rigid {

// snippet: euler_poisson
// Euler's equation for the free body                                                [P, (6.7)]
//   I dOmega/dt = [I Omega, Omega],   so   dOmega/dt = I^{-1} ((I Omega) x Omega)
Vec3 euler_rhs(const Vec3& I, const Vec3& Omega);

// Poisson's equation                                                                 [P, (6.8)]
//   dR_ij/dt = -eps_jkm Omega_k R_im,   i.e.   dR/dt = R hat(Omega)
Mat3 poisson_rhs(const Mat3& R, const Vec3& Omega);

// The 3 + 9 equations as one right-hand side f(t, y) for rigid/ode.hpp and rigid/integrators.hpp,
// y = pack({Omega, R}). Throws std::invalid_argument (naming the rule) for moments that are not
// finite and > 0 or that break the triangle inequality; a flat body (I1 + I2 = I3) is allowed.
OdeRhs free_body_equations(const Vec3& I);
// end snippet

// snippet: free_body_integrals
// The two integrals of motion that [P] labels (6.9), both constant along every solution of (6.7).
// The kinetic energy of rotation, 1/2 (I1 Omega1^2 + I2 Omega2^2 + I3 Omega3^2). [P, (6.9)]
// writes the sum without the 1/2: twice the energy, as constant as the energy itself.
double rotational_energy(const Vec3& I, const Vec3& Omega);

// The squared angular momentum |I Omega|^2 = I1^2 Omega1^2 + I2^2 Omega2^2 + I3^2 Omega3^2.  [P, (6.9)]
double angular_momentum_squared(const Vec3& I, const Vec3& Omega);
// end snippet

// snippet: wobble_frequency_squared
// A derivation exercise (Chapter 3): the body spins steadily about its principal axis number
// `axis` (0, 1 or 2) at the rate `spin`, Omega = spin e_axis. Returns nu^2 such that small
// disturbances of the two other components of Omega obey x'' = -nu^2 x under Euler's
// equation: nu^2 > 0, they oscillate with the angular frequency nu; nu^2 < 0, they grow like
// exp(sqrt(-nu^2) t). Throws std::invalid_argument for moments that are not a body (as
// free_body_equations), an axis outside 0..2 or a non-finite spin.
double wobble_frequency_squared(const Vec3& I, int axis, double spin);
// end snippet

}  // namespace rigid
