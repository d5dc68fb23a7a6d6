// The linear stability of a Grioli precession, for every scene that integrates one: an error that
// grows because the precession is unstable is physics, not arithmetic, and the report says so.
//
//   const kit::LinearStability s = kit::linear_stability(m, sense);  // one monodromy, a few ms
//   kit::report_stability(scene.report, s, {.periods = 100, .error = err, .tol = 1e-13,
//                                           .steps = kit::rk8pd_steps(stats.rhs_calls)});
//
// The monodromy matrix M = Phi(P) of the variational equations dPhi/dt = D(t) Phi along the
// exact precession over one period P = 2 pi / alpha (Phi(0) = 1), and its eigenvalues, the Floquet
// multipliers: a deviation grows by |mu| per period for the largest |mu|. D is the Jacobian of
// Euler's equations on the moment gaps (rigid::euler_poisson_rhs_gaps), written out here: the one
// of Chapter 4, built from J, forms B Omega_C - C Omega_C from rounded products and leaves an error
// of relative size eps B / A in its first row (Chapter 6), of order 1 far out on a Grioli line. The multipliers depend on the moments only up to scale and not on f
// (scaling J or f rescales time, and a period stays a period): the monodromy is taken with
// f = S = grioli_root(m), so that alpha = 1 and Omega and R are both of size 1 whatever the size
// of the moments, and the tolerance means the same in every column of Phi.
//
// Header-only: a scene that includes it links the grioli topic (which brings heavy_top, rotation
// and ode), as every scene that integrates a Grioli precession does.
#pragma once

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <vector>

#include "rigid/grioli.hpp"
#include "rigid/ode.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

namespace kit {

using Mat12 = Eigen::Matrix<double, 12, 12>;

// The Jacobian of euler_poisson_rhs_gaps at the state s, with respect to the packed state
// (Omega, then R row by row): Euler's equations on the gaps,
//   A Omega_dot_A = (B - C) Omega_B Omega_C + f [R^T k, z0]_A  (and cyclically),
// whose torque f [R^T k, z0] = -f hat(z0) R^T k has d(R^T k)_c / dR_ac = k_a, and R_dot = R hat(Omega).
inline Mat12 gap_jacobian(const rigid::Moments& m, double f, const rigid::Vec3& k, const rigid::Vec3& z0,
                          const rigid::BodyState& s) {
    const double gBC = -m.C_minus_B, gCA = m.B_minus_A + m.C_minus_B, gAB = -m.B_minus_A;
    const rigid::Vec3& W = s.Omega;
    Mat12 D = Mat12::Zero();
    D(0, 1) = gBC * W(2) / m.A, D(0, 2) = gBC * W(1) / m.A;
    D(1, 0) = gCA * W(2) / m.B, D(1, 2) = gCA * W(0) / m.B;
    D(2, 0) = gAB * W(1) / m.C, D(2, 1) = gAB * W(0) / m.C;
    const rigid::Mat3 G = -f * rigid::Vec3(1 / m.A, 1 / m.B, 1 / m.C).asDiagonal() * rigid::hat(z0);
    for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c) D.block<3, 1>(0, 3 + 3 * a + c) = G.col(c) * k(a);
    const rigid::Mat3 Wh = rigid::hat(W);
    for (int i = 0; i < 3; ++i)
        for (int c = 0; c < 3; ++c) {
            for (int l = 0; l < 3; ++l) D(3 + 3 * i + c, 3 + 3 * i + l) = Wh(l, c);
            for (int n = 0; n < 3; ++n) D(3 + 3 * i + c, n) = (s.R * rigid::hat(rigid::Vec3::Unit(n)))(i, c);
        }
    return D;
}

// The tolerance the scenes take the monodromy at (Chapter 7's default).
inline constexpr double monodromy_tol = 1e-11;

// snippet: monodromy
// The monodromy matrix over one period P = 2 pi / alpha: Phi(P) with Phi(0) = 1 and
// dPhi/dt = D(y(t)) Phi, y(t) the exact precession (Theorem 1) with f = S, so that alpha = 1;
// Phi is packed column by column. rk8pd at the (relative and absolute) tolerance tol.
inline Mat12 grioli_monodromy(const rigid::Moments& m, rigid::Sense sense, double tol = monodromy_tol) {
    const rigid::GrioliPrecession g = rigid::grioli_precession(m, rigid::grioli_root(m), sense);
    const rigid::OdeRhs rhs = [&](double t, const rigid::VecX& phi) {
        const rigid::BodyState y{rigid::grioli_angular_velocity(g, t), rigid::grioli_rotation(g, t)};
        const Mat12 dPhi = gap_jacobian(m, g.f, g.k, g.z0, y) * Eigen::Map<const Mat12>(phi.data());
        return rigid::VecX(Eigen::Map<const rigid::VecX>(dPhi.data(), 144));
    };
    const Mat12 I = Mat12::Identity();
    rigid::VecX last;
    rigid::integrate_gsl(rhs, Eigen::Map<const rigid::VecX>(I.data(), 144), {0.0, 2 * std::numbers::pi / g.alpha},
                         [&](double, const rigid::VecX& phi) { last = phi; },
                         {.method = "rk8pd", .rel_tol = tol, .abs_tol = tol});
    return Eigen::Map<const Mat12>(last.data());
}
// end snippet

// About how long one grioli_monodromy takes at tolerance tol, as a budget's estimate:
// c tol^(-1/8) seconds (rk8pd's steps grow as tol^(-1/8); alpha being 1, the steps of a period do
// not depend on the moments). CPU time of one on one core of the 2-core machine at load 6 to 12:
// c = 5.7e-5 to 7.7e-5 (tol = 1e-14 ... 1e-8), 6.9e-5 in Chapter 7's map at 1e-11; c = 8.5e-5.
inline double monodromy_seconds(double tol) { return 8.5e-5 * std::pow(tol, -1.0 / 8); }

struct Floquet {
    double growth = -1e300;  // ln |mu| of the largest multiplier: growth per period
    double rotation = 0;     // arg(mu) / (2 pi) of the multiplier farthest from 1, in [0, 1/2]
    std::complex<double> largest;
    std::vector<std::complex<double>> multipliers;
};

// The multipliers: the eigenvalues of M.
inline Floquet floquet(const rigid::MatX& M) {
    Eigen::EigenSolver<rigid::MatX> es(M, false);
    Floquet f;
    double far = -1;
    for (Eigen::Index i = 0; i < M.rows(); ++i) {
        const std::complex<double> mu = es.eigenvalues()(i);
        f.multipliers.push_back(mu);
        if (std::log(std::abs(mu)) > f.growth) f.growth = std::log(std::abs(mu)), f.largest = mu;
        if (std::abs(mu - 1.0) > far)
            far = std::abs(mu - 1.0), f.rotation = std::abs(std::arg(mu)) / (2 * std::numbers::pi);
    }
    return f;
}

// Unstable when ln |mu| > 1e-4 per period. A stable precession has its multipliers on the unit
// circle, 1 among them with a Jordan block (the energy and the phase), which the monodromy's own
// error delta ~ tol splits by about sqrt(delta): at tol = 1e-11 (sqrt: 3e-6), ln |mu| of the
// stable shapes of Chapter 7's map of 2400 shapes is at most 4e-6, and its unstable shapes grow by
// 8e-3 per period or more. 1e-4 is 30 sqrt(1e-11), between the two.
inline constexpr double unstable_growth = 1e-4;

struct LinearStability {
    Floquet floquet;
    double tol = 0, time_s = 0;  // of the monodromy
    bool unstable() const { return floquet.growth > unstable_growth; }
    // The largest multiplier, signed when it is real; its modulus when it is one of a complex pair.
    bool real() const { return std::abs(floquet.largest.imag()) <= 1e-9 * std::abs(floquet.largest); }
    double multiplier() const { return real() ? floquet.largest.real() : std::abs(floquet.largest); }
};

inline LinearStability linear_stability(const rigid::Moments& m, rigid::Sense sense, double tol = monodromy_tol) {
    const auto t0 = std::chrono::steady_clock::now();
    LinearStability s;
    s.floquet = floquet(grioli_monodromy(m, sense, tol));
    s.tol = tol;
    s.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return s;
}

// A scene's integration of the precession: how long, the error it measured, and what the
// integrator was asked for.
struct RunError {
    double periods = 0;  // the run's length in periods 2 pi / alpha
    double error = 0;    // the scene's error of that run (a rotation angle, or a distance of unit vectors)
    double tol = 0;      // the integrator's tolerance
    double steps = 0;    // its steps
};

// rk8pd evaluates the right-hand side 13 times a step.
inline double rk8pd_steps(long rhs_calls) { return double(rhs_calls) / 13; }

// snippet: instability_rule
// Is the error the instability's? A stable run gathers at most about tol per step: tol x steps.
// An unstable one can multiply what it gathered by |mu| every period, |mu|^periods over the run.
// The error is dominated by the instability when the precession is unstable, that amplification
// is over 10, the error is over 10 tol x steps (more than the tolerance explains), and it is at
// most tol x steps x |mu|^periods (what the instability can make of it).
struct Verdict {
    double amplification = 1;    // |mu|^periods (at most 1e300)
    double tolerance_error = 0;  // tol x steps
    bool dominated = false;
};

inline Verdict judge(const LinearStability& s, const RunError& run) {
    Verdict v;
    v.amplification = std::exp(std::min(std::max(s.floquet.growth, 0.0) * run.periods, 690.0));
    v.tolerance_error = run.tol * run.steps;
    v.dominated = s.unstable() && v.amplification > 10 && run.error > 10 * v.tolerance_error &&
                  run.error <= v.tolerance_error * v.amplification;
    return v;
}
// end snippet

// One sentence for the printed report: "linearly unstable: multiplier -1.22 per period, ...".
inline std::string stability_sentence(const LinearStability& s, const RunError& run, const Verdict& v) {
    if (!s.unstable())
        return fmt::format(
            "the precession is linearly stable (largest Floquet multiplier |mu| = {:.6f}, ln |mu| <= {:g} per "
            "period): no instability grows its error",
            std::abs(s.floquet.largest), unstable_growth);
    std::string text = fmt::format(
        "the precession is linearly unstable: Floquet multiplier {:.4g} per period (ln |mu| = {:.3g}), so a deviation "
        "grows by |mu|^{:g} = {:.2g} over the run; ",
        s.multiplier(), s.floquet.growth, run.periods, v.amplification);
    if (v.dominated)
        return text +
               fmt::format(
                   "the error {:.2g} is {:.2g} times the tolerance's share tol x steps = {:.2g}: it is dominated "
                   "by the instability (physics), not by the arithmetic",
                   run.error, run.error / v.tolerance_error, v.tolerance_error);
    return text +
           fmt::format("the error {:.2g} is not dominated by it (tol x steps = {:.2g})", run.error, v.tolerance_error);
}

// The report's keys: precession_stability, floquet_multiplier, floquet_multiplier_rotation,
// floquet_growth_per_period, instability_amplification, tolerance_error,
// error_dominated_by_instability, stability_time_s; and the sentence as a note.
inline Verdict report_stability(Report& r, const LinearStability& s, const RunError& run) {
    const Verdict v = judge(s, run);
    r.add("precession_stability", std::string(s.unstable() ? "linearly unstable" : "linearly stable"),
          fmt::format("Floquet multipliers of the integrated precession; unstable: ln |mu| > {:g} per period",
                      unstable_growth));
    r.add("floquet_multiplier", s.multiplier(), "the largest, signed when real (else its modulus)");
    r.add("floquet_multiplier_rotation", std::abs(std::arg(s.floquet.largest)) / (2 * std::numbers::pi),
          "its arg / 2 pi: 0 real positive, 0.5 real negative");
    r.add("floquet_growth_per_period", s.floquet.growth, "ln |mu|");
    r.add("instability_amplification", v.amplification, "|mu|^periods over the run");
    r.add("tolerance_error", v.tolerance_error, "tol x steps: what a stable run gathers at most");
    r.add("error_dominated_by_instability", v.dominated,
          "unstable, |mu|^periods > 10, tol x steps x 10 < error <= tol x steps x |mu|^periods");
    r.add("stability_time_s", s.time_s, "the monodromy matrix and its eigenvalues");
    r.note(stability_sentence(s, run, v));
    return v;
}

// The same without a report, for a scene that tabulates many runs: one call a row.
struct RunStability {
    LinearStability stability;
    Verdict verdict;
};
inline RunStability run_stability(const rigid::Moments& m, rigid::Sense sense, const RunError& run) {
    const LinearStability s = linear_stability(m, sense);
    return {s, judge(s, run)};
}

// The one call of a scene: the stability of the precession it integrates, into its report.
inline Verdict report_stability(Report& r, const rigid::Moments& m, rigid::Sense sense, const RunError& run) {
    return report_stability(r, linear_stability(m, sense), run);
}

}  // namespace kit
