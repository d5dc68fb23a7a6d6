// Chapter 4 exercises: the heavy top. Contracts, conventions and equation numbers are in
// rigid/heavy_top.hpp; hints in exercises/hints.md. Replace each todo(...) with your code.
#include "rigid/heavy_top.hpp"

#include <gsl/gsl_multimin.h>

#include "rigid/require.hpp"
#include "rigid/rotation.hpp"
#include "rigid/todo.hpp"

namespace rigid {

// TODO: check J (symmetric, positive definite), f > 0, and normalise k and z(0).
HeavyTop heavy_top(const Mat3& J, double f, const Vec3& k, const Vec3& z0) { todo("heavy_top"); }

// TODO: [P, (3.1), (3.2)] Omega_dot from J Omega_dot = [J Omega, Omega] + f [R^T k, z(0)]; R_dot = R hat(Omega).
BodyState euler_poisson_rhs(const HeavyTop& top, const BodyState& s) { todo("euler_poisson_rhs"); }

// TODO: H = 1/2 (Omega, J Omega) + f (k, R z(0)).
double heavy_top_energy(const HeavyTop& top, const BodyState& s) { todo("heavy_top_energy"); }

// TODO: the 12 x 12 matrix d(rhs)/dy in the layout of pack().
MatX euler_poisson_jacobian(const HeavyTop& top, const BodyState& s) { todo("euler_poisson_jacobian"); }

// TODO: [P, (3.4)] E = J Omega_dot - [J Omega, Omega] with Omega(t) from [P, (1.5)].
Vec3 euler_vector(const Mat3& J, const TrialPrecession& p, double t) { todo("euler_vector"); }

// TODO: [P, (3.4)] T = [R(t)^T k, z(0)] with R(t) = R^b(beta t) R^a(alpha t).
Vec3 torque(const Vec3& k, const Vec3& z0, const TrialPrecession& p, double t) { todo("torque"); }

// TODO: the sum of the eleven terms of the series at time t.
Vec3 evaluate(const PrecessionSeries& s, double alpha, double beta, double t) { todo("evaluate"); }

// TODO: [P, (3.5)], corrected: the coefficient vectors of E.
PrecessionSeries euler_vector_series(const Mat3& J, double alpha, double beta, double b3) {
    todo("euler_vector_series");
}

// TODO: [P, (3.6)], corrected: the coefficient vectors of T.
PrecessionSeries torque_series(const Vec3& k, const Vec3& z0, double alpha, double beta, double b3) {
    todo("torque_series");
}

// TODO: the RMS of |E - f T| / f over n sample times spread over 4 pi / min(alpha, beta).
double precession_residual(const HeavyTop& top, const TrialPrecession& p, int n) { todo("precession_residual"); }

// TODO: Nelder-Mead (gsl_multimin_fminimizer_nmsimplex2) over the free parameters, from random starts.
PrecessionFit min_precession_residual(const PrecessionSearch& search) { todo("min_precession_residual"); }

// TODO (derivation): linearise (3.1)-(3.2) about the upright spin.
double sleeping_top_min_spin(double A, double C, double f) { todo("sleeping_top_min_spin"); }

}  // namespace rigid
