// Chapter 8 scene: the Grioli frequency is fixed by the body and f alone, with exactly two senses
// [P, (int.4), Theorem 1, Sect. 7]. (a) A map of alpha sqrt(C / f) over every admissible body
// (A/C, B/C), from Chapter 5's grioli_alpha, with bodies across the map integrated in both senses
// (Chapter 5's integrate_grioli) to show that each is a regular precession at that frequency.
// (b) The Chapter 5 body started with its angular velocity scaled by lambda: the motion stays on
// the regular precession R^b(lambda alpha t) R^a(lambda alpha t) only for lambda = +1 and -1.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "figure.hpp"
#include "grioli_frequency.gp.hpp"
#include "heavy_body.hpp"
#include "precession.hpp"
#include "rigid/grioli.hpp"
#include "rigid/heavy_top.hpp"
#include "rigid/ode.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

using rigid::Mat3;
using rigid::Vec3;
using rigid::VecX;
using std::numbers::pi;

namespace {

// A number as printf's %g writes it (the figures' titles and keys).
std::string gnum(double x) {
    char s[32];
    std::snprintf(s, sizeof s, "%g", x);
    return s;
}

// snippet: ch08_off_frequency
// The body of Theorem 1 started from R(0) = 1 with Omega(0) = lambda Omega_ccw(0): the largest
// geodesic angle between the integrated R(t) and the regular precession R^b(lambda alpha t)
// R^a(lambda alpha t) over `periods` periods 2 pi / alpha. Zero (to the integrator) only when
// the initial state is one of Theorem 1's two precessions: lambda = +1 or -1.
double off_frequency_deviation(const rigid::Moments& m, double f, double lambda, double periods) {
    const rigid::GrioliPrecession g = rigid::grioli_precession(m, f, rigid::Sense::ccw);
    const rigid::HeavyTop top = rigid::grioli_top(m, g);
    rigid::BodyState s0 = rigid::grioli_initial_state(g);
    s0.Omega *= lambda;
    const double T = periods * 2 * pi / g.alpha;
    double worst = 0;
    rigid::integrate_gsl(
        [&](double, const VecX& y) { return rigid::pack(rigid::euler_poisson_rhs(top, rigid::unpack(y))); },
        rigid::pack(s0), rigid::linspace(0, T, static_cast<int>(32 * periods)),
        [&](double t, const VecX& y) {
            const Mat3 exact = kit::precession_rotation({g.a, lambda * g.alpha, g.b, lambda * g.alpha}, t);
            worst = std::max(worst, rigid::geodesic_angle(rigid::unpack(y).R, exact));
        },
        {.method = "rk8pd", .rel_tol = 1e-12, .abs_tol = 1e-12 * std::min(1.0, g.alpha)});
    return worst;
}
// end snippet

struct Params {
    kit::HeavyBody body;
    int grid = 200;
    int repeats = 3;
};

void declare(kit::Options& opts, Params& p) {
    kit::heavy_body_options(opts, p.body)
        .integer("grid", &p.grid, "map resolution: grid points per side", 20, 2000)
        .integer("repeats", &p.repeats, "timing repetitions (the minimum is kept)", 1, 50);
}

// (a) The map of alpha sqrt(C / f) over the admissible bodies (A/C, B/C), NaN outside, a row
// break after each B/C; its smallest and largest value.
struct Map {
    std::vector<std::vector<double>> points;
    double lowest = 1e300, highest = 0;
};

Map alpha_map(int n) {
    Map map;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            const double a = double(i) / n, b = double(j) / n;
            double value = NAN;
            if (a > 0 && a < b && b < 1 && 1 - b <= a) {                      // the rules of rigid::moments
                value = rigid::grioli_alpha(rigid::moments(a, b, 1.0), 1.0);  // alpha sqrt(C / f)
                map.lowest = std::min(map.lowest, value), map.highest = std::max(map.highest, value);
            }
            map.points.push_back({a, b, value});
        }
        map.points.push_back({});
    }
    return map;
}

// Bodies across the map integrated in both senses over two periods. Rows: A/C, B/C,
// alpha sqrt(C/f), error ccw, error cw.
struct Checked {
    std::vector<std::vector<double>> rows;
    double worst = 0, time;
};

Checked check_bodies(const rigid::Moments& body, double f, int repeats) {
    Checked r;
    r.time = kit::min_time(
        [&] {
            r.rows.clear();
            r.worst = 0;
            for (double a : {0.1, 0.3, 0.5, 0.7, 0.9}) {
                const double lo = std::max(a, 1 - a);
                for (double u : {0.25, 0.5, 0.75}) {
                    const double b = lo + u * (1 - lo);
                    const rigid::Moments m = rigid::moments(a * body.C, b * body.C, body.C);
                    std::vector<double> row{a, b, rigid::grioli_alpha(m, f) * std::sqrt(body.C / f)};
                    for (rigid::Sense s : {rigid::Sense::ccw, rigid::Sense::cw}) {
                        const rigid::GrioliPrecession g = rigid::grioli_precession(m, f, s);
                        const rigid::PrecessionCheck c = rigid::integrate_grioli(
                            m, g, 2.0, 16,
                            {.method = "rk8pd", .rel_tol = 1e-12, .abs_tol = 1e-12 * std::min(1.0, g.alpha)});
                        row.push_back(c.max_rotation_error);
                        r.worst = std::max(r.worst, c.max_rotation_error);
                    }
                    r.rows.push_back(row);
                }
            }
        },
        repeats);
    if (!std::isfinite(r.worst)) throw kit::NumericalFailure("an integration produced a non-finite rotation");
    return r;
}

void report_map(kit::Scene& scene, const rigid::Moments& body, double f, const Map& map, const Checked& checked) {
    scene.report.headline(
        "max geodesic angle between the integrated R(t) and R^b(sigma alpha t) R^a(sigma alpha t), "
        "15 bodies across the map, both senses, two periods, rk8pd at tol 1e-12",
        checked.worst, checked.time);
    scene.report.add("alpha", rigid::grioli_alpha(body, f), "the Chapter 5 body, [P, (int.4)]");
    scene.report.add("alpha_map_min", map.lowest, "alpha sqrt(C/f) over the admissible bodies (grid)");
    scene.report.add("alpha_map_max", map.highest, "the same, largest on the grid (unbounded near A = 0, B = C)");
    scene.report.table("checked_bodies", {"A_over_C", "B_over_C", "alpha_sqrt_C_over_f", "error_ccw", "error_cw"},
                       checked.rows);
}

// (b) Scaling the initial angular velocity by lambda: the deviation over |lambda| in [0.3, 1.6]
// (rows lambda, deviation) and near lambda = 1 (rows lambda - 1, deviation).
struct Scaling {
    std::vector<std::vector<double>> sweep, near;
};

Scaling scaling(const rigid::Moments& body, double f) {
    Scaling s;
    for (int i = -160; i <= 160; i += 2) {
        const double lambda = i / 100.0;
        if (std::abs(lambda) < 0.3) continue;
        s.sweep.push_back({lambda, off_frequency_deviation(body, f, lambda, 2.0)});
    }
    for (int e = 1; e <= 8; ++e) {
        const double d = std::pow(10.0, -e);
        s.near.push_back({d, off_frequency_deviation(body, f, 1 + d, 2.0)});
    }
    return s;
}

void report_scaling(kit::Scene& scene, const Scaling& s) {
    double at_plus = 0, at_minus = 0, elsewhere = 1e300;
    for (const auto& r : s.sweep) {
        if (r[0] == 1)
            at_plus = r[1];
        else if (r[0] == -1)
            at_minus = r[1];
        else if (std::abs(std::abs(r[0]) - 1) >= 0.05)
            elsewhere = std::min(elsewhere, r[1]);
    }
    scene.report.add("deviation_lambda_plus_1", at_plus, "radians: the ccw precession of Theorem 1");
    scene.report.add("deviation_lambda_minus_1", at_minus, "radians: the cw precession");
    scene.report.add("deviation_elsewhere_min", elsewhere,
                     "radians: smallest over |lambda| >= 0.3, ||lambda| - 1| >= 0.05");
    scene.report.add("deviation_per_lambda_error", s.near[4][1] / s.near[4][0],
                     "deviation / (lambda - 1) at lambda - 1 = 1e-5 (two periods)");
    scene.report.table("near_lambda_1", {"lambda_minus_1", "deviation"}, s.near);
}

void draw_map(kit::Scene& scene, const rigid::Moments& body, const Map& map, const Checked& checked) {
    kit::Figure fig(scene, "grioli_alpha_map.svg", 760, 520);
    if (!fig.enabled()) return;
    fig.script(kit::gp::alpha_map);
    std::vector<std::vector<double>> pts;
    for (const auto& r : checked.rows) pts.push_back({r[0], r[1]});
    fig.data(map.points)
        .data({{0, 1}, {0.5, 0.5}, {1, 1}, {0, 1}})
        .data(pts)
        .data({{body.A / body.C, body.B / body.C}});
    fig.finish();
}

void draw_senses(kit::Scene& scene, const rigid::Moments& body, const Scaling& s) {
    kit::Figure fl(scene, "grioli_two_senses.svg", 820, 480);
    if (!fl.enabled()) return;
    fl.script(kit::gp::two_senses, {{"A", gnum(body.A)}, {"B", gnum(body.B)}, {"C", gnum(body.C)}});
    std::vector<std::vector<double>> both;  // the two branches, with a break (an empty row)
    for (const auto& r : s.sweep)
        if (r[0] < 0) both.push_back({r[0], std::max(r[1], 1e-16)});
    both.push_back({});
    for (const auto& r : s.sweep)
        if (r[0] > 0) both.push_back({r[0], std::max(r[1], 1e-16)});
    fl.data(both);
    fl.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("grioli_frequency", "Chapter 8: the Grioli frequency, fixed by the body and f, with two senses");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        const rigid::Moments body = kit::grioli_moments(p.body.moments);
        const double f = p.body.f;
        // The work: the map (grid^2 closed forms) and 15 bodies x 2 senses x 2 periods, `repeats` times.
        kit::require_budget(
            o, {double(p.grid) * p.grid * 2e-7 + 60.0 * double(p.repeats) * 3e-4, 1, "seconds", "--grid, --repeats"});
        const Map map = alpha_map(p.grid);
        const Checked checked = check_bodies(body, f, p.repeats);
        report_map(scene, body, f, map, checked);
        const Scaling s = scaling(body, f);
        report_scaling(scene, s);
        draw_map(scene, body, map, checked);
        draw_senses(scene, body, s);
    });
}
