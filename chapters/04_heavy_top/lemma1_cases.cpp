// Chapter 4 scene: Lemma 1 and its Cases 1-3 [P, (3.8)-(3.14)], by a numerical search.
//
// For an asymmetric body, rigid::min_precession_residual looks for a regular precession
// R^b(beta t) R^a(alpha t) on a grid of fixed angles gamma between a and b and fixed ratios
// beta/alpha: Case 1 (beta/alpha = 1/2, sqrt 2), Case 2 (2), the ratio 3 that [P]'s Case 1
// passes over (|gamma_-| = 2 alpha), and Case 3 (1). Only gamma = 90 degrees with beta = alpha
// reaches zero. At that precession the scene moves to [P]'s frame (3.3) and measures every
// condition of (3.12)-(3.14) and the three claims of Lemma 1.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "body.hpp"
#include "figure.hpp"
#include "lemma1_cases.gp.hpp"
#include "precession.hpp"
#include "rigid/heavy_top.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

using rigid::Mat3;
using rigid::Vec3;
using std::numbers::pi;

namespace {

// snippet: ch04_lemma1_frame
// The precession found, seen in [P]'s frame (3.3): the time origin moved to the instant t0 at
// which R(t0) a lies in the plane of b and k, then e3 = a, e2 along the part of b across a.
struct Lemma1Frame {
    Mat3 J;
    Vec3 k, z0, b;
};

Lemma1Frame to_lemma1_frame(const rigid::PrecessionFit& fit) {
    const rigid::TrialPrecession& p = fit.precession;
    const Vec3 b = p.b, k = fit.top.k, a_perp = p.a - p.a.dot(b) * b;
    const double phi = std::atan2(-a_perp.dot(b.cross(k)), b.cross(a_perp).dot(b.cross(k)));  // beta t0
    const double t0 = phi / p.beta;
    const Mat3 R0 = kit::precession_rotation(p, t0);  // b = p.b
    const Vec3 a0 = R0 * p.a;                         // = R^b(beta t0) a
    Mat3 P;                                           // columns e1, e2, e3 of the new lab frame
    P.col(2) = a0;
    P.col(1) = (b - b.dot(a0) * a0).normalized();
    P.col(0) = P.col(1).cross(P.col(2));
    return {P.transpose() * R0 * fit.top.J * R0.transpose() * P, P.transpose() * k, P.transpose() * R0 * fit.top.z0,
            P.transpose() * b};
}
// end snippet

struct Params {
    kit::MomentsAtO body;
    int restarts = 8;
    long seed = 1;
};

void declare(kit::Options& opts, Params& p) {
    kit::moment_options(opts, p.body)
        .integer("restarts", &p.restarts, "random starts of the simplex per search", 1, 200)
        .integer("seed", &p.seed, "seed of the random starts", 0, 1000000);
}

const std::vector<double> ratios = {0.5, 1.0, std::sqrt(2.0), 2.0, 3.0};
const std::vector<double> gammas_deg = {30, 60, 90, 120, 150};

// The grid of searches: a row per ratio beta / alpha, the smallest residual at each gamma.
struct Grid {
    std::vector<std::vector<double>> table;
    rigid::PrecessionFit zero{};  // the search at beta = alpha, gamma = 90 deg (Case 3)
    double zero_time = 0, total_time = 0, worst_elsewhere = 1e300;
    long evaluations = 0;
};

Grid search(const Vec3& moments, const Params& p) {
    Grid grid;
    for (double ratio : ratios) {
        std::vector<double> row{ratio};
        for (double gd : gammas_deg) {
            rigid::PrecessionFit fit{};
            const double t = kit::min_time(
                [&] {
                    fit = rigid::min_precession_residual({.moments = moments,
                                                          .gamma = gd * pi / 180,
                                                          .ratio = ratio,
                                                          .restarts = p.restarts,
                                                          .seed = static_cast<unsigned>(p.seed)});
                },
                1);
            grid.total_time += t;
            grid.evaluations += fit.evaluations;
            row.push_back(fit.residual);
            if (ratio == 1.0 && gd == 90)
                grid.zero = fit, grid.zero_time = t;
            else
                grid.worst_elsewhere = std::min(grid.worst_elsewhere, fit.residual);
        }
        grid.table.push_back(row);
    }
    return grid;
}

// Case 3 with b3 = 0: the conditions (3.12)-(3.14) and Lemma 1 at the precession found.
void report(kit::Scene& scene, const Vec3& moments, const Grid& grid) {
    const rigid::PrecessionFit& zero = grid.zero;
    const Lemma1Frame L = to_lemma1_frame(zero);
    const Mat3& J = L.J;
    const double f = zero.top.f, a2 = zero.precession.alpha * zero.precession.alpha;
    const double scale = moments.maxCoeff();
    const std::vector<std::pair<std::string, double>> conditions = {
        {"(3.12) J12", std::abs(J(0, 1)) / scale},
        {"(3.12) J13", std::abs(J(0, 2)) / scale},
        {"(3.12) J22 - J11", std::abs(J(1, 1) - J(0, 0)) / scale},
        {"(3.13) alpha^2 J33 - f k2 z3", std::abs(a2 * J(2, 2) - f * L.k.y() * L.z0.z()) / f},
        {"(3.13) -alpha^2 J23 - f k3 z3", std::abs(-a2 * J(1, 2) - f * L.k.z() * L.z0.z()) / f},
        {"(3.14) k3 z1", std::abs(L.k.z() * L.z0.x())},
        {"(3.14) k3 z2", std::abs(L.k.z() * L.z0.y())},
        {"(3.14) k2 z1", std::abs(L.k.y() * L.z0.x())},
        {"(3.14) k2 z2", std::abs(L.k.y() * L.z0.y())},
        {"(3.3) k1 = 0", std::abs(L.k.x())},
    };
    double worst = 0;
    for (const auto& [name, v] : conditions) {
        scene.report.add(name, v);
        worst = std::max(worst, v);
    }
    scene.report.headline("largest violation of (3.12)-(3.14) at the precession found (beta = alpha, b3 = 0)", worst,
                          grid.zero_time);
    scene.report.add("residual_at_zero", zero.residual, "Case 3, gamma = 90 deg: RMS |E - f T| / f");
    scene.report.add("smallest_residual_elsewhere", grid.worst_elsewhere, "every other (ratio, gamma) of the grid");
    scene.report.add("lemma1a_b3", std::abs(L.b.z()), "|b3| (held at 0 by the grid point)");
    scene.report.add("lemma1b_z0_off_axis", std::hypot(L.z0.x(), L.z0.y()), "|z(0) x a|: z(0) = +-a");
    scene.report.add("lemma1c_J11", J(0, 0), "the principal moment along e1 (= B: Lemma 2)");
    scene.report.add("k", L.k, "in the frame (3.3)");
    scene.report.add("z0", L.z0, "in the frame (3.3)");
    scene.report.add("alpha", zero.precession.alpha, "with f = 1");
    scene.report.add("search_time_s", grid.total_time, "all 25 searches");
    scene.report.add("evaluations", grid.evaluations);
    scene.report.table("min_residual", {"beta/alpha", "gamma30", "gamma60", "gamma90", "gamma120", "gamma150"},
                       grid.table);
}

void draw(kit::Scene& scene, const Vec3& moments, const Grid& grid) {
    kit::Figure fig(scene, "lemma1_min_residual.svg", 820, 500);
    const std::string moments_text = std::to_string(moments(0)).substr(0, 4) + ", " +
                                     std::to_string(moments(1)).substr(0, 4) + ", " +
                                     std::to_string(moments(2)).substr(0, 4);
    const char* titles[] = {"β/α = 1/2 (Case 1)", "β = α (Case 3)", "β/α = √2 (Case 1)", "β = 2α (Case 2)",
                            "β = 3α (|γ_-| = 2α)"};
    std::vector<kit::Fill> curves;
    for (std::size_t r = 0; r < ratios.size(); ++r)
        curves.push_back({{"ls", std::to_string(r + 1)}, {"title", titles[r]}});
    fig.script(kit::gp::lemma1_cases, {{"moments", moments_text}, {"curves", kit::joined(kit::gp::curve, curves)}});
    for (std::size_t r = 0; r < ratios.size(); ++r) {
        std::vector<std::vector<double>> d;
        for (std::size_t g = 0; g < gammas_deg.size(); ++g)
            d.push_back({gammas_deg[g], std::max(grid.table[r][g + 1], 1e-17)});
        fig.data(d);
    }
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("lemma1_cases", "Chapter 4: Lemma 1 and Cases 1-3, by a search for regular precessions");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        const Vec3 moments = kit::require_moments(p.body);
        // The work: 25 searches of `restarts` simplex runs each (a run stops early at a zero).
        kit::require_budget(o, {25.0 * p.restarts, 0.03, "simplex runs", "--restarts"});
        const Grid grid = search(moments, p);
        report(scene, moments, grid);
        draw(scene, moments, grid);
    });
}
