// Chapter 5 scene: Theorem 1 verified by integration [P, Theorem 1, (int.3), (int.4),
// (4.10), (4.11)].
//
// Builds the precession of the chosen sense from A < B < C and f (rigid::grioli_precession),
// starts the Euler-Poisson equations (3.1)-(3.2) from its state at t = 0 and integrates them
// with GSL for N periods, comparing R(t) with R^b(sigma alpha t) R^a(sigma alpha t) at every
// sample: the largest geodesic angle between the two is the error.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "rigid/grioli.hpp"
#include "rigid/ode.hpp"
#include "common.hpp"
#include "scene.hpp"

using rigid::Vec3;

int main(int argc, char** argv) {
    kit::Options opts("grioli_precession", "Chapter 5: a Grioli precession, built from A < B < C and f, integrated and compared");
    ch5::moment_options(opts)
        .choice("sense", "ccw", {"ccw", "cw"}, "counter-clockwise or clockwise precession (Theorem 1)")
        .integer("periods", 100, "periods 2 pi / alpha to integrate", 1, 100000)
        .integer("samples", 16, "comparisons per period", 1, 10000)
        .choice("method", "rk8pd", rigid::gsl_methods(), "GSL stepper (implicit ones get the analytic Jacobian)")
        .real("tol", 1e-12, "relative tolerance; the absolute one is tol * min(1, alpha), alpha being the unit of Omega",
              kit::between(1e-15, 1e-2));

    return kit::run(argc, argv, opts, [](const kit::Options& o, kit::Scene& scene) {
        kit::require_budget(o, {double(o.integer("periods")) * (o.integer("periods") <= 1000 ? 3 : 1),
                                ch5::seconds_per_period(o.choice("method"), o.real("tol")) + double(o.integer("samples")) * 2e-6,
                                "periods", "--periods, --samples, --method, --tol"});
        // snippet: ch05_contract
        const rigid::Moments m = ch5::moments(o);
        const rigid::Sense sense = o.choice("sense") == "ccw" ? rigid::Sense::ccw : rigid::Sense::cw;
        const rigid::GrioliPrecession g = rigid::grioli_precession(m, o.real("f"), sense);
        const long periods = o.integer("periods");
        const double tol = o.real("tol");
        const rigid::OdeSettings settings{.method = o.choice("method"), .rel_tol = tol, .abs_tol = tol * std::min(1.0, g.alpha)};
        rigid::PrecessionCheck c{};
        const double run_time = kit::min_time([&] {
            c = rigid::integrate_grioli(m, g, double(periods), static_cast<int>(o.integer("samples")), settings);
        }, periods <= 1000 ? 3 : 1);
        // end snippet
        if (!std::isfinite(c.max_rotation_error))
            throw kit::NumericalFailure("the integration produced a non-finite rotation");

        scene.report.headline("max over t of the geodesic angle between integrated R(t) and R^b(sigma alpha t) R^a(sigma alpha t)",
                              c.max_rotation_error, run_time);
        scene.report.add("alpha", g.alpha, "[P, (int.4)]: frequency of both rotations");
        scene.report.add("theta", g.theta, "[P, (int.3)]: angle between k and b (radians)");
        scene.report.add("a", g.a, "rotation vector, inertia frame (A, B, C) [P, (4.10)]");
        scene.report.add("b", g.b, "precession vector = R_B(0)");
        scene.report.add("k", g.k, "upward vertical [P, (4.11)]");
        scene.report.add("z0", g.z0, "centre-of-mass direction z(0) = a");
        scene.report.add("sense", o.choice("sense"));
        scene.report.add("periods", periods);
        scene.report.add("max_rotation_error", c.max_rotation_error, "radians");
        scene.report.add("max_omega_error", c.max_omega_error, "max |Omega - Omega_exact| / alpha");
        scene.report.add("max_energy_drift", c.max_energy_drift, "max |H - H(0)| / f");
        scene.report.add("orthogonality", c.orthogonality, "|R^T R - 1| at the end");
        scene.report.add("period", 2 * std::numbers::pi / g.alpha);
        scene.report.add("method", o.choice("method"));
        scene.report.add("rel_tol", settings.rel_tol);
        scene.report.add("abs_tol", settings.abs_tol);
        scene.report.add("rhs_calls", c.stats.rhs_calls);
        scene.report.add("jacobian_calls", c.stats.jacobian_calls);
    });
}
