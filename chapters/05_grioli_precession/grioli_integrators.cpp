// Chapter 5 scene: Theorem 1 as a benchmark. The Grioli precession is an exact solution of
// the full Euler-Poisson system, so every integrator can be scored against it: the largest
// rotation error over 100 periods (geodesic angle, computed with atan2) against the run time,
// for GSL's explicit (rk8pd, rkck, rkf45, msadams) and implicit (bsimp, msbdf, rk4imp, with
// the analytic Jacobian) steppers at several tolerances.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "figure.hpp"
#include "grioli_integrators.gp.hpp"
#include "heavy_body.hpp"
#include "rigid/grioli.hpp"
#include "rigid/ode.hpp"
#include "scene.hpp"
#include "stability.hpp"

namespace {

struct Params {
    kit::HeavyBody body;
    std::string sense = "ccw";
    long periods = 100;
    int repeats = 3;
};

void declare(kit::Options& opts, Params& p) {
    kit::heavy_body_options(opts, p.body)
        .choice("sense", &p.sense, {"ccw", "cw"}, "sense of the precession")
        .integer("periods", &p.periods, "periods to integrate", 1, 10000)
        .integer("repeats", &p.repeats, "timing: the smallest of this many runs (runs over 0.05 s: one)", 1, 20);
}

const std::vector<std::string> methods = {"rk8pd", "rkck", "rkf45", "msadams", "bsimp", "msbdf", "rk4imp"};
const std::vector<double> tols = {1e-6, 1e-8, 1e-10, 1e-12};
// rk4imp below 1e-10 takes seconds per run: left out.
bool left_out(const std::string& method, double tol) { return method == "rk4imp" && tol < 1e-10; }

void check_budget(const kit::Options& o, const Params& p) {
    double per_period = 0;  // every run of the table, `repeats` times when short
    for (const std::string& method : methods)
        for (double tol : tols)
            if (!left_out(method, tol)) per_period += kit::seconds_per_period(method, tol);
    kit::require_budget(
        o, {double(p.periods) * p.repeats, per_period, "periods (every method and tolerance)", "--periods, --repeats"});
}

// Every method at every tolerance. Rows: method, tol, max rotation error, run time, rhs calls,
// Jacobian calls, energy drift, orthogonality.
std::vector<std::vector<double>> sweep(const Params& p, const rigid::Moments& m, const rigid::GrioliPrecession& g) {
    const double periods = double(p.periods);
    std::vector<std::vector<double>> table;
    for (std::size_t i = 0; i < methods.size(); ++i)
        for (double tol : tols) {
            if (left_out(methods[i], tol)) continue;
            rigid::PrecessionCheck c{};
            const rigid::OdeSettings s{.method = methods[i], .rel_tol = tol, .abs_tol = tol * std::min(1.0, g.alpha)};
            // Timing: the smallest of `repeats` runs, but a run of more than 0.05 s is timed once.
            double t = kit::min_time([&] { c = rigid::integrate_grioli(m, g, periods, 4, s); }, 1);
            if (t < 0.05 && p.repeats > 1)
                t = std::min(t,
                             kit::min_time([&] { c = rigid::integrate_grioli(m, g, periods, 4, s); }, p.repeats - 1));
            table.push_back({double(i), tol, c.max_rotation_error, t, double(c.stats.rhs_calls),
                             double(c.stats.jacobian_calls), c.max_energy_drift, c.orthogonality});
        }
    return table;
}

// Returns the linear stability of the precession, and whether it dominates the headline's error.
kit::Verdict report(kit::Scene& scene, const Params& p, const rigid::Moments& m, const rigid::GrioliPrecession& g,
                    const std::vector<std::vector<double>>& table) {
    double head_err = 0, head_time = 0, head_calls = 0;
    for (const auto& r : table)
        if (methods[std::size_t(r[0])] == "rk8pd" && r[1] == 1e-12)
            head_err = r[2], head_time = r[3], head_calls = r[4];
    scene.report.headline("max rotation error over the periods, rk8pd at tol 1e-12 (geodesic angle, radians)", head_err,
                          head_time);
    scene.report.add("periods", static_cast<long>(double(p.periods)));
    scene.report.add("alpha", g.alpha);
    std::string legend;
    for (std::size_t i = 0; i < methods.size(); ++i) legend += (i ? ", " : "") + std::to_string(i) + " " + methods[i];
    scene.report.note("method: " + legend);
    scene.report.table(
        "work_precision",
        {"method", "tol", "max_rot_error", "run_time_s", "rhs_calls", "jac_calls", "energy_drift", "orthogonality"},
        table);
    // Is the headline's error physics? The Floquet multipliers of the precession (Chapter 7).
    return kit::report_stability(scene.report, m, g.sense,
                                 {double(p.periods), head_err, 1e-12, kit::rk8pd_steps(long(head_calls))});
}

// The title says so when the instability dominates the errors it shows.
void draw(kit::Scene& scene, const Params& p, const std::vector<std::vector<double>>& table, const kit::Verdict& v) {
    kit::Figure fig(scene, "integrators_error_vs_time.svg", 820, 520);
    // A double-quoted gnuplot string, so that \n breaks the title's line.
    const std::string unstable =
        v.dominated ? fmt::format(
                          "\\nlinearly unstable precession: the errors are dominated by the instability, "
                          "|μ|^{{{}}} = {:.1e}",
                          p.periods, v.amplification)
                    : "";
    std::vector<kit::Fill> curves;
    for (std::size_t i = 0; i < methods.size(); ++i)
        curves.push_back({{"ls", std::to_string(i + 1)}, {"title", methods[i] + (i >= 4 ? " (implicit)" : "")}});
    fig.script(kit::gp::grioli_integrators, {{"periods", std::to_string(p.periods)},
                                             {"unstable", unstable},
                                             {"curves", kit::joined(kit::gp::method, curves)}});
    for (std::size_t i = 0; i < methods.size(); ++i) {
        std::vector<std::vector<double>> d;
        for (const auto& r : table)
            if (r[0] == double(i)) d.push_back({r[3], std::max(r[2], 1e-17)});
        fig.data(d);
    }
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("grioli_integrators",
                      "Chapter 5: rotation error against run time over 100 periods, for GSL's integrators");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        const rigid::Moments m = kit::grioli_moments(p.body.moments);
        const rigid::Sense sense = p.sense == "ccw" ? rigid::Sense::ccw : rigid::Sense::cw;
        const rigid::GrioliPrecession g = rigid::grioli_precession(m, p.body.f, sense);
        check_budget(o, p);
        const auto table = sweep(p, m, g);
        const kit::Verdict v = report(scene, p, m, g, table);
        draw(scene, p, table, v);
    });
}
