// Chapter 5 scene: the closed form of Theorem 1 against an independent computation, for many
// random inertia sets.
//
// The independent computation never uses (4.5)-(4.11). It solves the Euler equation E = f T
// itself [P, (3.4)], sampled at 16 instants, by Levenberg-Marquardt (GSL multifit_nlinear)
// from random starting points: J = diag(A, B, C) fixed, z(0) = a and beta = alpha imposed
// (Lemma 1 (b) and Case 3), and the directions of a, b and k and the frequency alpha free
// (7 unknowns, 48 equations). Whatever instant of the motion it lands on, the numbers that do
// not depend on the instant are compared with the closed form: alpha, the angle theta between
// k and b, the body-fixed direction of a (one of the four (+-p, 0, +-q)), and (a, b), which
// the solver is free to choose and which Theorem 1 says is 0. Each set is also integrated
// for 2 periods from the closed form's initial state.
#include <gsl/gsl_blas.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "heavy_body.hpp"
#include "rigid/grioli.hpp"
#include "rigid/heavy_top.hpp"
#include "rigid/ode.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"
#include "stability.hpp"

using rigid::Mat3;
using rigid::Vec3;
using std::numbers::pi;

namespace {

Vec3 unit(double theta, double phi) {
    return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

struct Problem {
    Mat3 J;
    double f, scale;  // scale = f / C: alpha^2 = scale * exp(x6)
};

struct Unknowns {
    Vec3 a, b, k;
    double alpha;
};

Unknowns decode(const Problem& P, const double* x) {
    return {unit(x[0], x[1]), unit(x[2], x[3]), unit(x[4], x[5]),
            std::sqrt(P.scale * std::exp(std::clamp(x[6], -50.0, 50.0)))};
}

// snippet: ch05_independent
// The residual vector: (E(t_j) - f T(t_j)) / f at 16 instants over two periods, with
// R(t) = R^b(alpha t) R^a(alpha t), z(0) = a, J = diag(A, B, C).
int residual(const gsl_vector* x, void* params, gsl_vector* r) {
    const Problem& P = *static_cast<const Problem*>(params);
    const Unknowns u = decode(P, x->data);
    const rigid::TrialPrecession p{u.a, u.alpha, u.b, u.alpha};
    for (int j = 0; j < 16; ++j) {
        const double t = (j + 0.5) * 4 * pi / u.alpha / 16;
        const Vec3 e = (rigid::euler_vector(P.J, p, t) - P.f * rigid::torque(u.k, u.a, p, t)) / P.f;
        for (int i = 0; i < 3; ++i) gsl_vector_set(r, 3 * j + i, e(i));
    }
    return GSL_SUCCESS;
}
// end snippet

struct Params {
    int sets = 200;
    long seed = 2024;
    int tries = 200;
};

void declare(kit::Options& opts, Params& p) {
    opts.integer("sets", &p.sets, "random inertia sets", 1, 100000)
        .integer("seed", &p.seed, "seed of the random sets and starts", 0, 1000000)
        .integer("tries", &p.tries, "random starts allowed per set", 1, 10000);
}

// The worst disagreements over the sets, and how many the independent solve found.
struct Worst {
    int solved = 0;
    long tries_total = 0;
    double alpha = 0, theta = 0, a = 0, ab = 0, integration = 0;
    // The set with the largest integration error: its moments and its run's right-hand sides.
    rigid::Moments worst_body{};
    long worst_rhs_calls = 0;
};

// A random body: A in [0.5, 2], (B - A)/(C - A) log-uniform in [1e-4, 1 - 1e-4],
// C - A up to A (so that A + B >= C), f log-uniform in [1e-3, 1e3].
std::pair<rigid::Moments, double> random_body(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> U(0, 1);
    const double A = 0.5 + 1.5 * U(rng), CA = (0.05 + 0.95 * U(rng)) * A;
    double frac = std::pow(10.0, -4 * U(rng));
    if (U(rng) < 0.5) frac = 1 - frac;
    frac = std::clamp(frac, 1e-4, 1 - 1e-4);
    const rigid::Moments m = rigid::moments_from_gaps(A, frac * CA, (1 - frac) * CA);
    return {m, std::pow(10.0, -3 + 6 * U(rng))};
}

constexpr std::size_t n = 48, np = 7;  // residuals, unknowns

// Solves E = f T for one body from random starts, at most max_tries of them, and compares the
// first solution with the closed form g. Returns whether one was found.
bool solve_independently(const rigid::Moments& m, double f, const rigid::GrioliPrecession& g, int max_tries,
                         std::mt19937_64& rng, gsl_multifit_nlinear_workspace* w, Worst& worst) {
    std::uniform_real_distribution<double> U(0, 1);
    Problem P{Vec3(m.A, m.B, m.C).asDiagonal(), f, f / m.C};
    gsl_multifit_nlinear_fdf fdf{residual, nullptr, nullptr, n, np, &P, 0, 0, 0};
    for (int tr = 0; tr < max_tries; ++tr) {
        ++worst.tries_total;
        double x0[7];
        for (int i = 0; i < 6; ++i) x0[i] = 2 * pi * U(rng);
        x0[6] = 2 * U(rng) - 1;
        gsl_vector_view xv = gsl_vector_view_array(x0, np);
        gsl_multifit_nlinear_init(&xv.vector, &fdf, w);
        int info = 0;
        gsl_multifit_nlinear_driver(200, 1e-15, 1e-15, 1e-15, nullptr, nullptr, &info, w);
        const double rms = gsl_blas_dnrm2(gsl_multifit_nlinear_residual(w)) / std::sqrt(double(n));
        if (!(rms < 1e-11)) continue;
        const Unknowns u = decode(P, gsl_multifit_nlinear_position(w)->data);
        if (u.a.cross(u.b).norm() < 0.05) continue;  // a along b: a pure rotation, not (1.4)
        const double theta = std::atan2(u.k.cross(u.b).norm(), u.k.dot(u.b));
        double e_a = 1e300;
        for (double sa : {1.0, -1.0})
            for (double sc : {1.0, -1.0}) e_a = std::min(e_a, (u.a - Vec3(sa * g.a.x(), 0, sc * g.a.z())).norm());
        worst.alpha = std::max(worst.alpha, std::abs(u.alpha / g.alpha - 1));
        worst.theta = std::max(worst.theta, std::abs(theta - g.theta));
        worst.a = std::max(worst.a, e_a);
        worst.ab = std::max(worst.ab, std::abs(u.a.dot(u.b)));
        return true;
    }
    return false;
}

// Every set: the independent solve, and two periods of rk8pd against the closed form.
Worst compute(const Params& p) {
    std::mt19937_64 rng(static_cast<unsigned>(p.seed));
    gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
    gsl_multifit_nlinear_workspace* w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, np);
    Worst worst;
    for (int s = 0; s < p.sets; ++s) {
        const auto [m, f] = random_body(rng);
        const rigid::GrioliPrecession g = rigid::grioli_precession(m, f, rigid::Sense::ccw);
        worst.solved += solve_independently(m, f, g, p.tries, rng, w, worst);
        const rigid::PrecessionCheck c = rigid::integrate_grioli(
            m, g, 2, 8, {.method = "rk8pd", .rel_tol = 1e-12, .abs_tol = 1e-12 * std::min(1.0, g.alpha)});
        if (c.max_rotation_error >= worst.integration)
            worst.integration = c.max_rotation_error, worst.worst_body = m, worst.worst_rhs_calls = c.stats.rhs_calls;
    }
    gsl_multifit_nlinear_free(w);
    return worst;
}

void report(kit::Scene& scene, const Params& p, const Worst& worst, double run_time) {
    const int sets = p.sets;
    if (worst.solved < sets)
        throw kit::NumericalFailure("the independent solve failed for " + std::to_string(sets - worst.solved) + " of " +
                                    std::to_string(sets) + " sets");
    scene.report.headline(
        "worst disagreement between the closed form and the independent solve (alpha relative, theta, a)",
        std::max({worst.alpha, worst.theta, worst.a}), run_time);
    scene.report.add("sets", static_cast<long>(sets));
    scene.report.add("solved", static_cast<long>(worst.solved));
    scene.report.add("mean_starts_per_set", double(worst.tries_total) / sets);
    scene.report.add("worst_alpha_relative", worst.alpha);
    scene.report.add("worst_theta", worst.theta, "radians");
    scene.report.add("worst_a", worst.a, "|a_solved - a_closed form| (sign pattern matched)");
    scene.report.add("worst_a_dot_b", worst.ab, "the solver's (a, b): Theorem 1 says 0");
    scene.report.add("worst_integration_error", worst.integration, "2 periods, rk8pd, tol 1e-12");
    // The stability of the precession with that error. Over 2 periods no instability grows by more
    // than |mu|^2 (about 2 for the most unstable shapes of Chapter 7): it cannot dominate the error
    // and the report says which it is, not more; one monodromy matrix, not one per set.
    if (worst.worst_rhs_calls > 0)
        kit::report_stability(scene.report, worst.worst_body, rigid::Sense::ccw,
                              {2, worst.integration, 1e-12, kit::rk8pd_steps(worst.worst_rhs_calls)});
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("grioli_random_check",
                      "Chapter 5: the closed form against an independent solve of E = f T, random inertia sets");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        // The work per set: a few random starts of the independent solve (about 3 on average; the
        // watchdog stops a run whose sets all need `tries`) and 2 periods of rk8pd.
        kit::require_budget(o,
                            {double(p.sets), 3 * 6e-3 + 2 * kit::seconds_per_period("rk8pd", 1e-12), "sets", "--sets"});
        const auto t0 = std::chrono::steady_clock::now();
        const Worst worst = compute(p);
        const double run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        report(scene, p, worst, run_time);
    });
}
