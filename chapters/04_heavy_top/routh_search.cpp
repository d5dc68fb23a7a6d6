// Chapter 4 scene: Routh's result [P, Corollary 1] by a numerical search. With the precession
// vector b held along the vertical k, rigid::min_precession_residual minimises the residual
// of E = f T over the body's orientation, the direction of z(0) and alpha^2/f, for a grid of
// angles gamma between a and b and ratios beta/alpha. An asymmetric body leaves a residual
// that stays away from zero; the same body made symmetric (A = B) reaches round-off, as
// Lagrange's top must.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "body.hpp"
#include "figure.hpp"
#include "rigid/heavy_top.hpp"
#include "routh_search.gp.hpp"
#include "scene.hpp"

using rigid::Vec3;
using std::numbers::pi;

namespace {

struct Params {
    kit::MomentsAtO body;
    int restarts = 6;
    long seed = 1;
};

void declare(kit::Options& opts, Params& p) {
    kit::moment_options(opts, p.body)
        .integer("restarts", &p.restarts,
                 "random starts per search for the asymmetric body (the symmetric twin (B, B, C) gets four times as "
                 "many; it stops at its first zero)",
                 1, 200)
        .integer("seed", &p.seed, "seed of the random starts", 0, 1000000);
}

const std::vector<double> ratios = {0.5, 1.0, 2.0};
const std::vector<double> gammas_deg = {5, 30, 60, 90, 120, 150, 175};

struct Grid {
    std::vector<std::vector<double>> rows;  // gamma, then asym and sym residual per ratio
    double asym_min = 1e300, sym_max = 0, sym_time = 0;
    long evaluations = 0;
};

// snippet: ch04_routh_grid
// The smallest residual of E = f T with k along b, for the asymmetric body and its symmetric
// twin, at every angle gamma between a and b and every ratio beta / alpha.
Grid search(const Vec3& asym, const Vec3& sym, int restarts, unsigned seed) {
    Grid grid;
    for (double gd : gammas_deg) {
        std::vector<double> row{gd};
        for (int which = 0; which < 2; ++which)
            for (double ratio : ratios) {
                const Vec3& body = which ? sym : asym;
                rigid::PrecessionFit fit{};
                const double t = kit::min_time(
                    [&] {
                        fit = rigid::min_precession_residual({.moments = body,
                                                              .gamma = gd * pi / 180,
                                                              .ratio = ratio,
                                                              .k_along_b = true,
                                                              .restarts = which ? 4 * restarts : restarts,
                                                              .seed = seed});
                    },
                    1);
                grid.evaluations += fit.evaluations;
                row.push_back(fit.residual);
                if (which == 0)
                    grid.asym_min = std::min(grid.asym_min, fit.residual);
                else
                    grid.sym_max = std::max(grid.sym_max, fit.residual), grid.sym_time += t;
            }
        grid.rows.push_back(row);
    }
    return grid;
}
// end snippet

void report(kit::Scene& scene, const Grid& grid) {
    scene.report.headline("largest residual left for the symmetric twin (A = B), whose precessions about k exist",
                          grid.sym_max, grid.sym_time);
    scene.report.add("asymmetric_min", grid.asym_min, "smallest residual found for the asymmetric body, whole grid");
    std::vector<double> near_vertical;
    for (std::size_t r = 0; r < ratios.size(); ++r) near_vertical.push_back(grid.rows[0][1 + r]);
    scene.report.add("asymmetric_at_5deg", near_vertical,
                     "gamma = 5 deg, beta/alpha = 1/2, 1, 2: smallest near a || k");
    scene.report.add("evaluations", grid.evaluations);
    scene.report.table("min_residual", {"gamma_deg", "asym_r0.5", "asym_r1", "asym_r2", "sym_r0.5", "sym_r1", "sym_r2"},
                       grid.rows);
    scene.report.note(
        "the asymmetric minimum shrinks as gamma -> 0 or pi: there the trial motion degenerates into a "
        "uniform rotation about the vertical (Staude), which [P]'s definition (1.4) excludes");
}

void draw(kit::Scene& scene, const Grid& grid) {
    kit::Figure fig(scene, "routh_min_residual.svg", 820, 500);
    const char* rt[] = {"1/2", "1", "2"};
    std::vector<kit::Fill> curves;
    for (std::size_t r = 0; r < ratios.size(); ++r) curves.push_back({{"ls", std::to_string(r + 1)}, {"ratio", rt[r]}});
    fig.script(kit::gp::routh_search, {{"asymmetric", kit::joined(kit::gp::asymmetric, curves)},
                                       {"symmetric", kit::joined(kit::gp::symmetric, curves)}});
    for (std::size_t c = 1; c <= 2 * ratios.size(); ++c) {
        std::vector<std::vector<double>> d;
        for (const auto& row : grid.rows) d.push_back({row[0], std::max(row[c], 1e-17)});
        fig.data(d);
    }
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("routh_search",
                      "Chapter 4: Routh's result, no regular precession of an asymmetric body about the vertical");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        const Vec3 asym = kit::require_moments(p.body), sym(p.body.B, p.body.B, p.body.C);
        // The work: 21 searches of `restarts` simplex runs on the asymmetric body and 21 of
        // 4 restarts on its symmetric twin (which stops at its first zero: about 3 runs, measured).
        kit::require_budget(o, {21.0 * (p.restarts + 3), 0.03, "simplex runs", "--restarts"});
        const Grid grid = search(asym, sym, p.restarts, static_cast<unsigned>(p.seed));
        report(scene, grid);
        draw(scene, grid);
    });
}
