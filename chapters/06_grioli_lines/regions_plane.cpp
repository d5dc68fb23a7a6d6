// Chapter 6 scene, Figure 5 of [P]: the plane of the smallest and largest axes at G, cut by the
// two Grioli lines (5.15) and the hyperbola (5.7) into the regions I-VI.
//
// Checked against the eigen-solver: on 64 lines below the critical angle, a bisection on
// Eigen's moments finds where B = C; there (5.7) must read 1 and (5.8) must give that h. On a
// grid over the plane, region() must agree with the order of Eigen's moments, or of the binary128
// moments where two of Eigen's are within its round-off (a nearly symmetric body). And the Grioli
// lines must be the normals of the circular sections of the inertia ellipsoid at G.
//
// One suspension point O = G + L z, z a Grioli line (--line) turned by --off radians (the book's
// live page moves it): the moments at O, its region, and Theorem 1's condition there. The gap
// cos^2 phi - (B - A)/(C - A) is checked against its closed form (dCB z_A^2 - dBA z_C^2)/(C - A),
// zero only on the Grioli lines.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "common.hpp"
#include "figure.hpp"
#include "regions_plane.gp.hpp"

using namespace ch6;

struct Params {
    rigid::BodyAtG body = ch6::default_body;
    int lines = 64;
    int grid = 121;
    int line = 1;    // the suspension point: on the Grioli line x_C = line k x_A,
    double off = 0;  // turned by off rad (> 0 towards x_C, < 0 towards x_A),
    double L = 1;    // at the distance L from G
};

void declare(kit::Options& opts, Params& p) {
    ch6::body_options(opts, p.body);
    opts.integer("lines", &p.lines, "lines below the critical angle on which B = C is found by bisection", 4, 4096)
        .integer("grid", &p.grid, "grid points per side for the region check", 11, 1001)
        .integer("line", &p.line, "the suspension point's Grioli line (5.15): +1 for x_C = +k x_A, -1 for x_C = -k x_A",
                 -1, 1)
        .real("off", &p.off,
              "the angle (rad) between the suspension point's line OG and the Grioli line: 0 on it, > 0 towards x_C, "
              "< 0 towards x_A",
              kit::between(-0.5, 0.5))
        .real("L", &p.L, "the distance from G to the suspension point O", kit::between(1e-3, 1e3));
}

namespace {

// Each of Eigen's moments is within eigen_bound eps |I'| of the exact one (|I'| the Frobenius
// norm; the solver is backward stable, and the scene measures its error against binary128). Where
// two of its moments are closer than twice that, their order is round-off's, not the body's: a
// point within the eigen-solver's round-off of a region boundary (B = C, or B = A for a nearly
// symmetric body at G). There region() is judged by the binary128 moments instead.
constexpr double eigen_bound = 8;

// (5.7) and (5.8) at the eigen-solver's crossings, over `lines` lines below the critical angle.
struct Crossings {
    double hyperbola = 0, hcrit = 0, hcrit_printed = 0;
    double uncertainty = 0;  // of the crossings' h, relative: the reference's own
};

// How well Eigen's moments place B = C on the line z near h: C - B is off by up to twice
// eigen_bound eps |I'|, so the crossing by (2 eigen_bound eps |I'|) / |d(C - B)/dh| (the slope
// from the binary128 moments), relative to h.
double crossing_uncertainty(const BodyAtG& b, const Vec3& z, const Crossing& x) {
    const double h = x.h(), eps = std::numeric_limits<double>::epsilon();
    const auto C_minus_B = [&](double hh) { return inertia_reference::quad_moments(b, std::sqrt(hh / b.mu), z).CmB; };
    const double slope = static_cast<double>((C_minus_B(h * 1.001) - C_minus_B(h * 0.999)) / (0.002 * h));
    const double norm = tensor_at(b, std::sqrt(h / b.mu), z).norm();
    return 2 * eigen_bound * eps * norm / std::abs(slope) / h + (x.hi - x.lo) / h;
}

Crossings crossings(const BodyAtG& b, int lines) {
    const double crit = rigid::critical_cos2(b);
    Crossings err;
    for (int i = 0; i < lines; ++i) {
        const double c2 = crit * (i + 0.5) / lines;  // cos^2 phi_g in (0, crit)
        const Vec3 z(std::sqrt(c2), 0, (i % 2 ? -1 : 1) * std::sqrt(1 - c2));
        const Crossing x = crossing_by_bisection(b, z);
        const double h = x.h(), L = std::sqrt(h / b.mu);
        err.uncertainty = std::max(err.uncertainty, crossing_uncertainty(b, z, x));
        err.hyperbola = std::max(err.hyperbola, std::abs(rigid::hyperbola_lhs(b, L * z.x(), L * z.z()) - 1));
        err.hcrit = std::max(err.hcrit, std::abs(rigid::critical_h(b, z) - h) / h);
        err.hcrit_printed = std::max(err.hcrit_printed, std::abs(printed(b, L, z).h_crit_58() - h) / h);
    }
    return err;
}

// The half-width of the figure and of the region grid.
double plane_radius(const BodyAtG& b) { return 2.5 * std::sqrt(std::max(b.B_g - b.A_g, b.C_g - b.B_g) / b.mu); }

// One point of the grid, judged: the moments' order against region() (regions I-IV: A < B < C).
struct Judged {
    bool unresolved = false, eigen_wrong = false, mismatch = false;
    double eigen_error = -1;  // max |Eigen - binary128| / (eps |I'|), when measured
};

Judged judge(const BodyAtG& b, double x, double y, int region, const EigenMoments& e, bool measure) {
    const double L = std::hypot(x, y), eps = std::numeric_limits<double>::epsilon();
    const Vec3 z(x / L, 0, y / L);
    const double norm = tensor_at(b, L, z).norm();
    Judged j;
    j.unresolved = std::min(std::abs(e.B - e.A), std::abs(e.C - e.B)) <= 2 * eigen_bound * eps * norm;
    const bool eigen_abc = e.A < e.B && e.B < e.C;
    if (!j.unresolved && !measure) {
        j.mismatch = eigen_abc != (region <= 4);
        return j;
    }
    const quadref::Moments q = inertia_reference::quad_moments(b, L, z);
    const bool abc = q.BmA > 0 && q.CmB > 0;
    j.eigen_wrong = eigen_abc != abc;
    j.mismatch = (j.unresolved ? abc : eigen_abc) != (region <= 4);
    const auto off = [](double v, quadref::quad ref) { return static_cast<double>(quadref::abs_q(v - ref)); };
    j.eigen_error = std::max({off(e.A, q.A), off(e.B, q.B), off(e.C, q.C)}) / (eps * norm);
    return j;
}

// region() against the order of the moments on an n x n grid (Eigen's, or binary128's within
// Eigen's round-off of a boundary), and region() and Eigen timed.
struct RegionCheck {
    long mismatches = 0, checked = 0, unresolved = 0, eigen_wrong = 0, measured = 0;
    std::size_t points;
    double t_region, t_eigen;  // per point
    double eigen_error = 0;    // the largest measured, / (eps |I'|)
};

RegionCheck check_regions(const BodyAtG& b, int n) {
    const double R = plane_radius(b);
    std::vector<std::pair<double, double>> pts;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            pts.emplace_back(R * (2.0 * i / (n - 1) - 1) + 1e-9 * R, R * (2.0 * j / (n - 1) - 1) + 2e-9 * R);
    std::vector<int> regions(pts.size());
    const double t_region = kit::min_time([&] {
        for (std::size_t p = 0; p < pts.size(); ++p) regions[p] = rigid::region(b, pts[p].first, pts[p].second);
        kit::keep(regions);
    });
    std::vector<EigenMoments> eig(pts.size());
    const double t_eigen = kit::min_time(
        [&] {
            for (std::size_t p = 0; p < pts.size(); ++p) {
                const double L = std::hypot(pts[p].first, pts[p].second);
                eig[p] = eigen_moments(tensor_at(b, L, Vec3(pts[p].first / L, 0, pts[p].second / L)));
            }
            kit::keep(eig);
        },
        2);
    RegionCheck r{};
    r.points = pts.size();
    r.t_region = t_region / static_cast<double>(pts.size());
    r.t_eigen = t_eigen / static_cast<double>(pts.size());
    // Eigen's error is measured on 121 x 121 points of the grid at most (all of the default grid).
    const std::size_t stride = std::max<std::size_t>(1, pts.size() / (121 * 121));
    for (std::size_t p = 0; p < pts.size(); ++p) {
        if (regions[p] == 0) continue;
        ++r.checked;
        const Judged j = judge(b, pts[p].first, pts[p].second, regions[p], eig[p], p % stride == 0);
        r.unresolved += j.unresolved;
        r.eigen_wrong += j.unresolved && j.eigen_wrong;
        r.mismatches += j.mismatch;
        if (j.eigen_error >= 0) ++r.measured, r.eigen_error = std::max(r.eigen_error, j.eigen_error);
    }
    return r;
}

// Grioli's description: the largest angle between the lines (5.15) and the normals of the
// circular sections of x^T I_G x = 1.
double grioli_vs_sections(const BodyAtG& b) {
    const auto normals = rigid::circular_section_normals(Vec3(b.A_g, b.B_g, b.C_g).asDiagonal());
    double angle = 0;
    for (int s : {1, -1}) {
        const Vec3 z = rigid::grioli_direction(b, s);
        const Vec3& nrm = normals[s == 1 ? 0 : 1];
        angle = std::max(angle, std::atan2(z.cross(nrm).norm(), std::abs(z.dot(nrm))));
    }
    return angle;
}

// The suspension point O = G + L z of --line, --off, --L, and Theorem 1's condition there.
struct Point {
    Vec3 z;
    double L;
    int region;
    rigid::ShiftedMoments m;
    rigid::Cos2Sin2 tilt, ratio;
    double gap, gap_closed;  // cos^2 phi - (B - A)/(C - A): measured, and its closed form
};

Point suspension_point(const BodyAtG& b, const Params& p) {
    if (p.line == 0) throw kit::BadInput("--line: got 0; it must be +1 or -1");
    const Vec3 zg = rigid::grioli_direction(b, p.line);
    const Vec3 z = p.off == 0 ? zg : rigid::shift_direction(std::atan2(zg.z(), zg.x()) + p.line * p.off);
    Point o{z, p.L, rigid::region(b, p.L * z.x(), p.L * z.z()), rigid::shifted_moments(b, p.L, z), {}, {}, 0, 0};
    o.tilt = rigid::smallest_axis_tilt(b, p.L, z);
    o.ratio = rigid::grioli_ratio(o.m);
    o.gap = o.tilt.cos2 - o.ratio.cos2;
    // (5.12) - (5.13): ((C_g - A_g) cos 2phi_g - (2B_g - A_g - C_g)) / (2 sqrt D), written on the gaps.
    const double dBA = b.B_g - b.A_g, dCB = b.C_g - b.B_g;
    o.gap_closed = (dCB * z.x() * z.x() - dBA * z.z() * z.z()) / o.m.C_minus_A;
    return o;
}

void report_point(kit::Scene& scene, const Params& p, const Point& o) {
    scene.report.add("point_x_A", o.L * o.z.x(), "the suspension point O - G along x_A (--line, --off, --L)");
    scene.report.add("point_x_C", o.L * o.z.z(), "the suspension point O - G along x_C");
    scene.report.add("point_A", o.m.A, "the smallest moment at O (5.3)");
    scene.report.add("point_B", o.m.B, "B_g + h, about the normal of the plane: above C in the regions V, VI");
    scene.report.add("point_C", o.m.C, "(5.3)");
    scene.report.add("point_region", o.region, "region() of O: 1..6 for I..VI, 0 on a boundary");
    scene.report.add("point_cos2_phi", o.tilt.cos2, "(5.12): the smallest axis at O against the line OG");
    scene.report.add("point_ratio", o.ratio.cos2, "(5.13): (B - A)/(C - A) at O");
    scene.report.add("point_gap", o.gap, "cos^2 phi - (B - A)/(C - A): Theorem 1 asks for 0");
    scene.report.add("point_gap_closed_form", o.gap_closed, "(dCB z_A^2 - dBA z_C^2)/(C - A): 0 only on a Grioli line");
    scene.report.add("point_precesses", p.off == 0 ? 1 : 0,
                     "1: O on a Grioli line (--off 0), Theorem 1's precession exists; 0: off it, none exists (the "
                     "gap is not 0, however small)");
    if (!(std::abs(o.gap - o.gap_closed) <= 1e-12))
        throw kit::CheckFailed("at the suspension point, cos^2 phi - (B - A)/(C - A) = " + std::to_string(o.gap) +
                               " is not its closed form " + std::to_string(o.gap_closed));
}

void report(kit::Scene& scene, const BodyAtG& b, const Crossings& err, const RegionCheck& r) {
    scene.report.headline("max |(5.7) - 1| where the eigen-solver finds B = C (bisection), over the lines",
                          err.hyperbola, r.t_region);
    scene.report.add("critical_cos2", rigid::critical_cos2(b), "(5.6)");
    scene.report.add("h_crit_rel_error", err.hcrit, "(5.8) rewritten, against the bisection");
    scene.report.add("h_crit_printed_rel_error", err.hcrit_printed, "(5.8) as printed, against the bisection");
    scene.report.add("crossing_h_uncertainty", err.uncertainty,
                     "Eigen's own uncertainty on the crossings' h, relative: the three errors above are no better");
    scene.report.add("region_points_checked", r.checked);
    scene.report.add("region_mismatches", r.mismatches,
                     "region() against the order of the moments: Eigen's, binary128's where Eigen's is round-off's");
    scene.report.add("region_points_unresolved", r.unresolved,
                     "points where two of Eigen's moments are closer than twice its round-off bound");
    scene.report.add("region_unresolved_eigen_wrong", r.eigen_wrong,
                     "of these, where Eigen's order is not binary128's");
    scene.report.add("eigen_error_over_eps", r.eigen_error,
                     "max |Eigen - binary128| / (eps |I'|), at most " + std::to_string(static_cast<int>(eigen_bound)));
    scene.report.add("eigen_error_points", r.measured, "points where it was measured");
    scene.report.add("run_time_region_s", r.t_region, "per point");
    scene.report.add("run_time_eigen_s", r.t_eigen, "per point, SelfAdjointEigenSolver");
    scene.report.add("grioli_vs_circular_sections_rad", grioli_vs_sections(b),
                     "largest angle between (5.15) and the circular-section normals");
    if (!(r.eigen_error <= eigen_bound))
        throw kit::CheckFailed("the eigen-solver's moments are off by " + std::to_string(r.eigen_error) +
                               " eps |I'|, over the bound of " + std::to_string(eigen_bound) +
                               " that decides where its order is trusted");
    if (r.mismatches != 0)
        throw kit::CheckFailed("region() disagrees with the order of the moments at " + std::to_string(r.mismatches) +
                               " points (" + std::to_string(r.unresolved) + " judged in binary128)");
}

using Curve = std::vector<std::vector<double>>;

// Figure 5's regions as filled bands (x, y_lo, y_hi), the hyperbola's branches and the asymptotes.
struct Regions {
    Curve right, left, near_up, near_down, far_up, far_down, branch_up, branch_down, asym1, asym2;
};

Regions regions(const BodyAtG& b, double R) {
    const double dBA = b.B_g - b.A_g, dCB = b.C_g - b.B_g, k = std::sqrt(dCB / dBA);
    auto hyp = [&](double x) { return std::sqrt(dCB / b.mu * (1 + b.mu * x * x / dBA)); };
    Regions g;
    const int m = 400;
    for (int i = 0; i <= m; ++i) {
        const double x = R * (2.0 * i / m - 1), ax = std::min(k * std::abs(x), R), hx = std::min(hyp(x), R);
        (x >= 0 ? g.right : g.left).push_back({x, -ax, ax});
        g.near_up.push_back({x, ax, hx});
        g.near_down.push_back({x, -hx, -ax});
        g.far_up.push_back({x, hx, R});
        g.far_down.push_back({x, -R, -hx});
        if (hyp(x) <= R) {
            g.branch_up.push_back({x, hyp(x)});
            g.branch_down.push_back({x, -hyp(x)});
        }
    }
    const double xe = std::min(R, R / k);
    g.asym1 = {{-xe, -k * xe}, {xe, k * xe}};
    g.asym2 = {{-xe, k * xe}, {xe, -k * xe}};
    return g;
}

// The labels I-VI of the regions.
void region_labels(kit::Figure& fig, const BodyAtG& b, double R) {
    const double yv = std::sqrt((b.C_g - b.B_g) / b.mu);  // the vertex of the hyperbola
    auto label = [&](const std::string& text, double x, double y) {
        fig.script(kit::gp::label, {{"text", kit::quoted(text)}, {"x", std::to_string(x)}, {"y", std::to_string(y)}});
    };
    label("I", 0.8 * R, 0.0);
    label("II", -0.8 * R, 0.0);
    label("III", 0.0, 0.5 * std::min(yv, R));
    label("IV", 0.0, -0.5 * std::min(yv, R));
    label("V", 0.0, 0.5 * (std::min(yv, R) + R));
    label("VI", 0.0, -0.5 * (std::min(yv, R) + R));
}

// Figure 5, with the suspension point O (a segment from G to it).
void draw(kit::Scene& scene, const BodyAtG& b, const Point& o) {
    kit::Figure fig(scene, "regions_plane.svg", 640, 720);
    if (!fig.enabled()) return;
    const double R = std::max(plane_radius(b), 1.15 * o.L);
    const Regions g = regions(b, R);
    const auto normals = rigid::circular_section_normals(Vec3(b.A_g, b.B_g, b.C_g).asDiagonal());
    const Vec3 n0 = 0.6 * R * normals[0], n1 = 0.6 * R * normals[1];
    fig.script(kit::gp::regions_plane, {{"xmin", std::to_string(-R)},
                                        {"xmax", std::to_string(R)},
                                        {"ymin", std::to_string(-R)},
                                        {"ymax", std::to_string(R)}});
    region_labels(fig, b, R);
    fig.script(kit::gp::plot, {{"n0", std::to_string(n0.x()) + "," + std::to_string(n0.z())},
                               {"n1", std::to_string(n1.x()) + "," + std::to_string(n1.z())}});
    fig.data(g.right).data(g.left).data(g.near_up).data(g.near_down).data(g.far_up).data(g.far_down);
    fig.data(g.branch_up).data(g.branch_down).data(g.asym1).data(g.asym2);
    const std::vector<double> O{o.L * o.z.x(), o.L * o.z.z()};
    fig.data(Curve{{0, 0}, O}).data(Curve{O});
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("regions_plane",
                      "Chapter 6, Figure 5: regions I-VI of the principal plane, hyperbola (5.7), Grioli lines (5.15)");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options&, kit::Scene& scene) {
        const BodyAtG b = body(p.body);
        const Crossings err = crossings(b, p.lines);
        const RegionCheck r = check_regions(b, p.grid);
        const Point o = suspension_point(b, p);
        report(scene, b, err, r);
        report_point(scene, p, o);
        draw(scene, b, o);
    });
}
