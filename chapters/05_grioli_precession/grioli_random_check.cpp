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

#include "common.hpp"
#include "rigid/grioli.hpp"
#include "rigid/heavy_top.hpp"
#include "rigid/ode.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

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
    return {unit(x[0], x[1]), unit(x[2], x[3]), unit(x[4], x[5]), std::sqrt(P.scale * std::exp(std::clamp(x[6], -50.0, 50.0)))};
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

}  // namespace

int main(int argc, char** argv) {
    kit::Options opts("grioli_random_check", "Chapter 5: the closed form against an independent solve of E = f T, random inertia sets");
    opts.integer("sets", 200, "random inertia sets", 1, 100000)
        .integer("seed", 2024, "seed of the random sets and starts", 0, 1000000)
        .integer("tries", 200, "random starts allowed per set", 1, 10000);

    return kit::run(argc, argv, opts, [](const kit::Options& o, kit::Scene& scene) {
        const int sets = static_cast<int>(o.integer("sets")), max_tries = static_cast<int>(o.integer("tries"));
        std::mt19937_64 rng(static_cast<unsigned>(o.integer("seed")));
        // The work per set: a few random starts of the independent solve (about 3 on average; the
        // watchdog stops a run whose sets all need `tries`) and 2 periods of rk8pd.
        kit::require_budget(o, {double(sets), 3 * 6e-3 + 2 * ch5::seconds_per_period("rk8pd", 1e-12), "sets", "--sets"});
        std::uniform_real_distribution<double> U(0, 1);
        const std::size_t n = 48, np = 7;
        gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
        gsl_multifit_nlinear_workspace* w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, np);

        int solved = 0;
        long tries_total = 0;
        double worst_alpha = 0, worst_theta = 0, worst_a = 0, worst_ab = 0, worst_integration = 0, worst_closed = 0;
        const auto t0 = std::chrono::steady_clock::now();
        for (int s = 0; s < sets; ++s) {
            // A random body: A in [0.5, 2], (B - A)/(C - A) log-uniform in [1e-4, 1 - 1e-4],
            // C - A up to A (so that A + B >= C), f log-uniform in [1e-3, 1e3].
            const double A = 0.5 + 1.5 * U(rng), CA = (0.05 + 0.95 * U(rng)) * A;
            double frac = std::pow(10.0, -4 * U(rng));
            if (U(rng) < 0.5) frac = 1 - frac;
            frac = std::clamp(frac, 1e-4, 1 - 1e-4);
            const rigid::Moments m = rigid::moments_from_gaps(A, frac * CA, (1 - frac) * CA);
            const double f = std::pow(10.0, -3 + 6 * U(rng));
            const rigid::GrioliPrecession g = rigid::grioli_precession(m, f, rigid::Sense::ccw);
            Problem P{Vec3(m.A, m.B, m.C).asDiagonal(), f, f / m.C};
            gsl_multifit_nlinear_fdf fdf{residual, nullptr, nullptr, n, np, &P, 0, 0, 0};
            bool found = false;
            for (int tr = 0; tr < max_tries && !found; ++tr) {
                ++tries_total;
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
                found = true;
                const double theta = std::atan2(u.k.cross(u.b).norm(), u.k.dot(u.b));
                double e_a = 1e300;
                for (double sa : {1.0, -1.0})
                    for (double sc : {1.0, -1.0}) e_a = std::min(e_a, (u.a - Vec3(sa * g.a.x(), 0, sc * g.a.z())).norm());
                worst_alpha = std::max(worst_alpha, std::abs(u.alpha / g.alpha - 1));
                worst_theta = std::max(worst_theta, std::abs(theta - g.theta));
                worst_a = std::max(worst_a, e_a);
                worst_ab = std::max(worst_ab, std::abs(u.a.dot(u.b)));
            }
            solved += found;
            const rigid::PrecessionCheck c = rigid::integrate_grioli(
                m, g, 2, 8, {.method = "rk8pd", .rel_tol = 1e-12, .abs_tol = 1e-12 * std::min(1.0, g.alpha)});
            worst_integration = std::max(worst_integration, c.max_rotation_error);
        }
        gsl_multifit_nlinear_free(w);
        const double run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (solved < sets) throw kit::NumericalFailure("the independent solve failed for " + std::to_string(sets - solved) + " of " +
                                                       std::to_string(sets) + " sets");
        worst_closed = std::max({worst_alpha, worst_theta, worst_a});
        scene.report.headline("worst disagreement between the closed form and the independent solve (alpha relative, theta, a)",
                              worst_closed, run_time);
        scene.report.add("sets", static_cast<long>(sets));
        scene.report.add("solved", static_cast<long>(solved));
        scene.report.add("mean_starts_per_set", double(tries_total) / sets);
        scene.report.add("worst_alpha_relative", worst_alpha);
        scene.report.add("worst_theta", worst_theta, "radians");
        scene.report.add("worst_a", worst_a, "|a_solved - a_closed form| (sign pattern matched)");
        scene.report.add("worst_a_dot_b", worst_ab, "the solver's (a, b): Theorem 1 says 0");
        scene.report.add("worst_integration_error", worst_integration, "2 periods, rk8pd, tol 1e-12");
    });
}
