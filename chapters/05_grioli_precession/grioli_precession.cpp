// Chapter 5 scene: Theorem 1 verified by integration [P, Theorem 1, (int.3), (int.4),
// (4.10), (4.11)].
//
// Builds the precession of the chosen sense from A < B < C and f (rigid::grioli_precession),
// starts the Euler-Poisson equations (3.1)-(3.2) from its state at t = 0 and integrates them
// for N periods, comparing R(t) with R^b(sigma alpha t) R^a(sigma alpha t) at every sample: the
// largest geodesic angle between the two is the error. Up to 1000 periods it integrates with GSL
// through your integrate_grioli (--method auto picks rk8pd); beyond, a GSL method's energy
// drifts like t and its phase error grows like t^2 (1e-3 rad after 1e5 periods), and auto picks
// the provided Taylor method of degree 16 with compensated summation (Chapter 7), whose round-off
// does not correlate: its phase error grows like t^(3/2) (Brouwer's law).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "heavy_body.hpp"
#include "motion.hpp"
#include "rigid/grioli.hpp"
#include "rigid/heavy_top.hpp"
#include "rigid/ode.hpp"
#include "rigid/rotation.hpp"
#include "rigid/taylor.hpp"
#include "scene.hpp"
#include "stability.hpp"

using rigid::Vec3;

namespace {

struct Params {
    kit::HeavyBody body;
    std::string sense = "ccw";
    long periods = 100;
    int samples = 16;
    std::string method = "auto";
    double tol = 1e-12;
    std::string motion_file;  // --motion: the book's viewer data (motion.hpp)
};

// The methods of --method: GSL's, taylor, and auto.
const std::vector<std::string>& methods() {
    static const std::vector<std::string> all = [] {
        std::vector<std::string> m = rigid::gsl_methods();
        m.insert(m.end(), {"taylor", "auto"});
        return m;
    }();
    return all;
}

// The method auto picks: rk8pd up to 1000 periods, the Taylor method beyond.
std::string method_of(const Params& p) {
    if (p.method != "auto") return p.method;
    return p.periods <= 1000 ? "rk8pd" : "taylor";
}

// The provided Taylor method: degree 16 and 32 steps a period (truncation well below round-off
// for every body: |Omega| <= 2 alpha), with compensated summation.
constexpr int taylor_degree = 16;
constexpr double taylor_steps_per_period = 32;

void declare(kit::Options& opts, Params& p) {
    kit::heavy_body_options(opts, p.body)
        .choice("sense", &p.sense, {"ccw", "cw"}, "counter-clockwise or clockwise precession (Theorem 1)")
        .integer("periods", &p.periods, "periods 2 pi / alpha to integrate", 1, 100000)
        .integer("samples", &p.samples, "comparisons per period", 1, 10000)
        .choice("method", &p.method, methods(),
                "a GSL stepper (implicit ones get the analytic Jacobian), or taylor: the provided Taylor method "
                "of degree 16, 32 steps a period, compensated summation (it ignores --tol); auto: rk8pd up to "
                "1000 periods, taylor beyond")
        .real("tol", &p.tol,
              "relative tolerance; the absolute one is tol * min(1, alpha), alpha being the unit of Omega",
              kit::between(1e-15, 1e-2))
        .file("motion", &p.motion_file, kit::motion_help);
}

void check_budget(const kit::Options& o, const Params& p) {
    const std::string method = method_of(p);
    // The Taylor step: about 12 degree^2 multiply-adds, measured 3.5 us at degree 16, doubled.
    const double per_period =
        method == "taylor" ? taylor_steps_per_period * 7e-6 : kit::seconds_per_period(method, p.tol);
    kit::require_budget(o, {double(p.periods) * (p.periods <= 1000 ? 3 : 1), per_period + double(p.samples) * 2e-6,
                            "periods", "--periods, --samples, --method, --tol"});
}

struct Integration {
    rigid::Moments m;
    rigid::GrioliPrecession g;
    rigid::OdeSettings settings;
    rigid::PrecessionCheck c;
    double run_time;
};

// The same comparison as integrate_grioli's, with the provided Taylor method: the Euler-Poisson
// equations of grioli_top (the form J Omega), at the same sample times.
rigid::PrecessionCheck integrate_grioli_taylor(const rigid::Moments& m, const rigid::GrioliPrecession& g,
                                               double periods, int samples_per_period) {
    const rigid::HeavyTop top = rigid::grioli_top(m, g);
    const double T = 2 * std::numbers::pi / g.alpha;
    const auto times = rigid::linspace(0.0, periods * T, static_cast<int>(std::ceil(periods * samples_per_period)));
    // Whole steps between samples, as near to taylor_steps_per_period a period as they can be.
    const double span = times.size() > 1 ? times[1] - times[0] : T;
    // (A hair longer, so that the round-off of the sample times never adds a step.)
    const double h = span / std::max(1.0, std::round(span * taylor_steps_per_period / T)) * (1 + 1e-9);
    const rigid::BodyState s0 = rigid::grioli_initial_state(g);
    const double H0 = rigid::heavy_top_energy(top, s0);
    rigid::PrecessionCheck c{0, 0, 0, 0, {}};
    rigid::Mat3 R_last = s0.R;
    const long steps = rigid::integrate_taylor<double>(
        top, s0, times,
        [&](double t, const rigid::TaylorState<double>& x) {
            const rigid::BodyState s = rigid::to_double(x);
            c.max_rotation_error =
                std::max(c.max_rotation_error, rigid::geodesic_angle(s.R, rigid::grioli_rotation(g, t)));
            c.max_omega_error =
                std::max(c.max_omega_error, (s.Omega - rigid::grioli_angular_velocity(g, t)).norm() / g.alpha);
            c.max_energy_drift = std::max(c.max_energy_drift, std::abs(rigid::heavy_top_energy(top, s) - H0) / g.f);
            R_last = s.R;
        },
        h, taylor_degree, rigid::Summation::compensated);
    c.orthogonality = rigid::orthogonality_defect(R_last);
    c.stats.rhs_calls = steps;  // a Taylor step expands the solution once: one call of the equations' terms
    return c;
}

// snippet: ch05_contract
// The precession of the options, built from A < B < C and f, integrated for `periods` periods.
Integration integrate(const Params& p) {
    const rigid::Moments m = kit::grioli_moments(p.body.moments);
    const rigid::Sense sense = p.sense == "ccw" ? rigid::Sense::ccw : rigid::Sense::cw;
    const rigid::GrioliPrecession g = rigid::grioli_precession(m, p.body.f, sense);
    const std::string method = method_of(p);
    const rigid::OdeSettings settings{.method = method, .rel_tol = p.tol, .abs_tol = p.tol * std::min(1.0, g.alpha)};
    rigid::PrecessionCheck c{};
    const double run_time = kit::min_time(
        [&] {
            c = method == "taylor" ? integrate_grioli_taylor(m, g, double(p.periods), p.samples)
                                   : rigid::integrate_grioli(m, g, double(p.periods), p.samples, settings);
        },
        p.periods <= 1000 ? 3 : 1);
    return {m, g, settings, c, run_time};
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
    scene.report.add("method", r.settings.method,
                     p.method == "auto" ? "--method auto: rk8pd up to 1000 periods, taylor beyond" : "--method");
    scene.report.add("rel_tol", r.settings.rel_tol);
    scene.report.add("abs_tol", r.settings.abs_tol);
    scene.report.add("rhs_calls", c.stats.rhs_calls, r.settings.method == "taylor" ? "Taylor steps" : "one run");
    scene.report.add("jacobian_calls", c.stats.jacobian_calls);
    // Is the error physics? The precession's Floquet multipliers (Chapter 7), and whether they,
    // not the arithmetic, made the error. The Taylor method has no tolerance: its steps gather
    // round-off, about eps each.
    const bool taylor = r.settings.method == "taylor";
    kit::report_stability(
        scene.report, r.m, g.sense,
        {double(p.periods), c.max_rotation_error, taylor ? std::numeric_limits<double>::epsilon() : r.settings.rel_tol,
         taylor ? double(c.stats.rhs_calls) : kit::rk8pd_steps(c.stats.rhs_calls)});
}

// The book's motion viewer: two periods of the precession in a lab whose vertical is k (Item II's
// placement R0), R(t) = R^b(sigma alpha t) R^a(sigma alpha t) R0, the closed form the integration
// was compared with, and its two cones: about b in the lab, about a in the body, touching along
// omega = sigma alpha (a + b) at t = 0.
void write_motion(kit::Scene& scene, const Params& p, const Integration& r) {
    if (p.motion_file.empty()) return;
    const rigid::LabPlacement lab = rigid::place_item_II(r.m, p.body.f, r.g.sense, Vec3::UnitZ(), Vec3::UnitX());
    const double s = r.g.sense == rigid::Sense::ccw ? 1.0 : -1.0, T = 2 * std::numbers::pi / lab.alpha;
    const Vec3 w0 = (lab.a + lab.b).normalized();
    kit::Motion b;
    b.title = fmt::format("the {} Grioli precession R(t) = R^b({}αt) R^a({}αt) R0, k up", p.sense, s > 0 ? "" : "−",
                          s > 0 ? "" : "−");
    b.parameters =
        fmt::format("A = {:g}, B = {:g}, C = {:g}, f = {:g}; two periods 2π/α", r.m.A, r.m.B, r.m.C, p.body.f);
    b.error = r.c.max_rotation_error;
    b.error_measure = "max geodesic angle between the integrated R(t) and this closed form (rad)";
    b.moments = {r.m.A, r.m.B, r.m.C};
    b.size = 0.55;
    b.centre_of_mass = r.g.z0;
    b.speed = T / 8;
    b.cones = {
        {"space cone (about b, fixed in the lab)", lab.b, std::acos(std::clamp(lab.b.dot(w0), -1.0, 1.0)), false},
        {"body cone (about a, carried by the body)", lab.R0.transpose() * lab.a,
         std::acos(std::clamp(lab.a.dot(w0), -1.0, 1.0)), true}};
    for (int i = 0; i <= 400; ++i) {
        const double t = 2 * T * i / 400;
        b.sample(t, rigid::rotation_about(lab.b, s * lab.alpha * t) * rigid::rotation_about(lab.a, s * lab.alpha * t) *
                        lab.R0);
    }
    kit::write_motion(scene, p.motion_file, b);
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("grioli_precession",
                      "Chapter 5: a Grioli precession, built from A < B < C and f, integrated and compared");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        check_budget(o, p);
        const Integration r = integrate(p);
        report(scene, p, r);
        write_motion(scene, p, r);
    });
}
