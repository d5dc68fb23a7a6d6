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

#include "common.hpp"
#include "rigid/grioli.hpp"
#include "rigid/ode.hpp"
#include "scene.hpp"

using rigid::Vec3;

namespace {

struct Params {
    ch5::Body body;
    std::string sense = "ccw";
    long periods = 100;
    int samples = 16;
    std::string method = "rk8pd";
    double tol = 1e-12;
};

void declare(kit::Options& opts, Params& p) {
    ch5::moment_options(opts, p.body)
        .choice("sense", &p.sense, {"ccw", "cw"}, "counter-clockwise or clockwise precession (Theorem 1)")
        .integer("periods", &p.periods, "periods 2 pi / alpha to integrate", 1, 100000)
        .integer("samples", &p.samples, "comparisons per period", 1, 10000)
        .choice("method", &p.method, rigid::gsl_methods(), "GSL stepper (implicit ones get the analytic Jacobian)")
        .real("tol", &p.tol,
              "relative tolerance; the absolute one is tol * min(1, alpha), alpha being the unit of Omega",
              kit::between(1e-15, 1e-2));
}

void check_budget(const kit::Options& o, const Params& p) {
    kit::require_budget(o, {double(p.periods) * (p.periods <= 1000 ? 3 : 1),
                            ch5::seconds_per_period(p.method, p.tol) + double(p.samples) * 2e-6, "periods",
                            "--periods, --samples, --method, --tol"});
}

struct Integration {
    rigid::GrioliPrecession g;
    rigid::OdeSettings settings;
    rigid::PrecessionCheck c;
    double run_time;
};

// snippet: ch05_contract
// The precession of the options, built from A < B < C and f, integrated for `periods` periods.
Integration integrate(const Params& p) {
    const rigid::Moments m = ch5::moments(p.body.moments);
    const rigid::Sense sense = p.sense == "ccw" ? rigid::Sense::ccw : rigid::Sense::cw;
    const rigid::GrioliPrecession g = rigid::grioli_precession(m, p.body.f, sense);
    const rigid::OdeSettings settings{.method = p.method, .rel_tol = p.tol, .abs_tol = p.tol * std::min(1.0, g.alpha)};
    rigid::PrecessionCheck c{};
    const double run_time = kit::min_time(
        [&] { c = rigid::integrate_grioli(m, g, double(p.periods), p.samples, settings); }, p.periods <= 1000 ? 3 : 1);
    return {g, settings, c, run_time};
}
// end snippet

void report(kit::Scene& scene, const Params& p, const Integration& r) {
    const rigid::GrioliPrecession& g = r.g;
    const rigid::PrecessionCheck& c = r.c;
    if (!std::isfinite(c.max_rotation_error))
        throw kit::NumericalFailure("the integration produced a non-finite rotation");
    scene.report.headline(
        "max over t of the geodesic angle between integrated R(t) and R^b(sigma alpha t) R^a(sigma alpha t)",
        c.max_rotation_error, r.run_time);
    scene.report.add("alpha", g.alpha, "[P, (int.4)]: frequency of both rotations");
    scene.report.add("theta", g.theta, "[P, (int.3)]: angle between k and b (radians)");
    scene.report.add("a", g.a, "rotation vector, inertia frame (A, B, C) [P, (4.10)]");
    scene.report.add("b", g.b, "precession vector = R_B(0)");
    scene.report.add("k", g.k, "upward vertical [P, (4.11)]");
    scene.report.add("z0", g.z0, "centre-of-mass direction z(0) = a");
    scene.report.add("sense", p.sense);
    scene.report.add("periods", p.periods);
    scene.report.add("max_rotation_error", c.max_rotation_error, "radians");
    scene.report.add("max_omega_error", c.max_omega_error, "max |Omega - Omega_exact| / alpha");
    scene.report.add("max_energy_drift", c.max_energy_drift, "max |H - H(0)| / f");
    scene.report.add("orthogonality", c.orthogonality, "|R^T R - 1| at the end");
    scene.report.add("period", 2 * std::numbers::pi / g.alpha);
    scene.report.add("method", p.method);
    scene.report.add("rel_tol", r.settings.rel_tol);
    scene.report.add("abs_tol", r.settings.abs_tol);
    scene.report.add("rhs_calls", c.stats.rhs_calls);
    scene.report.add("jacobian_calls", c.stats.jacobian_calls);
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("grioli_precession",
                      "Chapter 5: a Grioli precession, built from A < B < C and f, integrated and compared");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        check_budget(o, p);
        report(scene, p, integrate(p));
    });
}
