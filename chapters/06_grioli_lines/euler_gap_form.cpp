// Chapter 6 scene: a body hung far out on a Grioli line, integrated with Euler's equations in
// the naive form and on the moment gaps; error and run time against the distance L.
//
// For several bodies at G (one generic, two nearly symmetric, one more) and L from 1e-6 to 1e8
// body sizes, this is grioli_body's step 4 twice: rk8pd on the Euler-Poisson equations with
//   naive: J Omega_dot = (J Omega) x Omega + f [R^T k, z(0)],  J = diag(A, B, C) (Chapter 4);
//   gaps:  A Omega_dot_A = (B - C) Omega_B Omega_C + ..., the gaps from Chapter 6's closed forms,
// each against Theorem 1's R^b(alpha t) R^a(alpha t) over the periods. Next to them, what the
// chapter's explanation rests on, measured at each L:
//   * C - B from the closed form and from C and B rounded to double, and eps B / A;
//   * the largest |eigenvalue| of the Jacobian of the equations along the motion, over alpha
//     (were the body stiff, this would grow with B / A);
//   * the growth of a change of Omega(0) by 1e-10 over the periods, per period: where it is
//     exponential the moments at O lie in an instability tongue of the Grioli precession
//     (Chapter 7), and no arithmetic can follow Theorem 1 for long.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "common.hpp"
#include "euler_gap_form.gp.hpp"
#include "figure.hpp"
#include "rigid/grioli.hpp"
#include "rigid/heavy_top.hpp"
#include "rigid/ode.hpp"
#include "rigid/rotation.hpp"
#include "stability.hpp"

using rigid::Mat3;
using rigid::Vec3;
using rigid::VecX;

namespace {

const double nan_ = std::numeric_limits<double>::quiet_NaN();
const double eps = std::numeric_limits<double>::epsilon();

// The body at O as grioli_body builds it: moments with gaps, Theorem 1's precession, and the
// direction of G in the principal frame at O (from Chapter 6's frame).
struct Hung {
    rigid::ShiftedMoments sm;
    rigid::Moments m;
    rigid::GrioliPrecession P;
    Vec3 z0;
};

Hung hang(const rigid::BodyAtG& body, double L) {
    const rigid::GrioliSuspension s = rigid::grioli_suspension(body, L, 1);
    Hung h{s.frame.moments, {}, {}, {}};
    h.m = rigid::moments_from_gaps(h.sm.A, h.sm.B_minus_A, h.sm.C_minus_B);
    h.P = rigid::grioli_precession(h.m, 9.81 * L * body.mu, rigid::Sense::ccw);
    const double dA = s.z0.x() * h.P.z0.x() >= 0 ? 1 : -1, dC = s.z0.z() * h.P.z0.z() >= 0 ? 1 : -1;
    const Mat3 Q = s.frame.R * Vec3(dA, dA * dC, dC).asDiagonal();
    h.z0 = (Q.transpose() * -s.z).normalized();
    return h;
}

struct Run {
    double error = nan_, time_s = nan_;
    long evaluations = 0;
    bool gave_up = false;
    std::vector<rigid::BodyState> at_periods;  // the state after each whole period
};

// rk8pd over `periods` periods, 16 outputs a period; `repeats` timed runs (the minimum is kept).
// The naive form far out needs millions of steps: max_steps caps each output interval.
Run integrate(const Hung& h, bool gaps, int periods, double tol, int repeats, long max_steps, const Vec3& dOmega) {
    const rigid::HeavyTop naive = rigid::heavy_top(Vec3(h.sm.A, h.sm.B, h.sm.C).asDiagonal(), h.P.f, h.P.k, h.z0);
    const rigid::OdeRhs rhs = [&](double, const VecX& y) {
        const rigid::BodyState x = rigid::unpack(y);
        return rigid::pack(gaps ? rigid::euler_poisson_rhs_gaps(h.m, h.P.f, h.P.k, h.z0, x)
                                : rigid::euler_poisson_rhs(naive, x));
    };
    const double period = 2 * std::numbers::pi / h.P.alpha;
    const auto times = rigid::linspace(0, periods * period, 16 * periods);
    rigid::BodyState s0 = rigid::grioli_initial_state(h.P);
    s0.Omega += dOmega;
    Run r;
    try {
        r.time_s = kit::min_time(
            [&] {
                r.error = 0;
                r.at_periods.clear();
                int k = 0;
                r.evaluations =
                    rigid::integrate_gsl(rhs, rigid::pack(s0), times,
                                         [&](double t, const VecX& y) {
                                             const rigid::BodyState x = rigid::unpack(y);
                                             r.error = std::max(
                                                 r.error, rigid::geodesic_angle(x.R, rigid::grioli_rotation(h.P, t)));
                                             if (k++ % 16 == 0) r.at_periods.push_back(x);
                                         },
                                         {.method = "rk8pd",
                                          .rel_tol = tol,
                                          .abs_tol = tol * std::min(1.0, h.P.alpha),
                                          .max_steps = max_steps})
                        .rhs_calls;
            },
            repeats);
    } catch (const std::runtime_error&) {
        r = Run{};
        r.gave_up = true;
    }
    return r;
}

// The largest |eigenvalue| of the Jacobian of the gap form along the exact motion (8 instants of
// one period), over alpha. The Jacobian is the kit's, written out from the gap form (the one of
// Chapter 4, built from J, would cancel exactly as the naive equations do).
double jacobian_radius(const Hung& h) {
    double radius = 0;
    for (int j = 0; j < 8; ++j) {
        const double t = j * 2 * std::numbers::pi / h.P.alpha / 8;
        const rigid::BodyState y{rigid::grioli_angular_velocity(h.P, t), rigid::grioli_rotation(h.P, t)};
        const kit::Mat12 D = kit::gap_jacobian(h.m, h.P.f, h.P.k, h.z0, y);
        radius = std::max(radius, Eigen::EigenSolver<kit::Mat12>(D, false).eigenvalues().cwiseAbs().maxCoeff());
    }
    return radius / h.P.alpha;
}

// The growth of a change of Omega(0) per period, fitted over the second half of the run:
// ln(d(T) / d(T/2)) / (periods / 2). Linear growth gives 2 ln 2 / periods; an instability
// tongue gives its Floquet rate ln |mu|.
double growth_rate(const Run& a, const Run& b) {
    if (a.gave_up || b.gave_up || a.at_periods.size() < 4 || a.at_periods.size() != b.at_periods.size()) return nan_;
    auto d = [&](std::size_t i) {
        return std::max((a.at_periods[i].Omega - b.at_periods[i].Omega).norm() / a.at_periods[0].Omega.norm(),
                        (a.at_periods[i].R - b.at_periods[i].R).norm());
    };
    const std::size_t n = a.at_periods.size() - 1;
    return std::log(d(n) / d(n / 2)) / double(n - n / 2);
}

struct Body {
    std::string name;
    rigid::BodyAtG g;
};

struct Params {
    double step = 0.25;
    int periods = 100;
    double tol = 1e-13;
    int repeats = 2;
};

void declare(kit::Options& opts, Params& p) {
    opts.real("step", &p.step, "spacing of the distances L, in decades (from 1e-6 to 1e8 body sizes)",
              kit::between(0.05, 2))
        .integer("periods", &p.periods, "periods 2 pi / alpha per run", 4, 1000)
        .real("tol", &p.tol, "rk8pd relative tolerance", kit::between(1e-14, 1e-8))
        .integer("repeats", &p.repeats, "timing repetitions of each form (the minimum is kept)", 1, 20);
}

const std::vector<Body> bodies = {{"(1, 2, 2.5)", {1, 2, 2.5, 1}},
                                  {"(1, 1 + 1e-6, 2)", {1, 1 + 1e-6, 2, 1}},
                                  {"(1, 1.5, 1.5 + 1e-6)", {1, 1.5, 1.5 + 1e-6, 1}},
                                  {"(2, 3, 4)", {2, 3, 4, 1}}};
// The naive form gets at most 200 steps between two outputs (the gap form needs about 5).
constexpr long naive_cap = 200;

std::vector<double> decades(const Params& p) {
    std::vector<double> out;
    for (int i = 0; - 6 + i * p.step <= 8 + 1e-9; ++i) out.push_back(-6 + i * p.step);
    return out;
}

// The work per period of a point: 2 repeats + 1 runs of rk8pd (the gap form `repeats` times, its
// twin once, the naive form `repeats` times; a run of either form near the body costs about the
// same), plus what the naive form spends far out chasing round-off up to its cap of naive_cap
// steps an output, plus the point's monodromy matrix spread over its periods. Fitted to the CPU
// time of the default sweep (228 points, 100 periods, repeats 2) on one core of the 2-core
// machine at load 10: 12.6 s at tol 1e-8 and 28.7 s at 1e-14, so a run 3.1e-6 tol^(-1/8) s a
// period and the capped naive runs 2e-4 s a period each; raised by 30%.
void check_budget(const kit::Options& o, const Params& p) {
    const double runs = 2.0 * p.repeats + 1;
    const double per_period = 1.3 * (runs * 3.1e-6 * std::pow(p.tol, -1.0 / 8) + p.repeats * 2e-4) +
                              kit::monodromy_seconds(kit::monodromy_tol) / p.periods;
    kit::require_budget(o, {double(bodies.size() * decades(p).size()) * p.periods, per_period, "periods",
                            "--step, --periods, --repeats, --tol"});
}

// One body hung at 10^x body sizes: the gap form, a twin with Omega(0) changed by 1e-10 alpha,
// and the naive form. The row of the table (see `columns`).
std::vector<double> point(const Params& p, std::size_t b, double x) {
    const Hung h = hang(bodies[b].g, std::pow(10.0, x) * ch6::size_of(bodies[b].g));
    const Run gap = integrate(h, true, p.periods, p.tol, p.repeats, 0, Vec3::Zero());
    const Run twin = integrate(h, true, p.periods, p.tol, 1, 0, 1e-10 * h.P.alpha * Vec3(0.48, -0.6, 0.64));
    const Run naive = integrate(h, false, p.periods, p.tol, p.repeats, naive_cap, Vec3::Zero());
    const double rate = growth_rate(gap, twin), radius = jacobian_radius(h);
    // Exponential growth: faster than ln 2 per quarter of the run.
    const bool stable = !(rate > 4 * std::log(2.0) / p.periods);
    // The same from the linearisation: the Floquet multipliers, and whether they made the error.
    const kit::RunStability st = kit::run_stability(
        h.m, rigid::Sense::ccw, {double(p.periods), gap.error, p.tol, kit::rk8pd_steps(gap.evaluations)});
    return {double(b),
            x,
            h.sm.C_minus_B,
            h.sm.C - h.sm.B,
            eps * h.sm.B / h.sm.A,
            radius,
            gap.error,
            gap.time_s,
            double(gap.evaluations),
            naive.error,
            naive.time_s,
            double(naive.evaluations),
            rate,
            stable ? 1.0 : 0.0,
            st.stability.multiplier(),
            st.stability.floquet.growth,
            st.verdict.dominated ? 1.0 : 0.0};
}

const std::vector<std::string> columns = {"body",
                                          "log10_L_sizes",
                                          "C_minus_B",
                                          "C_minus_B_double",
                                          "eps_B_over_A",
                                          "jacobian_radius_over_alpha",
                                          "gap_error",
                                          "gap_time_s",
                                          "gap_evaluations",
                                          "naive_error",
                                          "naive_time_s",
                                          "naive_evaluations",
                                          "growth_per_period",
                                          "stable",
                                          "floquet_mu",
                                          "floquet_growth",
                                          "dominated"};

// What the table says: the worst stable error, the unstable points, the slowest run...
struct Summary {
    double worst_stable = 0, slowest = 0, worst_radius = 0, naive_first_fail = nan_;
    long unstable = 0;
    // The Floquet multipliers against the measured growth: points unstable by the multipliers,
    // those whose error the instability dominates, the points where the two verdicts differ, and
    // the measured growth over ln |mu| where both say unstable (its extremes).
    long floquet_unstable = 0, dominated = 0, disagreements = 0;
    double growth_ratio_min = nan_, growth_ratio_max = nan_;
};

Summary summarise(const std::vector<std::vector<double>>& rows) {
    Summary s;
    for (const auto& r : rows) {
        const bool stable = r[13] > 0;
        if (stable)
            s.worst_stable = std::max(s.worst_stable, r[6]);
        else
            ++s.unstable;
        s.slowest = std::max(s.slowest, r[7]);
        s.worst_radius = std::max(s.worst_radius, r[5]);
        const bool naive_ok = !std::isnan(r[9]) && r[9] <= 1e-9;  // NaN: the naive form gave up
        if (r[0] == 0 && stable && !naive_ok && std::isnan(s.naive_first_fail)) s.naive_first_fail = r[1];
        const bool floquet_unstable = r[15] > kit::unstable_growth;
        s.floquet_unstable += floquet_unstable;
        s.dominated += r[16] > 0;
        s.disagreements += floquet_unstable == stable;
        if (floquet_unstable && !stable) {
            const double ratio = r[12] / r[15];
            s.growth_ratio_min = std::isnan(s.growth_ratio_min) ? ratio : std::min(s.growth_ratio_min, ratio);
            s.growth_ratio_max = std::isnan(s.growth_ratio_max) ? ratio : std::max(s.growth_ratio_max, ratio);
        }
    }
    return s;
}

void report(kit::Scene& scene, const Params& p, const std::vector<std::vector<double>>& rows, const Summary& s) {
    if (!std::isfinite(s.worst_stable)) throw kit::NumericalFailure("the gap form produced a non-finite rotation");
    scene.report.headline(
        "largest error of the gap form, every body and distance where the precession is not "
        "exponentially unstable (geodesic angle to Theorem 1, rad)",
        s.worst_stable, s.slowest);
    scene.report.add("periods", static_cast<long>(p.periods));
    scene.report.add("tol", p.tol);
    scene.report.add("points", static_cast<long>(rows.size()), "bodies x distances");
    scene.report.add("unstable_points", s.unstable, "in an instability tongue of Chapter 7: exponential growth");
    scene.report.add("floquet_unstable_points", s.floquet_unstable,
                     "linearly unstable by the Floquet multipliers (ln |mu| > 1e-4 per period)");
    scene.report.add("dominated_points", s.dominated, "points whose gap-form error the instability dominates");
    scene.report.add("stability_disagreements", s.disagreements,
                     "points where the measured growth and the Floquet multipliers disagree on stability");
    scene.report.add("growth_over_floquet_min", s.growth_ratio_min,
                     "measured growth per period over ln |mu|, points unstable by both: the smallest");
    scene.report.add("growth_over_floquet_max", s.growth_ratio_max,
                     "the largest (below 1 where the deviation has grown to order 1 before the run ends)");
    scene.report.add("slowest_gap_run_s", s.slowest, "the longest run time of the gap form over every point");
    scene.report.add("largest_jacobian_radius_over_alpha", s.worst_radius,
                     "max over every point of max |eigenvalue| / alpha: sqrt(2) = 1.414 for every L");
    scene.report.add("naive_first_failure_decade", s.naive_first_fail,
                     "body (1, 2, 2.5): log10 of the first L (body sizes) where the naive form misses 1e-9 or "
                     "gives up (stable points)");
    // Rows of the default body at chosen distances, for the chapter's table.
    std::vector<std::vector<double>> chosen;
    for (const auto& r : rows)
        if (r[0] == 0 && std::abs(r[1] - std::round(r[1])) < 1e-9 && int(std::round(r[1])) % 2 == 0)
            chosen.push_back(r);
    scene.report.table("default_body", columns, chosen);
    scene.report.table("sweep", columns, rows, false);
    std::string legend;
    for (std::size_t b = 0; b < bodies.size(); ++b)
        legend += (b ? ", " : "") + std::to_string(b) + " = " + bodies[b].name;
    scene.report.note("bodies (A_g, B_g, C_g), mu = 1: " + legend + "; naive_error NaN: gave up after " +
                      std::to_string(naive_cap) + " steps between two outputs");
    // The chapter's promise, for the tolerances it is made at (a looser one misses it by design).
    if (p.tol <= 1e-12 && !(s.worst_stable <= 1e-9)) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.2g", s.worst_stable);
        throw kit::CheckFailed(std::string("the gap form misses Theorem 1 by ") + buf +
                               " rad where the precession is stable; at tolerance <= 1e-12 the chapter promises 1e-9");
    }
}

// One panel: the error (panel 0) or the run time (panel 1) of both forms, every body.
// The error panel's title says what the × points are: when the instability dominates the error
// at every one of them, it says so.
void draw_panel(kit::Figure& fig, const std::vector<std::vector<double>>& rows, const Summary& s, int panel) {
    const std::string dominated =
        s.unstable > 0 && s.dominated == s.unstable ? "\\nat ×, the error is dominated by the instability" : "";
    std::vector<kit::Fill> curves;
    std::vector<std::vector<std::vector<double>>> blocks;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        std::vector<std::vector<double>> g, n, u;
        for (const auto& r : rows) {
            if (r[0] != double(b)) continue;
            const double gv = panel == 0 ? r[6] : r[7];
            (r[13] > 0 ? g : u).push_back({r[1], std::max(gv, 1e-12)});
            const double nv = panel == 0 ? (std::isnan(r[9]) ? 30.0 : r[9]) : (std::isnan(r[10]) ? nan_ : r[10]);
            if (!std::isnan(nv)) n.push_back({r[1], std::max(nv, 1e-12)});
        }
        curves.push_back({{"ls", std::to_string(b + 1)},
                          {"gaps", kit::quoted("gaps, " + bodies[b].name)},
                          {"naive", kit::quoted("naive, " + bodies[b].name)}});
        blocks.push_back(g), blocks.push_back(n),
            blocks.push_back(u.empty() ? std::vector<std::vector<double>>{{nan_, nan_}} : u);
    }
    if (panel == 0)
        fig.script(kit::gp::error, {{"dominated", dominated}, {"curves", kit::joined(kit::gp::body, curves)}});
    else
        fig.script(kit::gp::time, {{"curves", kit::joined(kit::gp::body, curves)}});
    for (const auto& bl : blocks) fig.data(bl);
}

void draw(kit::Scene& scene, const Params& p, const std::vector<std::vector<double>>& rows, const Summary& s) {
    kit::Figure fig(scene, "euler_gap_form.svg", 1100, 480);
    if (!fig.enabled()) return;
    fig.script(kit::gp::euler_gap_form, {{"periods", std::to_string(p.periods)}});
    draw_panel(fig, rows, s, 0);
    draw_panel(fig, rows, s, 1);
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("euler_gap_form",
                      "Chapter 6: Euler's equations naive and on the moment gaps, far out on a Grioli line");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        check_budget(o, p);
        std::vector<std::vector<double>> rows;  // one per body and distance
        for (std::size_t b = 0; b < bodies.size(); ++b)
            for (double x : decades(p)) rows.push_back(point(p, b, x));
        const Summary s = summarise(rows);
        report(scene, p, rows, s);
        draw(scene, p, rows, s);
    });
}
