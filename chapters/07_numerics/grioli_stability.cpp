// Chapter 7 scene: how stable is the Grioli precession? [P] cites Markeev (2018) on its orbital
// stability in the critical case of fourth-order resonance; this scene measures what numerics can.
//
// Two independent measurements. (1) Linear: the monodromy matrix M of the variational equations
// dPhi/dt = D(t) Phi along the exact precession over one period (D the Jacobian of Euler's
// equations on the gaps; kit/stability.hpp, shared with the scenes of Chapters 5 and 6), and its
// eigenvalues, the Floquet multipliers, over a grid of body shapes; a
// multiplier off the unit circle, |mu| > 1, means a deviation that grows like |mu|^(t/P); on it,
// the precession is linearly (spectrally) stable, which does not decide its nonlinear stability.
// (2) Nonlinear, over a finite time: start the full equations from the precession's initial
// state changed by delta = 1e-8 ... 1e-4, follow the deviation for hundreds of periods, and
// measure its growth: a power of t, or an exponential, whose rate is read over a window of
// 100 periods once the transient has passed.
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "figure.hpp"
#include "grioli_stability.gp.hpp"
#include "motion.hpp"
#include "rigid/grioli.hpp"
#include "rigid/heavy_top.hpp"
#include "rigid/ode.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"
#include "stability.hpp"

using rigid::BodyState;
using rigid::MatX;
using rigid::Vec3;
using rigid::VecX;

namespace {

const double pi = std::numbers::pi;

// snippet: shape_coordinates
// A body shape as two numbers in (0, 1]: u = (B - A)/(C - A) runs from the symmetric limit B = A
// (u -> 0) to the other symmetric limit B = C (u -> 1); v = (C - A)/B measures flatness, with
// v = 1 the flat body A + B = C (the triangle inequality allows v <= 1). With A = 1:
//   B = 1 / (1 - u v),   C = 1 + v B.
rigid::Moments shape(double u, double v) {
    const double B = 1 / (1 - u * v);
    return rigid::moments_from_gaps(1.0, B - 1, v * B - (B - 1));
}
// end snippet

using kit::Floquet;
using kit::floquet;

// The monodromy matrix of the precession, from the kit (stability.hpp): the scenes of Chapters 5
// and 6 report the stability of the precessions they integrate with the same code.
MatX monodromy(const rigid::Moments& m, rigid::Sense sense, double tol) { return kit::grioli_monodromy(m, sense, tol); }

// The same monodromy by central differences of the nonlinear flow over one period: an
// independent check of the Jacobian and of the variational equations.
MatX monodromy_by_differences(const rigid::Moments& m, double tol, double eps) {
    const rigid::GrioliPrecession g = rigid::grioli_precession(m, 1.0, rigid::Sense::ccw);
    const rigid::HeavyTop top = rigid::grioli_top(m, g);
    const VecX y0 = rigid::pack(rigid::grioli_initial_state(g));
    const rigid::OdeRhs rhs = [&](double, const VecX& y) {
        return rigid::pack(rigid::euler_poisson_rhs(top, rigid::unpack(y)));
    };
    const auto flow = [&](const VecX& y) {
        VecX last;
        rigid::integrate_gsl(rhs, y, {0.0, 2 * pi / g.alpha}, [&](double, const VecX& x) { last = x; },
                             {.method = "rk8pd", .rel_tol = tol, .abs_tol = tol});
        return last;
    };
    MatX M(12, 12);
    for (int j = 0; j < 12; ++j) {
        VecX e = VecX::Zero(12);
        e(j) = eps;
        M.col(j) = (flow(y0 + e) - flow(y0 - e)) / (2 * eps);
    }
    return M;
}

std::string triple(const rigid::Moments& m) {
    std::ostringstream s;
    s.precision(4);
    s << "(" << m.A << ", " << m.B << ", " << m.C << ")";
    return s.str();
}

struct Body {
    std::string name;
    rigid::Moments m;
};

struct Growth {
    std::vector<double> periods, deviation;  // at whole periods
    double power = 0, rate = 0;              // fits of log d against log t, and against t
    double r2_power = 0, r2_rate = 0;
    bool exponential = false;
    // The growth rate per period over the last window of up to 100 periods (at most half the
    // time) that ends before d reaches 0.01: (ln d(end) - ln d(start)) / (its length in periods).
    double window_rate = 0, window_start = 0, window_periods = 0;
};

// Least squares y = a + b x; returns b and R^2.
std::pair<double, double> line_fit(const std::vector<double>& x, const std::vector<double>& y) {
    const double n = static_cast<double>(x.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
        sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i], syy += y[i] * y[i];
    const double cov = sxy - sx * sy / n, vx = sxx - sx * sx / n, vy = syy - sy * sy / n;
    return {cov / vx, vy > 0 ? cov * cov / (vx * vy) : 1.0};
}

// snippet: perturbation
// The full equations from the precession's initial state with Omega(0) changed by
// delta * alpha * (0.48, -0.6, 0.64), integrated by rk8pd; the deviation from the precession at
// every whole period kP, where the precession is back at R = 1, Omega = Omega(0):
//   d_k = angle(R(kP)) + |Omega(kP) - Omega(0)| / alpha.
BodyState perturbed_start(const rigid::GrioliPrecession& g, double delta) {
    BodyState start = rigid::grioli_initial_state(g);
    start.Omega += delta * g.alpha * Vec3(0.48, -0.6, 0.64);
    return start;
}

Growth perturbation(const rigid::Moments& m, double delta, int periods, double tol) {
    const rigid::GrioliPrecession g = rigid::grioli_precession(m, 1.0, rigid::Sense::ccw);
    const rigid::HeavyTop top = rigid::grioli_top(m, g);
    const BodyState start = perturbed_start(g, delta);
    const double P = 2 * pi / g.alpha;
    Growth gr;
    const rigid::OdeRhs rhs = [&](double, const VecX& y) {
        return rigid::pack(rigid::euler_poisson_rhs(top, rigid::unpack(y)));
    };
    rigid::integrate_gsl(rhs, rigid::pack(start), rigid::linspace(0, periods * P, periods),
                         [&](double t, const VecX& y) {
                             const BodyState s = rigid::unpack(y);
                             gr.periods.push_back(t / P);
                             gr.deviation.push_back(rigid::geodesic_angle(rigid::grioli_rotation(g, t), s.R) +
                                                    (s.Omega - rigid::grioli_angular_velocity(g, t)).norm() / g.alpha);
                         },
                         {.method = "rk8pd", .rel_tol = tol, .abs_tol = tol});
    // Fit where the deviation is past the start (t >= 5 P) and still small (d < 0.01), on the
    // later half of those points (past the transient).
    std::vector<double> lt, t, ld;
    std::size_t end = 0;
    while (end < gr.periods.size() && gr.deviation[end] < 0.01) ++end;
    for (std::size_t k = 0; k < end; ++k)
        if (gr.periods[k] >= 5 && gr.periods[k] >= gr.periods[end - 1] / 2)
            lt.push_back(std::log(gr.periods[k])), t.push_back(gr.periods[k]), ld.push_back(std::log(gr.deviation[k]));
    gr.power = gr.rate = std::numeric_limits<double>::quiet_NaN();
    if (lt.size() >= 4) {
        std::tie(gr.power, gr.r2_power) = line_fit(lt, ld);
        std::tie(gr.rate, gr.r2_rate) = line_fit(t, ld);
        // Linear growth d ~ c t has power 1 on this window; an exponential e^(lambda t) looks like a
        // power lambda t, larger the later the window. Faster than t^2 counts as exponential.
        gr.exponential = gr.power > 2;
    }
    // A fit over a stretch that still holds the transient (the linear drift of the phase, which
    // every perturbation starts) is not a growth rate: the rate over the last window before
    // d = 0.01 is, once it no longer changes as the window moves on (a small delta gives it room).
    gr.window_rate = gr.window_start = gr.window_periods = std::numeric_limits<double>::quiet_NaN();
    const std::size_t w = std::min<std::size_t>(100, end / 2);
    if (w >= 4) {
        gr.window_periods = gr.periods[end - 1] - gr.periods[end - 1 - w];
        gr.window_rate = (std::log(gr.deviation[end - 1]) - std::log(gr.deviation[end - 1 - w])) / gr.window_periods;
        gr.window_start = gr.periods[end - 1 - w];
    }
    return gr;
}
// end snippet

// The scene's parameters, bound to its options.
struct Params {
    long nu = 60, nv = 40, periods = 1500;
    double tol = 1e-11;
    std::string motion_file;  // --motion: the book's viewer data (motion.hpp)
};

void declare(kit::Options& opts, Params& p) {
    opts.integer("nu", &p.nu, "grid points along u = (B - A)/(C - A)", 4, 400)
        .integer("nv", &p.nv, "grid points along v = (C - A)/B", 4, 400)
        .integer("periods", &p.periods, "periods followed after a perturbation", 20, 100000)
        .real("tol", &p.tol, "rk8pd tolerance for the monodromy and the perturbed runs", kit::between(1e-14, 1e-6))
        .file("motion", &p.motion_file, kit::motion_help);
}

// The run time of one period of rk8pd on the Euler-Poisson equations (Chapter 4's right-hand
// side, which solves with J) at tolerance tol: c tol^(-1/8) s. CPU time on one core of the
// 2-core machine at load 6 to 12: c = 5.3e-6 to 6.5e-6 (tol = 1e-8 ... 1e-14); c = 8e-6.
double seconds_per_period(double tol) { return 8e-6 * std::pow(tol, -1.0 / 8); }

// The work, in periods of rk8pd at --tol: a monodromy matrix per grid point, three for the checks
// of the tongue and six for the perturbed bodies (kit::monodromy_seconds each); 18 perturbed runs
// over --periods, and at 1e-12 or tighter the settled runs of the two bodies that grow
// exponentially, (1, 3, 4) and the tongue, with the 24 one-period flows of the check by
// differences; the motion's two runs of 30 periods.
kit::Work work(const Params& p) {
    const double period = seconds_per_period(p.tol), tight = seconds_per_period(std::min(p.tol, 1e-12));
    const double seconds = kit::monodromy_seconds(p.tol) * double(p.nu * p.nv + 9) +
                           period * (18.0 * double(p.periods) + (p.motion_file.empty() ? 0 : 60)) +
                           tight * (2.0 * double(p.periods) + 24);
    return {seconds / period, period, "periods of rk8pd", "--nu, --nv, --periods, --tol"};
}

// (1) The map of the largest multiplier over the shapes, and its edges: the flat bodies (v = 1)
// and the two symmetric limits (the first and the last column, u -> 0 and u -> 1).
struct Map {
    std::vector<std::vector<double>> map;  // u, v, growth per period, rotation number
    double worst = -1, worst_u = 0, worst_v = 0;
    long unstable = 0;
    // The gap the threshold kit::unstable_growth sits in: the largest growth of a stable grid
    // point (the monodromy's own error) and the smallest of an unstable one.
    double largest_stable = 0, smallest_unstable = 1e300;
    double flat_unstable = 0, flat_u_min = 2, flat_u_max = -1, edge_growth_B_A = -1e300, edge_growth_B_C = -1e300;
    double time_s = 0;
};

Map stability_map(int nu, int nv, double tol) {
    Map M;
    auto& map = M.map;
    auto &worst = M.worst, &worst_u = M.worst_u, &worst_v = M.worst_v;
    auto& unstable = M.unstable;
    auto &flat_unstable = M.flat_unstable, &flat_u_min = M.flat_u_min, &flat_u_max = M.flat_u_max;
    auto &edge_growth_B_A = M.edge_growth_B_A, &edge_growth_B_C = M.edge_growth_B_C;
    M.time_s = kit::min_time(
        [&] {
            map.clear();
            for (int j = 0; j < nv; ++j) {
                const double v = (j + 1.0) / nv;  // up to the flat bodies, v = 1
                for (int i = 0; i < nu; ++i) {
                    const double u = (i + 0.5) / nu;
                    const Floquet f = floquet(monodromy(shape(u, v), rigid::Sense::ccw, tol));
                    map.push_back({u, v, f.growth, f.rotation});
                    if (f.growth > worst) worst = f.growth, worst_u = u, worst_v = v;
                }
                map.push_back({});  // a blank row between rows of the grid
            }
        },
        1);
    for (const auto& r : map) {
        if (r.empty()) continue;
        if (r[2] > kit::unstable_growth) ++unstable, M.smallest_unstable = std::min(M.smallest_unstable, r[2]);
        if (r[2] <= kit::unstable_growth) M.largest_stable = std::max(M.largest_stable, r[2]);
        if (r[1] == 1.0 && r[2] > kit::unstable_growth)
            ++flat_unstable, flat_u_min = std::min(flat_u_min, r[0]), flat_u_max = std::max(flat_u_max, r[0]);
        if (r[0] < 1.0 / nu) edge_growth_B_A = std::max(edge_growth_B_A, r[2]);
        if (r[0] > 1 - 1.0 / nu) edge_growth_B_C = std::max(edge_growth_B_C, r[2]);
    }

    return M;
}

// (2) Perturbations of a few bodies, from the symmetric limits to the flat one and the most
// unstable shape of the grid.
struct Perturbed {
    std::vector<Body> bodies;
    // body, delta, power, rate, r2 power, r2 rate, exponential, floquet, d(end)/delta, window rate
    // and start, rotation number
    std::vector<std::vector<double>> rows;
    std::vector<std::vector<double>> settled_rows;  // body, window rate, start, length, floquet, rotation number
    std::vector<std::vector<std::vector<double>>> curves;
    int exponential_bodies = 0, linear_bodies = 0;
    double time_s = 0;
};

Perturbed perturbed_bodies(const rigid::Moments& tongue, int periods, double tol) {
    Perturbed P;
    const auto& bodies = P.bodies;
    auto &rows = P.rows, &settled_rows = P.settled_rows;
    auto& curves = P.curves;
    auto &exponential_bodies = P.exponential_bodies, &linear_bodies = P.linear_bodies;
    P.bodies = {{"generic (1, 1.5, 2)", rigid::moments(1, 1.5, 2)},
                {"near B = A (1, 1.001, 2)", rigid::moments_from_gaps(1, 1e-3, 0.999)},
                {"near B = C (1, 1.999, 2)", rigid::moments_from_gaps(1, 0.999, 1e-3)},
                {"flat (1, 1.5, 2.5)", rigid::moments(1, 1.5, 2.5)},
                {"flat (1, 3, 4)", rigid::moments(1, 3, 4)},
                {"in the tongue " + triple(tongue), tongue}};
    P.time_s = kit::min_time(
        [&] {
            rows.clear(), curves.clear(), settled_rows.clear();
            exponential_bodies = linear_bodies = 0;
            for (std::size_t b = 0; b < bodies.size(); ++b) {
                const Floquet f = floquet(monodromy(bodies[b].m, rigid::Sense::ccw, tol));
                int exp_votes = 0;
                for (double delta : {1e-8, 1e-6, 1e-4}) {
                    const Growth gr = perturbation(bodies[b].m, delta, periods, tol);
                    rows.push_back({double(b), delta, gr.power, gr.rate, gr.r2_power, gr.r2_rate,
                                    gr.exponential ? 1.0 : 0.0, f.growth, gr.deviation.back() / delta, gr.window_rate,
                                    gr.window_start, f.rotation});
                    exp_votes += gr.exponential;
                    std::vector<std::vector<double>> c;
                    for (std::size_t k = 1; k < gr.periods.size(); ++k)
                        c.push_back({gr.periods[k], gr.deviation[k] / delta});
                    curves.push_back(c);
                }
                (exp_votes >= 2 ? exponential_bodies : linear_bodies)++;
                // An exponential growth's rate, read where it has settled: a smaller change (1e-10)
                // at a tighter tolerance leaves the transient behind before d reaches 0.01.
                Growth settled;
                settled.window_rate = settled.window_start = settled.window_periods =
                    std::numeric_limits<double>::quiet_NaN();
                if (exp_votes >= 2) settled = perturbation(bodies[b].m, 1e-10, periods, std::min(tol, 1e-12));
                settled_rows.push_back({double(b), settled.window_rate, settled.window_start, settled.window_periods,
                                        f.growth, f.rotation});
            }
        },
        1);

    return P;
}

// Checks of the linear analysis, on the most unstable shape of the map (the tongue): the
// multipliers by differences of the flow, and the clockwise sense (the time reversal of the
// counter-clockwise one).
struct Checks {
    Floquet f_var, f_fd, f_cw;
};

Checks check_tongue(const rigid::Moments& tongue, double tol) {
    return {floquet(monodromy(tongue, rigid::Sense::ccw, tol)), floquet(monodromy_by_differences(tongue, 1e-12, 1e-6)),
            floquet(monodromy(tongue, rigid::Sense::cw, tol))};
}

// The keys of each perturbed body: its fits at delta = 1e-6, its Floquet growth and rotation
// number, and the settled rate of the bodies that grow exponentially.
void report_bodies(kit::Report& r, const Perturbed& P) {
    const auto& bodies = P.bodies;
    const auto &rows = P.rows, &settled_rows = P.settled_rows;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const auto& row = rows[3 * b + 1];  // delta = 1e-6
        const std::string k = "body" + std::to_string(b) + "_";
        r.add(k + "name", bodies[b].name);
        r.add(k + "power", row[2], "fitted d ~ t^power, delta = 1e-6");
        r.add(k + "rate", row[3], "fitted d ~ exp(rate t/P) on the later half before d = 0.01, delta = 1e-6");
        r.add(k + "floquet_growth", row[7], "ln |mu| per period");
        r.add(k + "rotation_number", row[11], "arg(mu) / 2 pi of the multiplier pair farthest from 1");
        // Measured for the bodies that grow exponentially; null (not measured) for the others.
        r.add(k + "settled_rate", settled_rows[b][1],
              "growth per period over the last window before d = 0.01, delta = 1e-10");
        r.add(k + "settled_window_start", settled_rows[b][2]);
        r.add(k + "settled_window_periods", settled_rows[b][3]);
        r.add(k + "settled_over_floquet", settled_rows[b][1] / settled_rows[b][4]);
        r.add(k + "verdict", row[6] > 0.5 ? std::string("exponential") : std::string("linear"));
        r.add(k + "final_over_delta", row[8], "d(end) / delta, delta = 1e-6");
    }
}

void report(kit::Report& r, int nu, int nv, int periods, const Map& M, const rigid::Moments& tongue, const Checks& c,
            const Perturbed& P) {
    const auto& [f_var, f_fd, f_cw] = c;
    const auto& map = M.map;
    const auto& rows = P.rows;
    const double map_time = M.time_s, perturb_time = P.time_s;
    const double worst = M.worst, worst_u = M.worst_u, worst_v = M.worst_v, flat_unstable = M.flat_unstable;
    const double flat_u_min = M.flat_u_min, flat_u_max = M.flat_u_max;
    const double edge_growth_B_A = M.edge_growth_B_A, edge_growth_B_C = M.edge_growth_B_C;
    const long unstable = M.unstable;
    const int linear_bodies = P.linear_bodies, exponential_bodies = P.exponential_bodies;
    r.headline(
        "largest |ln|mu|| difference between the Floquet multipliers from the variational "
        "equations and from differences of the flow (body in the tongue)",
        std::abs(f_var.growth - f_fd.growth), map_time + perturb_time);
    r.add("grid_points", static_cast<long>(nu * nv));
    r.add("unstable_points", unstable, "growth per period > 1e-4");
    r.add("unstable_fraction", double(unstable) / (nu * nv));
    r.add("largest_stable_growth", M.largest_stable, "largest ln |mu| of a grid point at or below 1e-4: the noise");
    r.add("smallest_unstable_growth", unstable > 0 ? M.smallest_unstable : -1.0,
          "smallest ln |mu| of a grid point above 1e-4 (-1: none)");
    r.add("largest_growth_per_period", worst, "ln |mu| at the most unstable grid point");
    r.add("flat_unstable_fraction", flat_unstable / nu, "of the flat bodies v = 1 on the grid");
    r.add("flat_unstable_u_min", flat_unstable > 0 ? flat_u_min : -1.0);
    r.add("flat_unstable_u_max", flat_unstable > 0 ? flat_u_max : -1.0);
    r.add("edge_growth_B_near_A", edge_growth_B_A, "largest ln |mu| in the column next to B = A");
    r.add("edge_growth_B_near_C", edge_growth_B_C, "largest ln |mu| in the column next to B = C");
    r.add("largest_growth_u", worst_u);
    r.add("largest_growth_v", worst_v);
    r.add("tongue_A", tongue.A);
    r.add("tongue_B", tongue.B);
    r.add("tongue_C", tongue.C);
    r.add("tongue_multiplier_real", f_var.rotation > 0.49 ? -std::exp(f_var.growth) : std::exp(f_var.growth),
          "the largest multiplier (real and negative in the tongue)");
    r.add("tongue_growth_by_differences", f_fd.growth);
    r.add("tongue_growth_clockwise", f_cw.growth);
    r.add("map_time_s", map_time);
    r.add("perturbation_time_s", perturb_time);
    r.add("periods", static_cast<long>(periods));
    r.add("linear_bodies", static_cast<long>(linear_bodies));
    r.add("exponential_bodies", static_cast<long>(exponential_bodies));
    report_bodies(r, P);
    r.table("perturbations",
            {"body", "delta", "power", "rate_per_period", "r2_power", "r2_rate", "exponential",
             "floquet_growth_per_period", "final_over_delta", "window_rate", "window_start", "rotation_number"},
            rows);
    r.table(
        "map", {"u", "v", "growth_per_period", "rotation_number"},
        [&] {
            std::vector<std::vector<double>> m;
            for (const auto& row : map)
                if (!row.empty()) m.push_back(row);
            return m;
        }(),
        false);
}

void draw_map(kit::Scene& scene, const Map& M, const Perturbed& P) {
    const auto& map = M.map;
    const auto& bodies = P.bodies;
    kit::Figure fm(scene, "grioli_stability_map.svg", 900, 620);
    if (fm.enabled()) {
        fm.script(kit::gp::map);
        fm.data(map);
        std::vector<std::vector<double>> pts;
        for (const Body& b : bodies) pts.push_back({(b.m.B - b.m.A) / (b.m.C - b.m.A), (b.m.C - b.m.A) / b.m.B});
        fm.data(pts);
        std::vector<std::vector<double>> labels;
        for (std::size_t i = 0; i < pts.size(); ++i) labels.push_back({pts[i][0], pts[i][1], double(i + 1)});
        fm.data(labels);
        fm.finish();
    }
}

void draw_perturbations(kit::Scene& scene, const Perturbed& P) {
    const auto& bodies = P.bodies;
    const auto& rows = P.rows;
    const auto& curves = P.curves;
    kit::Figure fp(scene, "grioli_perturbations.svg", 1200, 520);
    if (fp.enabled()) {
        const char* colours[] = {"#000000", "#0072B2", "#56B4E9", "#009E73", "#E69F00", "#D55E00"};
        const std::size_t first = 3 * (bodies.size() - 1);  // three curves a body; the most unstable body goes right
        std::vector<kit::Fill> plot;
        for (std::size_t b = 0; b < first / 3; ++b)
            plot.push_back({{"colour", colours[b]}, {"title", kit::quoted(bodies[b].name)}});
        fp.script(kit::gp::perturbations, {{"curves", kit::joined(kit::gp::body, plot)}});
        for (std::size_t i = 0; i < first; ++i) fp.data(curves[i]);
        plot.clear();
        for (std::size_t i = first; i < curves.size(); ++i) {
            std::ostringstream delta;
            delta << rows[i][1];
            plot.push_back({{"delta", delta.str()},
                            {"dt", std::to_string(1 + (i - first))},
                            {"exponent", std::to_string(std::lround(std::log10(rows[i][1])))}});
        }
        std::ostringstream growth;
        growth << rows[first][7];
        fp.script(kit::gp::unstable, {{"curves", kit::joined(kit::gp::delta, plot)}, {"growth", growth.str()}});
        for (std::size_t i = first; i < curves.size(); ++i) fp.data(curves[i]);
        fp.finish();
    }
}

// ------------------------------------------------------------------ the book's motion viewer
// With --motion: the body in the tongue, started delta = 1e-4 off its precession (as the
// perturbed runs above) and integrated over 30 periods (left), beside Theorem 1's precession
// itself (right), k up. The deviation d of the perturbed runs, at whole periods, goes to the
// report and the caption; the same integration started on the precession (delta = 0) measures
// how much of what the reader sees is the integrator's own.
void write_tongue_motion(kit::Scene& scene, const std::string& file, const rigid::Moments& m, double tol) {
    if (file.empty()) return;
    const double delta = 1e-4;
    const int periods = 30, per_period = 16;
    const rigid::GrioliPrecession g = rigid::grioli_precession(m, 1.0, rigid::Sense::ccw);
    const rigid::HeavyTop top = rigid::grioli_top(m, g);
    const rigid::OdeRhs rhs = [&](double, const VecX& y) {
        return rigid::pack(rigid::euler_poisson_rhs(top, rigid::unpack(y)));
    };
    const double P = 2 * pi / g.alpha;
    const auto times = rigid::linspace(0, periods * P, periods * per_period);
    const rigid::Mat3 W = Eigen::Quaterniond::FromTwoVectors(g.k, Vec3::UnitZ()).toRotationMatrix();
    kit::Motion run, exact;
    std::vector<double> d;  // at whole periods
    double unperturbed = 0;
    for (const double dl : {delta, 0.0}) {
        std::size_t k = 0;
        rigid::integrate_gsl(rhs, rigid::pack(perturbed_start(g, dl)), times,
                             [&](double t, const VecX& y) {
                                 const BodyState s = rigid::unpack(y);
                                 const double dev = rigid::geodesic_angle(rigid::grioli_rotation(g, t), s.R) +
                                                    (s.Omega - rigid::grioli_angular_velocity(g, t)).norm() / g.alpha;
                                 if (dl == 0) {
                                     unperturbed = std::max(unperturbed, dev);
                                 } else {
                                     run.sample(t, W * s.R);
                                     exact.sample(t, W * rigid::grioli_rotation(g, t));
                                     if (k % per_period == 0) d.push_back(dev);
                                 }
                                 ++k;
                             },
                             {.method = "rk8pd", .rel_tol = tol, .abs_tol = tol});
    }
    for (kit::Motion* b : {&run, &exact}) {
        b->moments = {m.A, m.B, m.C};
        b->size = 0.55;
        b->centre_of_mass = g.z0;
        b->speed = P / 1.2;
    }
    run.fixed_point = Vec3(-1.7, 0, 0);
    exact.fixed_point = Vec3(1.7, 0, 0);
    run.label = fmt::format("left: started δ = {:g} off the precession (Ω(0) changed), integrated", delta);
    exact.label = "right: Theorem 1's precession R^b(αt) R^a(αt), exact";
    run.title =
        "a Grioli precession inside the instability tongue: the perturbed body (left) leaves the precession "
        "(right)";
    run.parameters = fmt::format(
        "A = {:.4g}, B = {:.4g}, C = {:.4g}, f = 1, counter-clockwise; {} periods 2π/α; "
        "deviation d = angle(R, R_exact) + |Ω − Ω_exact|/α: {:.1e} at t = 0, {:.1e} after 10 "
        "periods, {:.2g} after {}",
        m.A, m.B, m.C, periods, d.front(), d[10], d.back(), periods);
    run.error = unperturbed;
    run.error_measure = "the same integration started on the precession (δ = 0): its largest d over the 30 periods";
    scene.report.add("motion_delta", delta, "--motion: the change of Omega(0), as the perturbed runs");
    scene.report.add("motion_periods", static_cast<long>(periods));
    scene.report.add("motion_deviation_start", d.front(), "--motion: d at t = 0");
    scene.report.add("motion_deviation_10", d[10], "--motion: d after 10 periods");
    scene.report.add("motion_deviation_end", d.back(), "--motion: d after motion_periods periods");
    scene.report.add("motion_unperturbed", unperturbed, "--motion: largest d of the run with delta = 0");
    kit::write_motion(scene, file, std::vector<kit::Motion>{run, exact});
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("grioli_stability", "Chapter 7: the stability of the Grioli precession, linear and nonlinear");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&p](const kit::Options& o, kit::Scene& scene) {
        const int nu = static_cast<int>(p.nu), nv = static_cast<int>(p.nv), periods = static_cast<int>(p.periods);
        kit::require_budget(o, work(p));
        const Map map = stability_map(nu, nv, p.tol);
        const rigid::Moments tongue = shape(map.worst_u, map.worst_v);
        const Checks checks = check_tongue(tongue, p.tol);
        const Perturbed perturbed = perturbed_bodies(tongue, periods, p.tol);
        report(scene.report, nu, nv, periods, map, tongue, checks, perturbed);
        draw_map(scene, map, perturbed);
        draw_perturbations(scene, perturbed);
        write_tongue_motion(scene, p.motion_file, tongue, p.tol);
    });
}
