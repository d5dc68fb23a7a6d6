// Chapter 5 scene: the initial position of a Grioli gyroscope, built by the recipe of Item II
// [P, Introduction] (the paper's Figure 1, which the source leaves empty).
//
// rigid::place_item_II places the body in a lab whose vertical is e3, tilting in the plane of
// e3 and e1 (the "paper sheet"). The figure shows k, b, a, the centre of mass G, the inertia
// axes and the inertia ellipsoid at O with its circular section orthogonal to a. The error
// is the residual of the Euler equation E = f T along R^b(alpha t) R^a(alpha t) for the placed
// body, computed in the lab with its inertia tensor R0 diag(A, B, C) R0^T.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "figure.hpp"
#include "grioli_initial_position.gp.hpp"
#include "heavy_body.hpp"
#include "rigid/grioli.hpp"
#include "rigid/heavy_top.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

using rigid::Mat3;
using rigid::Vec3;
using std::numbers::pi;

namespace {

std::string xyz(const Vec3& v) {
    return std::to_string(v.x()) + "," + std::to_string(v.y()) + "," + std::to_string(v.z());
}

// Points of the ellipse {c u + s v} scaled in the plane of the unit vectors u, v.
std::vector<std::vector<double>> ellipse(const Vec3& u, double ru, const Vec3& v, double rv) {
    std::vector<std::vector<double>> pts;
    for (int i = 0; i <= 120; ++i) {
        const double t = 2 * pi * i / 120;
        const Vec3 p = ru * std::cos(t) * u + rv * std::sin(t) * v;
        pts.push_back({p.x(), p.y(), p.z()});
    }
    pts.push_back({});
    pts.push_back({});
    return pts;
}

struct Params {
    kit::HeavyBody body;
};

struct Placement {
    rigid::Moments m;
    double f;
    rigid::LabPlacement p;
    double run_time;
};

Placement compute(const Params& prm) {
    Placement r{kit::grioli_moments(prm.body.moments, 1e3), prm.body.f, {}, 0};
    r.run_time =
        kit::min_time([&] { r.p = rigid::place_item_II(r.m, r.f, rigid::Sense::ccw, Vec3::UnitZ(), Vec3::UnitX()); });
    return r;
}

void report(kit::Scene& scene, const Placement& r) {
    const rigid::Moments& m = r.m;
    const rigid::LabPlacement& p = r.p;
    const Mat3 J_lab = p.R0 * Vec3(m.A, m.B, m.C).asDiagonal() * p.R0.transpose();
    const double residual =
        rigid::precession_residual(rigid::heavy_top(J_lab, r.f, p.k, p.z0), {p.a, p.alpha, p.b, p.alpha}, 64);
    scene.report.headline("RMS |E - f T| / f along R^b(alpha t) R^a(alpha t) for the body placed by Item II", residual,
                          r.run_time);
    scene.report.add("theta_deg", p.theta * 180 / pi, "tilt of b from k");
    scene.report.add("phi_deg", std::acos(rigid::grioli_rotation_vector(m).x()) * 180 / pi,
                     "angle of z(0) to R_A [P, (int.2)]");
    scene.report.add("k", p.k);
    scene.report.add("b", p.b);
    scene.report.add("a", p.a);
    scene.report.add("R_A", Vec3(p.R0.col(0)));
    scene.report.add("R_B", Vec3(p.R0.col(1)));
    scene.report.add("R_C", Vec3(p.R0.col(2)));
    scene.report.add("k_body", Vec3(p.R0.transpose() * p.k), "k in the inertia frame: the k of (4.11)");
    scene.report.add("rule_holds", rigid::item_II_rule_holds(m, p.R0, p.k));
}

// Where the figure's arrows end and its labels stand (grioli_initial_position.gp): k, b, a, G,
// the axes R_A, R_C and theta.
kit::Fill places(const rigid::LabPlacement& p) {
    const Vec3 RA = p.R0.col(0), RC = p.R0.col(2);
    return {{"k", xyz(1.45 * p.k)},
            {"k_label", xyz(1.45 * p.k + Vec3(0.05, 0, 0.08))},
            {"b", xyz(1.3 * p.b)},
            {"b_label", xyz(1.3 * p.b + Vec3(0.06, 0, 0.06))},
            {"a", xyz(1.3 * p.a)},
            {"a_label", xyz(1.3 * p.a + Vec3(0.0, 0.0, 0.15))},
            {"G_label", xyz(1.0 * p.z0 + Vec3(0.05, 0, -0.12))},
            {"RA_label", xyz(1.45 * RA)},
            {"RC_label", xyz(1.45 * RC)},
            {"theta_label", xyz(0.45 * (p.k + p.b).normalized() + Vec3(0.02, 0, 0.03))}};
}

void draw(kit::Scene& scene, const Placement& r) {
    kit::Figure fig(scene, "initial_position.svg", 820, 720);
    if (!fig.enabled()) return;
    const rigid::Moments& m = r.m;
    const rigid::LabPlacement& p = r.p;
    const Vec3 RA = p.R0.col(0), RB = p.R0.col(1), RC = p.R0.col(2);
    // The inertia ellipsoid x.J x = B (so its circular sections have radius 1), drawn small.
    const double s = 0.9, rA = s * std::sqrt(m.B / m.A), rB = s, rC = s * std::sqrt(m.B / m.C);
    const Vec3 w = p.a.cross(RB).normalized();  // in the circular section, with R_B
    fig.script(kit::gp::grioli_initial_position, places(p));
    std::vector<std::vector<double>> axes;
    for (const Vec3& v : {RA, RC}) {
        const Vec3 q = 1.4 * v;
        axes.push_back({-q.x(), -q.y(), -q.z()});
        axes.push_back({q.x(), q.y(), q.z()});
        axes.push_back({});
        axes.push_back({});
    }
    fig.data(axes);
    std::vector<std::vector<double>> ell = ellipse(RA, rA, RB, rB), e2 = ellipse(RB, rB, RC, rC),
                                     e3 = ellipse(RC, rC, RA, rA);
    ell.insert(ell.end(), e2.begin(), e2.end());
    ell.insert(ell.end(), e3.begin(), e3.end());
    fig.data(ell);
    fig.data(ellipse(RB, s, w, s));                      // the circular section, orthogonal to a
    fig.data(ellipse(p.z0, 1.0, p.b.cross(p.z0), 1.0));  // the path of G: a circle about b
    fig.data({{p.z0.x(), p.z0.y(), p.z0.z()}});
    // The "paper sheet": the plane of k and b (here the plane of e1 and e3).
    fig.data({{-1.4, 0, -1.1}, {1.4, 0, -1.1}, {1.4, 0, 1.5}, {-1.4, 0, 1.5}, {-1.4, 0, -1.1}});
    fig.data({{0, 0, -1.1}, {0, 0, 0}});
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("grioli_initial_position", "Chapter 5: the initial position of Item II (the paper's Figure 1)");
    kit::heavy_body_options(opts, p.body);
    return kit::run(argc, argv, opts, [&](const kit::Options&, kit::Scene& scene) {
        const Placement r = compute(p);
        report(scene, r);
        draw(scene, r);
    });
}
