// The exact motion of a free rigid body: Omega(t) through Jacobi's elliptic functions and
// R(t) from the conservation of the angular momentum in space plus one quadrature. The
// reference against which Chapter 3 (and Chapter 7) measure every integrator. Provided, not
// an exercise; it uses none of the student's functions.
//
// Conventions for this file
//   * Body frame = principal axes, inertia diag(I1, I2, I3) in any order; R(0) = 1, as in
//     [P, Sect. 3]; Omega(0) = Omega0 arbitrary.
//   * Let the moments be sorted I_lo <= I_mid <= I_hi. Omega circulates about the axis s (the
//     "dn" axis: I_hi when M^2 > 2 E I_mid, I_lo when M^2 < 2 E I_mid); p is the other end
//     axis ("cn") and q the middle one ("sn"):
//       Omega_p = A_p cn(u | m),  Omega_q = A_q sn(u | m),  Omega_s = A_s dn(u | m),  u = u0 + lambda t,
//     with signed amplitudes A and lambda > 0 (Landau and Lifshitz, Mechanics, Sect. 37).
//   * Every constant is computed from sums of terms of one sign, in long double, so that the
//     elliptic parameter m and its complement m_c = 1 - m both keep their relative accuracy
//     near the separatrix (m_c -> 0) and near a symmetric body (m -> 0):
//       m_c = |I_s - I_p| |M^2 - 2 E I_q| / (|I_s - I_q| |M^2 - 2 E I_p|),
//       M^2 - 2 E I_q = I_p (I_p - I_q) Omega_p^2 + I_s (I_s - I_q) Omega_s^2,   etc.
//   * R(t) = W(l0)^T Rot(n, phi(t)) W(l(t)): l = I Omega / |I Omega| (body components of the
//     fixed spatial angular momentum direction), n = +-e_s (the side l never leaves), W(l) the
//     smallest rotation taking l to n, and phi' = 2E / M - n.(l x l') / (1 + n.l), integrated
//     by 20-point Gauss-Legendre panels.
//   * Steady rotations (Omega along a principal axis, any Omega of a spherical body, Omega in
//     the plane of two equal moments) have Omega constant and R(t) = Rot(Omega, |Omega| t).
#pragma once

#include <vector>

#include "rigid/types.hpp"

namespace rigid {

// snippet: jacobi_elliptic
// sn(u | m), cn(u | m), dn(u | m) for 0 <= m <= 1, with the complement m_c = 1 - m passed
// separately so that it keeps its digits when m is close to 1 (GSL's gsl_sf_elljac_e(u, m)
// forms 1 - m itself). Arithmetic-geometric mean (descending Landen) from a = 1, b = sqrt(m_c);
// dn = sqrt(cn^2 + m_c sn^2), free of cancellation. m_c = 0 gives tanh and sech.
struct JacobiElliptic {
    double sn, cn, dn;
};
JacobiElliptic jacobi_elliptic(double u, double m, double m_c);
// end snippet

// The constants of one free motion, fixed by I and Omega0 (see the conventions above).
struct FreeBodyMotion {
    Vec3 I, Omega0;
    bool steady = false;            // Omega constant
    int p = 0, q = 1, s = 2;        // axes carrying cn, sn and dn
    Vec3 amplitude = Vec3::Zero();  // signed A_p, A_q, A_s, stored at indices p, q, s
    double lambda = 0, u0 = 0;      // u = u0 + lambda t
    double m = 0, m_c = 1;          // elliptic parameter and its complement (m + m_c = 1)
    double energy = 0;              // E = 1/2 Omega.I Omega
    double momentum_squared = 0;    // M^2 = |I Omega|^2
    double period = 0;              // of Omega(t): 4 K(m) / lambda; +infinity on the separatrix, 0 if steady
};

// snippet: free_body_exact
// Throws std::invalid_argument for bad moments (rigid::require_principal_moments) or a
// non-finite Omega0.
FreeBodyMotion free_body_motion(const Vec3& I, const Vec3& Omega0);

// Omega(t), exact up to the round-off of u = u0 + lambda t (relative error ~ eps |lambda t|).
Vec3 free_body_exact_omega(const FreeBodyMotion& motion, double t);

// R(t) at each of the given times (strictly increasing; t = 0 need not be among them).
std::vector<Mat3> free_body_exact_rotations(const FreeBodyMotion& motion, const std::vector<double>& times);
// end snippet

}  // namespace rigid
