// Chapter 1 scene: the body angular velocity Omega recovered from R(t) alone, by finite
// differences, against the exact Omega = alpha a of a pure rotation [P, (1.1.1), (1.2)].
//
// Sweeps the step h for five difference formulas (forward, order 1; central, orders 2, 4, 6,
// 8). The error first falls like h^p (truncation), then rises like eps/h (round-off in
// R(t +- h)): the V of every numerical derivative. Then error against run time: wider
// stencils cost more evaluations of R and reach lower floors, until eps stops them all.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "figure.hpp"
#include "omega_finite_difference.gp.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

using rigid::Mat3;
using rigid::Vec3;

namespace {

// snippet: stencils
// A difference formula: R'(t) ~ sum_j w_j R(t + j h) / h.
struct Stencil {
    std::string name;
    int order;
    std::vector<int> offsets;
    std::vector<double> weights;
};

const std::vector<Stencil> stencils = {
    {"forward, order 1", 1, {0, 1}, {-1, 1}},
    {"central, order 2", 2, {-1, 1}, {-0.5, 0.5}},
    {"central, order 4", 4, {-2, -1, 1, 2}, {1. / 12, -2. / 3, 2. / 3, -1. / 12}},
    {"central, order 6", 6, {-3, -2, -1, 1, 2, 3}, {-1. / 60, 3. / 20, -3. / 4, 3. / 4, -3. / 20, 1. / 60}},
    {"central, order 8",
     8,
     {-4, -3, -2, -1, 1, 2, 3, 4},
     {1. / 280, -4. / 105, 1. / 5, -4. / 5, 4. / 5, -1. / 5, 4. / 105, -1. / 280}},
};

// Omega at t from R(t) and the difference quotient of R: only rotation_about is trusted.
Vec3 omega_fd(const Vec3& a, double alpha, double t, double h, const Stencil& s) {
    Mat3 R_dot = Mat3::Zero();
    for (std::size_t j = 0; j < s.offsets.size(); ++j)
        R_dot += s.weights[j] * rigid::rotation_about(a, alpha * (t + s.offsets[j] * h));
    return rigid::body_angular_velocity(rigid::rotation_about(a, alpha * t), R_dot / h);
}
// end snippet

struct Params {
    Vec3 axis = Vec3(1, 2, 2);
    double alpha = 1.3, t = 0.7;
    double hmin = 1e-12, hmax = 0.3;
    int points = 45;
};

void declare(kit::Options& opts, Params& p) {
    opts.vector("axis", &p.axis, "rotation axis a (normalised)", kit::nonzero_vector(-1e6, 1e6))
        .real("alpha", &p.alpha, "rotation frequency alpha", kit::between(1e-6, 1e6))
        .real("t", &p.t, "the instant at which Omega is recovered (|alpha t| <= 10)", kit::between(-1e6, 1e6))
        .real("hmin", &p.hmin, "smallest step of the sweep", kit::between(1e-16, 1e3))
        .real("hmax", &p.hmax, "largest step of the sweep", kit::between(1e-16, 1e3))
        .integer("points", &p.points, "steps in the sweep (log-spaced)", 5, 400);
}

void check(const kit::Options& o, const Params& p) {
    if (!(p.hmin < p.hmax)) throw kit::BadInput("--hmin must be smaller than --hmax");
    // The stencil evaluates R at alpha (t + j h): far from t = 0 the sum t + j h keeps fewer
    // of the digits of h (its round-off is eps |t| / h, not eps / (alpha h)), and the
    // floors predicted below would be wrong.
    if (!(std::abs(p.alpha * p.t) <= 10))
        throw kit::BadInput("--t, --alpha: |alpha t| = " + std::to_string(std::abs(p.alpha * p.t)) +
                            "; it must be at most 10 (further out t + h loses the digits of h)");
    kit::require_budget(o, {double(p.points) * 30 + 5 * 2000 * 30, 2e-7, "rotations R(t)", "--points"});
}

// The sweep: relative error |Omega_fd - alpha a| / alpha for every stencil and step, and the
// run time of one recovery at each stencil's best step.
struct Sweep {
    Vec3 a;
    std::vector<std::vector<double>> rows;  // h, then the error of each stencil
    std::vector<double> best_err, best_h, time_per;
};

Sweep compute(const Params& p) {
    Sweep sw{p.axis.normalized(),
             {},
             std::vector<double>(stencils.size(), 1e300),
             std::vector<double>(stencils.size(), 0),
             std::vector<double>(stencils.size())};
    const Vec3 exact = p.alpha * sw.a;  // [P, (1.2)]
    for (int k = 0; k < p.points; ++k) {
        const double h = p.hmin * std::pow(p.hmax / p.hmin, double(k) / (p.points - 1));
        std::vector<double> row{h};
        for (std::size_t s = 0; s < stencils.size(); ++s) {
            const double err = (omega_fd(sw.a, p.alpha, p.t, h, stencils[s]) - exact).norm() / p.alpha;
            row.push_back(err);
            if (err < sw.best_err[s]) sw.best_err[s] = err, sw.best_h[s] = h;
        }
        sw.rows.push_back(row);
    }
    // Run time of one recovery of Omega at each stencil's best step (min of 5 batches).
    const int batch = 2000;
    for (std::size_t s = 0; s < stencils.size(); ++s) {
        sw.time_per[s] = kit::min_time([&] {
                             Vec3 sum = Vec3::Zero();
                             for (int n = 0; n < batch; ++n)
                                 sum += omega_fd(sw.a, p.alpha, p.t + 1e-9 * n, sw.best_h[s], stencils[s]);
                             kit::keep(sum);
                         }) /
                         batch;
    }
    return sw;
}

// What one more evaluation of R costs: the least-squares slope of the run time against the
// number of evaluations, over the central formulas (2, 4, 6, 8 evaluations).
double time_per_evaluation(const std::vector<double>& time_per) {
    double n_mean = 0, t_mean = 0, cov = 0, var = 0;
    for (std::size_t s = 1; s < stencils.size(); ++s)
        n_mean += double(stencils[s].offsets.size()), t_mean += time_per[s];
    n_mean /= double(stencils.size() - 1), t_mean /= double(stencils.size() - 1);
    for (std::size_t s = 1; s < stencils.size(); ++s) {
        const double dn = double(stencils[s].offsets.size()) - n_mean;
        cov += dn * (time_per[s] - t_mean), var += dn * dn;
    }
    return cov / var;
}

// Theory: truncation ~ (alpha h)^p, round-off ~ eps / (alpha h); balanced at
// alpha h ~ eps^(1/(p+1)), which leaves a floor ~ eps^(p/(p+1)).
void report(kit::Scene& scene, const Params& p, const Sweep& sw) {
    const double eps = std::numeric_limits<double>::epsilon();
    const std::size_t c2 = 1;  // the classic central difference carries the headline
    scene.report.headline("min over h of |Omega_fd - alpha a| / alpha, central difference of order 2", sw.best_err[c2],
                          sw.time_per[c2]);
    scene.report.add("axis", sw.a);
    scene.report.add("alpha", p.alpha);
    std::vector<std::vector<double>> summary;
    for (std::size_t s = 0; s < stencils.size(); ++s) {
        const int order = stencils[s].order;
        summary.push_back({double(order), double(stencils[s].offsets.size()), sw.best_h[s], sw.best_err[s],
                           std::pow(eps, 1.0 / (order + 1)) / p.alpha, std::pow(eps, double(order) / (order + 1)),
                           sw.time_per[s]});
    }
    scene.report.table("by_stencil",
                       {"order", "evaluations", "best_h", "best_error", "predicted_h", "predicted_floor", "time_s"},
                       summary);
    scene.report.add("time_per_evaluation_s", time_per_evaluation(sw.time_per),
                     "run time of one more evaluation of R in a stencil");
    scene.report.table("sweep", {"h", "order1", "order2", "order4", "order6", "order8"}, sw.rows, false);
    scene.report.note("central order 2: best step " + std::to_string(sw.best_h[c2]) +
                      ", theory eps^(1/3)/alpha = " + std::to_string(std::cbrt(eps) / p.alpha));
}

void draw_error_vs_step(kit::Scene& scene, const Params& p, const Sweep& sw) {
    const double eps = std::numeric_limits<double>::epsilon();
    kit::Figure fig(scene, "omega_fd_error_vs_step.svg");
    std::vector<kit::Fill> curves;
    for (std::size_t s = 0; s < stencils.size(); ++s)
        curves.push_back({{"ls", std::to_string(s + 1)}, {"title", stencils[s].name}});
    fig.script(kit::gp::error_vs_step, {{"stencils", kit::joined(kit::gp::stencil, curves)}});
    for (std::size_t s = 0; s < stencils.size(); ++s) {
        std::vector<std::vector<double>> col;
        for (const auto& r : sw.rows) col.push_back({r[0], std::max(r[s + 1], 1e-17)});
        fig.data(col);
    }
    fig.data({{p.hmin, eps / (p.alpha * p.hmin)}, {p.hmax, eps / (p.alpha * p.hmax)}});
    fig.finish();
}

void draw_error_vs_time(kit::Scene& scene, const Sweep& sw) {
    kit::Figure wp(scene, "omega_fd_error_vs_time.svg");
    wp.script(kit::gp::error_vs_time);
    std::vector<std::vector<double>> central;
    for (std::size_t s = 1; s < stencils.size(); ++s) central.push_back({1e9 * sw.time_per[s], sw.best_err[s]});
    wp.data(central).data({{1e9 * sw.time_per[0], sw.best_err[0]}});
    std::vector<std::vector<double>> lab;
    for (std::size_t s = 0; s < stencils.size(); ++s)
        lab.push_back({1e9 * sw.time_per[s], sw.best_err[s], double(stencils[s].order)});
    wp.data(lab);
    wp.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("omega_finite_difference",
                      "Chapter 1: Omega from finite differences of R(t), error against step and run time");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        check(o, p);
        const Sweep sw = compute(p);
        report(scene, p, sw);
        draw_error_vs_step(scene, p, sw);
        draw_error_vs_time(scene, sw);
    });
}
