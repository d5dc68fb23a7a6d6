// Chapter 4: the heavy top, Lemma 1 and Routh's result, [P, Sect. 4, (3.1)-(3.14)].
//
// Conventions for this file
//   * The Euler-Poisson state is rigid::BodyState {Omega, R} (rigid/ode.hpp): Omega is the
//     angular velocity in the body frame, R maps body to lab coordinates, R_dot = R hat(Omega)
//     ([P, (3.2)]: R_dot_ij = -eps_jkm Omega_k R_im).
//   * The lab frame coincides with the body frame at t = 0 [P, Sect. 3]: J is the inertia
//     tensor at the fixed point O written in that frame (diagonal only when the lab axes are
//     the inertia axes), z0 = z(0) is the unit vector from O to the centre of mass, in body
//     (= lab at t = 0) coordinates, and k is the upward unit vector in the lab.
//   * f = g L mu > 0 [P, (3.1)]. The torque of gravity in the body frame is f [R^T k, z(0)]
//     ([a, b] is the cross product a x b), so the potential energy is f (k, R z(0)): the
//     centre of mass is high when R z(0) points along k.
//   * A trial regular precession is R(t) = R^b(beta t) R^a(alpha t) [P, (1.4)], with
//     Omega(t) = alpha a + beta R^a(alpha t)^T b [P, (1.5)].
//   * Bad input (a non-symmetric or non-positive J, f <= 0, a zero or non-finite vector,
//     ...) throws std::invalid_argument naming the value and the rule.
//
// How it is graded (tests/grading/README.md): each test calls your functions in a sandboxed
// process of their own, which keeps its state between the calls of one test; the grader runs in
// another. Threads are allowed (up to 16 besides the main one); starting a process or another
// program is not.
#pragma once

#include "rigid/ode.hpp"
#include "rigid/precession.hpp"  // RegularPrecession, the struct only (no function of it is called)
#include "rigid/types.hpp"

namespace rigid {

// snippet: heavy_top
// A heavy rigid body with a fixed point O [P, (3.1)].
struct HeavyTop {
    Mat3 J;    // inertia tensor at O, body frame: symmetric, positive definite
    double f;  // f = g L mu > 0
    Vec3 k;    // upward unit vector (lab)
    Vec3 z0;   // unit vector from O to the centre of mass at t = 0 (body = lab at t = 0)
};

// Checks and normalises: J symmetric (|J_ij - J_ji| <= 1e-12 times the largest |J_kl|) and
// positive definite, f finite and > 0, k and z0 finite and non-zero (returned as unit
// vectors). Throws std::invalid_argument.
HeavyTop heavy_top(const Mat3& J, double f, const Vec3& k, const Vec3& z0);
// end snippet

// snippet: heavy_top_euler_poisson
// The right-hand side of the Euler-Poisson equations [P, (3.1), (3.2)]:
//   J Omega_dot = [J Omega, Omega] + f [R^T k, z(0)],      R_dot = R hat(Omega).
// Returns the time derivative (Omega_dot, R_dot). The top is taken as valid (build it with
// heavy_top()); this function runs millions of times and does not re-check it.
BodyState euler_poisson_rhs(const HeavyTop& top, const BodyState& s);

// The energy H = 1/2 (Omega, J Omega) + f (k, R z(0)), a first integral of (3.1)-(3.2).
double heavy_top_energy(const HeavyTop& top, const BodyState& s);

// The Jacobian of euler_poisson_rhs with respect to the packed state y = pack(s) (12 x 12,
// Omega first, then R row by row): what GSL's implicit steppers need.
MatX euler_poisson_jacobian(const HeavyTop& top, const BodyState& s);
// end snippet

// snippet: heavy_top_in_place
// The same right-hand side in the form GSL calls (OdeRhsInPlace, rigid/ode.hpp): in place on
// the packed state y = (Omega, R row by row), with J^{-1} formed once, not a solve per call.
// Provided, not an exercise: euler_poisson_rhs above is the one to read and to write; this
// one is for speed, and Chapter 7 measures both and checks that they agree.
class EulerPoissonInPlace {
public:
    explicit EulerPoissonInPlace(const HeavyTop& top)
        : J_(top.J), J_inv_(top.J.inverse()), fk_(top.f * top.k), z0_(top.z0) {}

    void operator()(double /*t*/, const double* y, double* dydt) const {
        using Rows = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;  // R row by row, as packed
        const Eigen::Map<const Vec3> W(y);
        const Eigen::Map<const Rows> R(y + 3);
        Eigen::Map<Vec3> W_dot(dydt);
        Eigen::Map<Rows> R_dot(dydt + 3);
        // J Omega_dot = [J Omega, Omega] + f [R^T k, z(0)]
        W_dot = J_inv_ * ((J_ * W).cross(W) + (R.transpose() * fk_).cross(z0_));
        // R_dot = R hat(Omega): row i of R_dot is (row i of R) x Omega
        for (int i = 0; i < 3; ++i) R_dot.row(i) = R.row(i).cross(W.transpose());
    }

private:
    Mat3 J_, J_inv_;
    Vec3 fk_, z0_;
};
// end snippet

// snippet: heavy_top_trial
// A trial regular precession R(t) = R^b(beta t) R^a(alpha t) [P, (1.4)]: the four constants
// of Chapter 2's RegularPrecession {a, alpha, b, beta}, the same struct under the name this
// chapter gives it. Axes a and b are normalised by the functions that take one; [P] takes
// alpha, beta > 0, but the formulas below hold for any finite values (a negative one turning
// the other way), and a search may pass through them.
using TrialPrecession = RegularPrecession;

// The Euler vector E = J Omega_dot - [J Omega, Omega] along the trial precession, at time t,
// with Omega(t) from [P, (1.5)] and its exact time derivative                       [P, (3.4)]
// Throws std::invalid_argument for a zero or non-finite a or b, or non-finite alpha, beta, t.
Vec3 euler_vector(const Mat3& J, const TrialPrecession& p, double t);

// The torque T = [R(t)^T k, z(0)] along the trial precession, at time t             [P, (3.4)]
Vec3 torque(const Vec3& k, const Vec3& z0, const TrialPrecession& p, double t);
// end snippet

// snippet: heavy_top_series
// A trigonometric series with vector coefficients in the frequencies of [P, (3.5)-(3.7)]:
//   v(t) = constant + cos_alpha cos(alpha t) + sin_alpha sin(alpha t)
//        + cos_2alpha cos(2 alpha t) + sin_2alpha sin(2 alpha t)
//        + cos_beta cos(beta t) + sin_beta sin(beta t)
//        + cos_plus cos(gamma_+ t) + sin_plus sin(gamma_+ t)
//        + cos_minus cos(gamma_- t) + sin_minus sin(gamma_- t),
// gamma_+ = alpha + beta, gamma_- = alpha - beta (signed, as in [P, (3.7)]).
struct PrecessionSeries {
    Vec3 constant = Vec3::Zero();
    Vec3 cos_alpha = Vec3::Zero(), sin_alpha = Vec3::Zero();
    Vec3 cos_2alpha = Vec3::Zero(), sin_2alpha = Vec3::Zero();
    Vec3 cos_beta = Vec3::Zero(), sin_beta = Vec3::Zero();
    Vec3 cos_plus = Vec3::Zero(), sin_plus = Vec3::Zero();
    Vec3 cos_minus = Vec3::Zero(), sin_minus = Vec3::Zero();
};

// The value of the series at time t.
Vec3 evaluate(const PrecessionSeries& s, double alpha, double beta, double t);

// In the lab frame of [P, (3.3)]: a = e3, b = (0, b2, b3) with b2 = sqrt(1 - b3^2) > 0.
// The Euler vector E as a series, [P, (3.5)] with its one misprint corrected (see the
// chapter). J symmetric; -1 < b3 < 1; alpha, beta finite. Throws std::invalid_argument.
PrecessionSeries euler_vector_series(const Mat3& J, double alpha, double beta, double b3);

// The torque T as a series, [P, (3.6)] with its two misprints corrected. k = (0, k2, k3) must
// lie in the plane of a and b (|k_1| <= 1e-12 |k|), z0 any vector. Throws std::invalid_argument.
PrecessionSeries torque_series(const Vec3& k, const Vec3& z0, double alpha, double beta, double b3);
// end snippet

// snippet: heavy_top_residual
// How far a trial precession is from solving the Euler equation E = f T [P, (3.4)]: the
// root mean square of |E(t) - f T(t)| / f over n sample times t_j = (j + 1/2) L / n,
// j = 0..n-1, spread over L = 4 pi / min(alpha, beta) (two turns of the slower rotation).
// Zero for a regular precession of the top. n >= 16. Throws std::invalid_argument.
double precession_residual(const HeavyTop& top, const TrialPrecession& p, int n = 24);
// end snippet

// snippet: heavy_top_search
// A numerical search for regular precessions [P, Sect. 4]: in the lab frame of [P, (3.3)],
// a = e3 and b = (0, sin gamma, cos gamma), with the angle gamma between a and b and the
// ratio beta/alpha held fixed, minimise precession_residual (n = 24, f = 1) over
//   * the orientation Q of the body, J = Q diag(moments) Q^T (3 parameters),
//   * the direction of z(0) (2), the direction of k (2; none when k_along_b: then k = b,
//     Routh's question [P, Corollary 1]), and the scale s = alpha^2 / f (1),
// with GSL's Nelder-Mead simplex (nmsimplex2) from `restarts` random starting points drawn
// with `seed`, stopping early once the residual is below 1e-12.
struct PrecessionSearch {
    Vec3 moments;            // principal moments at O, any order: positive, triangle inequality
    double gamma;            // angle between a and b, 0 < gamma < pi
    double ratio;            // beta / alpha > 0
    bool k_along_b = false;  // true: the vertical k is the precession vector b
    int restarts = 12;       // >= 1
    unsigned seed = 1;
};

// top.J is symmetric bit for bit (J_ij == J_ji): a product Q D Q^T is symmetric only to
// rounding, so average it with its transpose.
struct PrecessionFit {
    double residual;             // the smallest precession_residual found
    HeavyTop top;                // the body at the minimum: J in the [P, (3.3)] frame, f = 1, k, z0
    TrialPrecession precession;  // a = e3, b, alpha = sqrt(s), beta = ratio * alpha
    long evaluations;            // residual evaluations, all restarts together
};

// Throws std::invalid_argument for bad moments, gamma or ratio, or restarts < 1.
PrecessionFit min_precession_residual(const PrecessionSearch& search);
// end snippet

// snippet: sleeping_top_min_spin
// A derivation exercise (Chapter 4): a symmetric top, J = diag(A, A, C) at the fixed point
// O, with its centre of mass on the symmetry axis above O (z(0) = k) and f = g L mu, spins
// upright about the vertical symmetry axis at the rate omega: Omega = omega z(0), R = 1.
// Returns the smallest omega > 0 above which this upright spin is linearly stable under
// (3.1)-(3.2) (the top "sleeps"). Throws std::invalid_argument for A, C or f that are not
// finite and > 0, or C > 2A (no body has it).
double sleeping_top_min_spin(double A, double C, double f);
// end snippet

}  // namespace rigid
