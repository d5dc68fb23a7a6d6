// Chapter 6 scene: how many digits the printed closed forms of [P, (5.3), (5.8), (5.12)] keep,
// against the rewritten forms of rigid/inertia.hpp and Eigen's eigen-solver, all measured
// against binary128 (tests/include/reference/quad_inertia.hpp):
//   1. on a Grioli line, L from 1e-6 to 1e6 body sizes;
//   2. on nearly symmetric bodies, B_g - A_g from 1e-1 to 1e-15 of C_g - A_g.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "closed_form_accuracy.gp.hpp"
#include "common.hpp"
#include "figure.hpp"
#include "reference/quad_inertia.hpp"

using namespace ch6;
using quadref::quad;

namespace {

// Relative error, floored at 1e-18 for a log plot (0 means: every digit right).
double floored(double e) { return std::max(e, 1e-18); }

struct Params {
    rigid::BodyAtG body = ch6::default_body;
    int points = 97;
};

void declare(kit::Options& opts, Params& p) {
    ch6::body_options(opts, p.body);
    opts.integer("points", &p.points, "distances, log-spaced from 1e-6 to 1e6 body sizes", 13, 10001);
}

constexpr int sign = 1;  // the Grioli line of the sweeps

// 1. Along the Grioli line: printed, rewritten and eigen-solver against binary128. Rows:
// L/size, A printed, stable, eigen, C - B printed, stable, eigen, sin^2 printed, stable.
struct DistanceSweep {
    std::vector<std::vector<double>> rows;
    double worst_stable = 0, worst_eigen_abs = 0, worst_eigen_rel = 0, worst_printed = 0;
};

DistanceSweep distance_sweep(const BodyAtG& b, int n) {
    const double ell = size_of(b);
    const Vec3 z = rigid::grioli_direction(b, sign);
    quad qA, qC;
    quadref::grioli_line(b.A_g, b.B_g, b.C_g, sign, qA, qC);
    DistanceSweep sw;
    for (int i = 0; i < n; ++i) {
        const double t = -6 + 12.0 * i / (n - 1), L = ell * std::pow(10.0, t);
        const auto r = quadref::moments(b.A_g, b.B_g, b.C_g, b.mu, L, qA, qC);
        const rigid::GrioliSuspension g = rigid::grioli_suspension(b, L, sign);
        const rigid::ShiftedMoments pm = rigid::printed_moments(b, L, z);
        const Printed p = printed(b, L, z);
        const Mat3 I = tensor_at(b, L, z);
        const EigenMoments e = eigen_moments(I);
        const double eA_stable = quadref::rel_err(g.frame.moments.A, r.A), eA_printed = quadref::rel_err(pm.A, r.A),
                     eA_eigen = quadref::rel_err(e.A, r.A);
        const double eCB_stable = quadref::rel_err(g.frame.moments.C_minus_B, r.CmB),
                     eCB_printed = quadref::rel_err(pm.C_minus_B, r.CmB),
                     eCB_eigen = quadref::rel_err(e.C - e.B, r.CmB);
        const double es_stable = quadref::rel_err(g.tilt.sin2, r.sin2),
                     es_printed = quadref::rel_err(1 - p.cos2_512(), r.sin2);
        sw.worst_stable = std::max({sw.worst_stable, eA_stable, eCB_stable, es_stable,
                                    quadref::rel_err(g.frame.moments.C, r.C), quadref::rel_err(g.tilt.cos2, r.cos2)});
        sw.worst_printed = std::max({sw.worst_printed, eA_printed, eCB_printed, es_printed});
        sw.worst_eigen_abs =
            std::max({sw.worst_eigen_abs, std::abs(e.A - g.frame.moments.A) / I.norm(),
                      std::abs(e.B - g.frame.moments.B) / I.norm(), std::abs(e.C - g.frame.moments.C) / I.norm()});
        sw.worst_eigen_rel = std::max(sw.worst_eigen_rel, eA_eigen);
        sw.rows.push_back({L / ell, floored(eA_printed), floored(eA_stable), floored(eA_eigen), floored(eCB_printed),
                           floored(eCB_stable), floored(eCB_eigen), floored(es_printed), floored(es_stable)});
    }
    return sw;
}

// One nearly symmetric body's row: gap, cos^2 printed, stable, B - A printed, stable, h_crit
// printed, stable; worst_stable takes the largest error of the rewritten forms.
std::vector<double> symmetric_row(double gap, double mu, double& worst_stable) {
    const BodyAtG s{1.0, 1.0 + 0.5 * gap, 1.5, mu};
    const double L = 0.1 * size_of(s);
    const Vec3 zs = rigid::grioli_direction(s, sign);
    quad sA, sC;
    quadref::grioli_line(s.A_g, s.B_g, s.C_g, sign, sA, sC);
    const auto r = quadref::moments(s.A_g, s.B_g, s.C_g, s.mu, L, sA, sC);
    const rigid::GrioliSuspension g = rigid::grioli_suspension(s, L, sign);
    const rigid::ShiftedMoments pm = rigid::printed_moments(s, L, zs);
    const Printed p = printed(s, L, zs);
    const double ec_stable = quadref::rel_err(g.tilt.cos2, r.cos2), ec_printed = quadref::rel_err(p.cos2_512(), r.cos2);
    const double eBA_stable = quadref::rel_err(g.frame.moments.B_minus_A, r.BmA),
                 eBA_printed = quadref::rel_err(pm.B_minus_A, r.BmA);
    // h_crit on the line at half the critical cos^2, against binary128 with delta exact.
    const double c2 = 0.5 * rigid::critical_cos2(s);
    const Vec3 zh = Vec3(std::sqrt(c2), 0, std::sqrt(1 - c2));
    const quad zA2 = quad(zh.x()) * zh.x(), zC2 = quad(zh.z()) * zh.z();
    const quad dBA = quad(s.B_g) - s.A_g, dCB = quad(s.C_g) - s.B_g;
    const quad h_ref = dBA * dCB / -(dCB * zA2 - dBA * zC2);
    const double eh_stable = quadref::rel_err(rigid::critical_h(s, zh), h_ref);
    const double eh_printed = quadref::rel_err(printed(s, 1.0, zh).h_crit_58(), h_ref);
    worst_stable = std::max({worst_stable, ec_stable, eBA_stable, eh_stable});
    return {gap,
            floored(ec_printed),
            floored(ec_stable),
            floored(eBA_printed),
            floored(eBA_stable),
            floored(eh_printed),
            floored(eh_stable)};
}

// 2. Nearly symmetric bodies: A_g = 1, B_g = 1 + gap/2, C_g = 1.5, at L = 0.1 body sizes.
std::vector<std::vector<double>> symmetric_sweep(double mu, double& worst_stable) {
    std::vector<std::vector<double>> rows;
    worst_stable = 0;
    for (int i = 0; i <= 56; ++i) rows.push_back(symmetric_row(std::pow(10.0, -1 - 14.0 * i / 56), mu, worst_stable));
    return rows;
}

// The run time of one closed-form evaluation and of one eigen-solver call.
std::pair<double, double> run_times(const BodyAtG& b) {
    const double ell = size_of(b);
    const Vec3 z = rigid::grioli_direction(b, sign);
    const double t_closed =
        kit::time_per_call([&](int i) { return rigid::shifted_moments(b, ell * (1 + 1e-3 * i), z).A; });
    const double t_eigen =
        kit::time_per_call([&](int i) { return eigen_moments(tensor_at(b, ell * (1 + 1e-3 * i), z)).A; });
    return {t_closed, t_eigen};
}

void report(kit::Scene& scene, const DistanceSweep& sw, const std::vector<std::vector<double>>& rows2,
            double worst_stable2, std::pair<double, double> times) {
    scene.report.headline("max relative error of the rewritten closed forms against binary128, both sweeps",
                          std::max(sw.worst_stable, worst_stable2), times.first);
    scene.report.add("run_time_eigen_s", times.second, "per SelfAdjointEigenSolver call");
    scene.report.add("worst_printed_rel_error", sw.worst_printed,
                     "printed (5.3), (5.12) on the Grioli line, L = 1e-6..1e6 sizes");
    scene.report.add("worst_stable_rel_error_distance", sw.worst_stable, "rewritten forms, same sweep");
    scene.report.add("worst_stable_rel_error_symmetric", worst_stable2, "rewritten forms, nearly symmetric bodies");
    scene.report.add("closed_vs_eigen_abs", sw.worst_eigen_abs,
                     "max |closed form - eigen-solver| / |I'| over the distance sweep");
    scene.report.add("closed_vs_eigen_rel_A", sw.worst_eigen_rel,
                     "max relative error of Eigen's A against binary128, same sweep");
    scene.report.table("distance_sweep",
                       {"L/size", "A_printed", "A_stable", "A_eigen", "CmB_printed", "CmB_stable", "CmB_eigen",
                        "sin2_printed", "sin2_stable"},
                       sw.rows, false);
    scene.report.table(
        "symmetric_sweep",
        {"gap", "cos2_printed", "cos2_stable", "BmA_printed", "BmA_stable", "hcrit_printed", "hcrit_stable"}, rows2,
        false);
    if (!(std::max(sw.worst_stable, worst_stable2) <= 1e-13))
        throw kit::NumericalFailure("a rewritten closed form lost digits");
}

void draw_distance(kit::Scene& scene, const std::vector<std::vector<double>>& rows) {
    kit::Figure fig(scene, "accuracy_vs_distance.svg", 820, 520);
    if (!fig.enabled()) return;
    fig.script(kit::gp::distance);
    for (int rep = 0; rep < 8; ++rep) fig.data(rows);
    fig.finish();
}

void draw_symmetric(kit::Scene& scene, const std::vector<std::vector<double>>& rows2) {
    kit::Figure fig(scene, "accuracy_nearly_symmetric.svg", 820, 500);
    if (!fig.enabled()) return;
    fig.script(kit::gp::nearly_symmetric);
    for (int rep = 0; rep < 6; ++rep) fig.data(rows2);
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("closed_form_accuracy",
                      "Chapter 6: digits kept by the printed and the rewritten closed forms, and by the eigen-solver");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options&, kit::Scene& scene) {
        const BodyAtG b = body(p.body);
        const DistanceSweep sw = distance_sweep(b, p.points);
        double worst_stable2 = 0;
        const auto rows2 = symmetric_sweep(b.mu, worst_stable2);
        report(scene, sw, rows2, worst_stable2, run_times(b));
        draw_distance(scene, sw.rows);
        draw_symmetric(scene, rows2);
    });
}
