// Chapter 3 scene: Theorem 2 of [P], measured. A regular precession has Omega(t) on a plane
// circle [P, (1.5)-(1.7)]; a free motion has Omega(t) on a polhode, the intersection of the two
// ellipsoids (6.9). Is a polhode ever a plane circle?
//
// For an asymmetric body, a sweep of polhodes from next to a principal axis (elliptic parameter
// m -> 0) to next to the separatrix (m_c -> 0), on both sides: the exact Omega(t) over one
// period, the best-fit plane and circle (fit_circle), and both residuals relative to the size of
// the curve. Then a symmetric body (it must give a circle) and nearly symmetric ones, and the
// exact separatrix (a plane curve, but an ellipse). The exact motion is checked against the
// student's equations integrated by rk8pd on every curve: that is the headline error.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "body.hpp"
#include "figure.hpp"
#include "free_body_scene.hpp"
#include "rigid/free_body_exact.hpp"
#include "rigid/precession.hpp"
#include "rigid/require.hpp"
#include "scene.hpp"
#include "theorem2_circle_test.gp.hpp"

using rigid::Vec3;

namespace {

struct Residuals {
    double plane, circle, size;
};

// snippet: polhode_residuals
// Omega(t) at n instants of [t0, t1], fitted by a plane and a circle; residuals relative to the
// size of the curve (the largest distance of a point from the centroid).
Residuals polhode_residuals(const rigid::FreeBodyMotion& motion, double t0, double t1, int n) {
    std::vector<Vec3> pts;
    Vec3 centroid = Vec3::Zero();
    for (int k = 0; k < n; ++k) {
        pts.push_back(rigid::free_body_exact_omega(motion, t0 + (t1 - t0) * k / n));
        centroid += pts.back() / n;
    }
    double size = 0;
    for (const Vec3& x : pts) size = std::max(size, (x - centroid).norm());
    const rigid::CircleFit fit = rigid::fit_circle(pts);
    return {fit.plane_residual / size, fit.circle_residual / size, size};
}
// end snippet

struct Params {
    Vec3 I = Vec3(2, 3, 4);
    double energy = 0.5;
    int samples = 400;
    double tol = 1e-12;
};

void declare(kit::Options& opts, Params& p) {
    opts.vector("I", &p.I, "principal moments I1,I2,I3 of the asymmetric body", kit::components_between(1e-3, 1e3))
        .real("energy", &p.energy, "kinetic energy E of every motion", kit::between(1e-6, 1e6))
        .integer("samples", &p.samples, "instants per period fitted", 16, 100000)
        .real("tol", &p.tol, "rk8pd tolerance for the check of the exact motion", kit::between(1e-14, 1e-3));
}

void check_input(const kit::Options& o, const Params& p) {
    kit::require_moments(p.I, "I", {kit::Order::distinct});
    const auto [lo, mid, hi] = scene3::sorted_axes(p.I);
    // The work: about 60 motions sampled n times per period, and 5 rk8pd checks of at most
    // 20 time units (3 timed runs each) at |Omega| = sqrt(2 E / I_lo) at most.
    const double omega = std::sqrt(2 * p.energy / p.I(lo));
    kit::require_budget(
        o, {60.0 * p.samples * 20 + 5 * 3 * std::min(20 * omega, 400.0) * scene3::steps_per_radian("rk8pd", p.tol) * 13,
            1.5e-7, "evaluations", "--samples, --tol, --energy"});
}

// The exact motion against the student's equations integrated by rk8pd: the largest error and
// the run time over the curves checked.
struct Check {
    double tol, err = 0, run_time = 0;
    void operator()(const Vec3& Iv, const rigid::FreeBodyMotion& mo, double T) {
        const auto times = rigid::linspace(0, T, 8);
        scene3::Run run;
        run_time += kit::min_time([&] { run = scene3::integrate(Iv, mo.Omega0, times, "rk8pd", tol); }, 3);
        for (std::size_t k = 0; k < times.size(); ++k)
            err = std::max(err, (run.Omega[k] - rigid::free_body_exact_omega(mo, times[k])).norm() / mo.Omega0.norm());
    }
};

// Fractions f of the way from the separatrix (f -> 0) to an axis (f -> 1), both sides. Rows:
// side, fraction, m, m_c, plane residual, circle residual.
std::vector<std::vector<double>> sweep(const Params& p, Check& check) {
    const Vec3& I = p.I;
    const auto [lo, mid, hi] = scene3::sorted_axes(I);
    std::vector<double> fractions;
    for (int e = 12; e >= 1; --e) fractions.push_back(std::pow(10.0, -e));
    for (double f : {0.2, 0.4, 0.6, 0.8}) fractions.push_back(f);
    for (int e = 1; e <= 12; ++e) fractions.push_back(1 - std::pow(10.0, -e));
    std::vector<std::vector<double>> rows;
    for (int side : {-1, +1}) {  // -1: about the smallest axis, +1: about the largest
        for (double f : fractions) {
            const double D = side < 0 ? I(mid) - f * (I(mid) - I(lo)) : I(mid) + f * (I(hi) - I(mid));
            const auto mo = rigid::free_body_motion(I, scene3::polhode_start(I, p.energy, D));
            if (mo.steady || !std::isfinite(mo.period)) continue;
            const Residuals r = polhode_residuals(mo, 0, mo.period, p.samples);
            if (f == 0.4 || f == 1e-6 || f == 1 - 1e-6) check(I, mo, std::min(mo.period, 20.0));
            rows.push_back({double(side), f, mo.m, mo.m_c, r.plane, r.circle});
        }
    }
    return rows;
}

// The separatrix itself (case 0) and a flat body (case 2). Rows: case, m_c, plane, circle.
std::vector<std::vector<double>> special_cases(const Params& p) {
    const Vec3& I = p.I;
    const double E = p.energy;
    const int n = p.samples;
    const auto [lo, mid, hi] = scene3::sorted_axes(I);
    std::vector<std::vector<double>> special;
    {
        // The separatrix: a motion that takes forever to go once round half an ellipse. Omega0 with
        // I_lo (I_mid - I_lo) W_lo^2 = I_hi (I_hi - I_mid) W_hi^2 to round-off, and W_mid = 0.
        const auto mo = rigid::free_body_motion(I, scene3::polhode_start(I, E, I(mid)));
        // Omega0 is on the separatrix only to round-off (m_c ~ 1e-16): the motion would come
        // back after 2K / lambda ~ 40 / lambda. The window +-15 / lambda stays on one half-ellipse.
        const double T = 15 / mo.lambda;
        const Residuals r = polhode_residuals(mo, -T, T, n);
        special.push_back({0, mo.m_c, r.plane, r.circle});
    }
    // A flat body, I_hi = I_lo + I_mid: its polhodes about the largest axis project onto the plane
    // of the other two as circles, since I_lo (I_hi - I_lo) = I_mid (I_hi - I_mid). Planar they are not.
    Vec3 If = I;
    If(hi) = I(lo) + I(mid);
    const auto mo = rigid::free_body_motion(If, scene3::polhode_start(If, E, 0.5 * (If(mid) + If(hi))));
    const Residuals r = polhode_residuals(mo, 0, mo.period, n);
    special.push_back({2, mo.m_c, r.plane, r.circle});
    return special;
}

// A symmetric body I_lo = I_mid (a regular precession), and nearly symmetric ones. Rows:
// asymmetry, m, plane, circle.
std::vector<std::vector<double>> nearly_symmetric(const Params& p, Check& check) {
    const Vec3& I = p.I;
    const auto [lo, mid, hi] = scene3::sorted_axes(I);
    std::vector<std::vector<double>> sym_rows;
    for (double eps : {0.0, 1e-10, 1e-8, 1e-6, 1e-4, 1e-2}) {
        Vec3 Is = I;
        Is(lo) = I(mid) * (1 - eps);
        const double D = 0.5 * (I(mid) + I(hi));
        const auto mo = rigid::free_body_motion(Is, scene3::polhode_start(Is, p.energy, D) + 0.3 * Vec3::Unit(mid));
        const Residuals r = polhode_residuals(mo, 0, mo.period, p.samples);
        if (eps == 0 || eps == 1e-2) check(Is, mo, std::min(mo.period, 20.0));
        sym_rows.push_back({eps, mo.m, r.plane, r.circle});
    }
    return sym_rows;
}

struct Results {
    std::vector<std::vector<double>> rows, special, sym_rows;
    Check check;
};

void report(kit::Scene& scene, const Results& r) {
    scene.report.headline("max |Omega_exact - Omega_rk8pd| / |Omega(0)| on the checked curves (student's equations)",
                          r.check.err, r.check.run_time);
    double min_circle_asym = 1e300;
    for (const auto& row : r.rows) min_circle_asym = std::min(min_circle_asym, row[5]);
    scene.report.add("asymmetric_min_circle_residual", min_circle_asym,
                     "smallest relative circle residual over the sweep");
    scene.report.add("separatrix_plane_residual", r.special[0][2], "exact separatrix, relative");
    scene.report.add("separatrix_circle_residual", r.special[0][3],
                     "exact separatrix, relative: an ellipse, not a circle");
    scene.report.add("symmetric_plane_residual", r.sym_rows[0][2]);
    scene.report.add("symmetric_circle_residual", r.sym_rows[0][3]);
    scene.report.table("sweep", {"side", "fraction_to_axis", "m", "m_c", "plane_residual", "circle_residual"}, r.rows,
                       false);
    scene.report.add("flat_body_plane_residual", r.special[1][2],
                     "flat body I_hi = I_lo + I_mid, about the largest axis");
    scene.report.add("flat_body_circle_residual", r.special[1][3], "its projection on the best plane is a circle");
    scene.report.table("special", {"case", "m_c", "plane_residual", "circle_residual"}, r.special);
    scene.report.note(
        "special: case 0 = the exact separatrix over +-15/lambda; case 2 = a flat body, about its largest axis");
    scene.report.table("nearly_symmetric", {"asymmetry", "m", "plane_residual", "circle_residual"}, r.sym_rows);
}

// The sweep's residual in column col on one side, against m (near_axis) or m_c.
std::vector<std::vector<double>> series(const std::vector<std::vector<double>>& rows, int side, bool near_axis,
                                        int col) {
    std::vector<std::vector<double>> out;
    for (const auto& r : rows) {
        if (int(r[0]) != side) continue;
        const double x = near_axis ? r[2] : r[3];
        if (x <= 0.5) out.push_back({x, std::max(r[col], 1e-17)});
    }
    return out;
}

void draw(kit::Scene& scene, const Results& r) {
    const auto& rows = r.rows;
    kit::Figure fig(scene, "theorem2_residuals.svg", 1000, 460);
    fig.script(kit::gp::theorem2_circle_test);
    std::vector<std::vector<double>> sym;
    for (const auto& s : r.sym_rows)
        if (s[1] > 0)
            sym.push_back({s[1], std::max(s[3], 1e-17)});  // the exactly symmetric body (m = 0) is in the table
    fig.data(series(rows, -1, true, 4)).data(series(rows, 1, true, 4)).data(series(rows, -1, true, 5));
    fig.data(series(rows, 1, true, 5)).data(sym);
    fig.script(kit::gp::separatrix);
    fig.data(series(rows, -1, false, 4)).data(series(rows, 1, false, 4)).data(series(rows, -1, false, 5));
    fig.data(series(rows, 1, false, 5));
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("theorem2_circle_test", "Chapter 3: Theorem 2 measured: is a free polhode ever a plane circle?");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        check_input(o, p);
        Results r{{}, {}, {}, Check{p.tol}};
        r.rows = sweep(p, r.check);
        r.special = special_cases(p);
        r.sym_rows = nearly_symmetric(p, r.check);
        report(scene, r);
        draw(scene, r);
    });
}
