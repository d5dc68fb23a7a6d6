// Chapter 3 exercises: the free body. Contracts, conventions and equation numbers are in
// rigid/free_body.hpp; hints in exercises/hints.md. Replace each todo(...) with your code.
#include "rigid/free_body.hpp"

#include "rigid/require.hpp"
#include "rigid/rotation.hpp"
#include "rigid/todo.hpp"

namespace rigid {

// TODO: [P, (6.7)] dOmega/dt = I^{-1} ((I Omega) x Omega), I = diag(I1, I2, I3).
Vec3 euler_rhs(const Vec3& I, const Vec3& Omega) { todo("euler_rhs"); }

// TODO: [P, (6.8)] dR/dt = R hat(Omega).
Mat3 poisson_rhs(const Mat3& R, const Vec3& Omega) { todo("poisson_rhs"); }

// TODO: check the moments once, then return f(t, y) = pack({euler_rhs, poisson_rhs}) of unpack(y).
OdeRhs free_body_equations(const Vec3& I) { todo("free_body_equations"); }

// TODO: [P, (6.9)] 1/2 (I1 Omega1^2 + I2 Omega2^2 + I3 Omega3^2).
double rotational_energy(const Vec3& I, const Vec3& Omega) { todo("rotational_energy"); }

// TODO: [P, (6.9)] |I Omega|^2.
double angular_momentum_squared(const Vec3& I, const Vec3& Omega) { todo("angular_momentum_squared"); }

// TODO (derivation): linearise Euler's equation about Omega = spin e_axis.
double wobble_frequency_squared(const Vec3& I, int axis, double spin) { todo("wobble_frequency_squared"); }

}  // namespace rigid
