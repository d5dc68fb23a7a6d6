// Chapter 5 scene: [P]'s Figures 2 and 3, which the source leaves empty. They show one motion,
// the counter-clockwise Grioli precession, a quarter period apart, in the lab of Item II
// (rigid::place_item_II with k up along z and the tilt toward x: k, b and [a, b] lie in the
// x-z plane, the "paper sheet", and a is perpendicular to it).
//
//   * Figure 2, t = -T/4 [P, Sect. 4]: the lab basis adapted to k, a, b, e1 = a, e2 = b,
//     e3 = [a, b] (the body's rotation axis R(-T/4) a, with the centre of mass G on it), and the
//     body's inertia axes at that instant. In that basis J has the block form [P, (3.14.1)].
//   * Figure 3, t = 0 [P, Sect. 5]: the inertia axes R_A, R_B = b, R_C, a = z(0) and k.
//
// The error is the largest deviation of J in Figure 2's basis from the block form (3.14.1),
// J12 = J13 = 0 and J22 = J11 = B (relative to C), and of the residuals of [P, (3.13)],
// alpha^2 J33 = f k2 z3 and -alpha^2 J23 = f k3 z3 (divided by f).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "figure.hpp"
#include "grioli_frames.gp.hpp"
#include "heavy_body.hpp"
#include "rigid/grioli.hpp"
#include "rigid/heavy_top.hpp"
#include "scene.hpp"

using rigid::Mat3;
using rigid::Vec3;
using std::numbers::pi;

namespace {

struct Params {
    kit::HeavyBody body;
};

// The body at one instant, in the lab: its inertia axes (columns R_A, R_B, R_C) and the unit
// vector z from O to its centre of mass.
struct Instant {
    Mat3 axes;
    Vec3 z;
};

struct Frames {
    rigid::GrioliPrecession g;
    Mat3 R0;              // the inertia frame of t = 0 -> the lab of Item II
    Mat3 E;               // Figure 2's basis e1 = a, e2 = b, e3 = [a, b], in the inertia frame of t = 0
    Instant fig2, fig3;   // t = -T/4 and t = 0, in the lab
    Mat3 J_fig2;          // the inertia tensor in Figure 2's basis
    Vec3 k_fig2, z_fig2;  // k and z(-T/4) in Figure 2's basis
};

// Everything from the workbook's API: the precession, its placement in the lab, and the body
// a quarter period before t = 0, R(-T/4) = R^b(-pi/2) R^a(-pi/2).
Frames frames(const rigid::Moments& m, double f) {
    Frames r{};
    r.g = rigid::grioli_precession(m, f, rigid::Sense::ccw);
    r.R0 = rigid::place_item_II(m, f, rigid::Sense::ccw, Vec3::UnitZ(), Vec3::UnitX()).R0;
    const rigid::GrioliPrecession& g = r.g;
    r.E << g.a, g.b, g.a.cross(g.b);
    const Mat3 Rq = rigid::grioli_rotation(g, -pi / (2 * g.alpha));
    r.J_fig2 = r.E.transpose() * Rq * Vec3(m.A, m.B, m.C).asDiagonal() * Rq.transpose() * r.E;
    r.k_fig2 = r.E.transpose() * g.k;
    r.z_fig2 = r.E.transpose() * Rq * g.z0;
    r.fig2 = {r.R0 * Rq, r.R0 * Rq * g.z0};
    r.fig3 = {r.R0, r.R0 * g.z0};
    return r;
}

struct Result {
    rigid::Moments m;
    double f;
    Frames fr;
    double run_time;
};

Result compute(const Params& prm) {
    Result r{kit::grioli_moments(prm.body.moments), prm.body.f, {}, 0};
    r.run_time = kit::min_time([&] { r.fr = frames(r.m, r.f); });
    return r;
}

// [P, (3.14.1)]: J12 = J13 = 0, J22 = J11, and J11 = B (e1 is the intermediate axis), relative to C.
double block_form_deviation(const Mat3& J, const rigid::Moments& m) {
    return std::max({std::abs(J(0, 1)), std::abs(J(1, 0)), std::abs(J(0, 2)), std::abs(J(2, 0)),
                     std::abs(J(1, 1) - J(0, 0)), std::abs(J(0, 0) - m.B)}) /
           m.C;
}

void report_lab(kit::Report& report, const Frames& fr) {
    const Vec3 k = fr.R0 * fr.g.k;
    report.add("k", k, "lab (Item II: up = z, toward = x)");
    report.add("fig2_e1", Vec3(fr.R0 * fr.E.col(0)), "e1 = a, lab");
    report.add("fig2_e2", Vec3(fr.R0 * fr.E.col(1)), "e2 = b, lab");
    report.add("fig2_e3", Vec3(fr.R0 * fr.E.col(2)), "e3 = [a, b], lab");
    report.add("fig2_z", fr.fig2.z, "centre of mass direction at t = -T/4, lab");
    report.add("fig2_R_A", Vec3(fr.fig2.axes.col(0)));
    report.add("fig2_R_B", Vec3(fr.fig2.axes.col(1)));
    report.add("fig2_R_C", Vec3(fr.fig2.axes.col(2)));
    report.add("fig3_R_A", Vec3(fr.fig3.axes.col(0)));
    report.add("fig3_R_B", Vec3(fr.fig3.axes.col(1)));
    report.add("fig3_R_C", Vec3(fr.fig3.axes.col(2)));
    report.add("fig3_a", fr.fig3.z, "a = z(0), lab");
    report.add("fig3_k_body", fr.g.k, "k along R_A, R_B, R_C at t = 0 (4.11): all positive");
}

void report(kit::Scene& scene, const Result& r) {
    const Frames& fr = r.fr;
    const Mat3& J = fr.J_fig2;
    const Vec3 &k = fr.k_fig2, &z = fr.z_fig2;
    const double s = fr.g.alpha * fr.g.alpha / r.f;  // alpha^2 / f
    const double block = block_form_deviation(J, r.m), r33 = std::abs(s * J(2, 2) - k.y() * z.z()),
                 r23 = std::abs(-s * J(1, 2) - k.z() * z.z());
    scene.report.headline(
        "largest deviation of J in Figure 2's basis from the block form (3.14.1) (J12, J13, J22 - J11, J11 - B, "
        "relative to C) and of the residuals of (3.13) (divided by f)",
        std::max({block, r33, r23}), r.run_time);
    std::vector<std::vector<double>> rows;
    for (int i = 0; i < 3; ++i) rows.push_back({J(i, 0), J(i, 1), J(i, 2)});
    scene.report.table("J_fig2", {"e1", "e2", "e3"}, rows);
    scene.report.add("k_fig2", k, "k in Figure 2's basis: (0, cos theta, sin theta)");
    scene.report.add("z_fig2", z, "z(-T/4) in Figure 2's basis: e3 [P, (3.14)]");
    scene.report.add("theta_deg", fr.g.theta * 180 / pi, "tilt of b from k");
    scene.report.add("block_form_deviation", block, "(3.14.1), relative to C");
    scene.report.add("eq_3_13_J33", r33, "|alpha^2 J33 - f k2 z3| / f");
    scene.report.add("eq_3_13_J23", r23, "|alpha^2 J23 + f k3 z3| / f");
    const rigid::HeavyTop top = rigid::heavy_top(J, r.f, k, z);
    scene.report.add("residual_fig2",
                     rigid::precession_residual(top, {Vec3::UnitZ(), fr.g.alpha, Vec3::UnitY(), fr.g.alpha}),
                     "RMS |E - f T| / f of R^e2(alpha t) R^e3(alpha t) in Figure 2's basis");
    report_lab(scene.report, fr);
}

std::string xyz(const Vec3& v) {
    return std::to_string(v.x()) + "," + std::to_string(v.y()) + "," + std::to_string(v.z());
}

// An arrow from O with its label at the tip.
struct Arrow {
    Vec3 v;
    std::string text, colour;
    Vec3 offset;
    std::string style = "lw 2.5";
};

void arrows(kit::Figure& fig, const std::vector<Arrow>& list) {
    fig.script(kit::gp::clear);
    int id = 1;
    for (const Arrow& a : list) {
        const std::string n = std::to_string(id++);
        fig.script(kit::gp::arrow, {{"n", n},
                                    {"to", xyz(a.v)},
                                    {"style", a.style},
                                    {"colour", a.colour},
                                    {"text", kit::quoted(a.text)},
                                    {"at", xyz(a.v + a.offset)}});
    }
}

// One panel: the arrows, then the path of G over a period (a circle about b), G, and the plane
// of k and b (the paper sheet, here the x-z plane).
void panel(kit::Figure& fig, const Result& r, const std::string& title, const std::vector<Arrow>& list, const Vec3& G) {
    arrows(fig, list);
    const Vec3 k = r.fr.R0 * r.fr.g.k, b = r.fr.R0 * r.fr.g.b;
    fig.script(kit::gp::panel,
               {{"theta_at", xyz(0.5 * (k + b).normalized() + Vec3(0.01, 0, 0.02))}, {"title", kit::quoted(title)}});
    std::vector<std::vector<double>> path;
    for (int i = 0; i <= 120; ++i) {
        const Vec3 p = r.fr.R0 * rigid::grioli_rotation(r.fr.g, 2 * pi * i / 120 / r.fr.g.alpha) * r.fr.g.z0;
        path.push_back({p.x(), p.y(), p.z()});
    }
    fig.data(path);
    fig.data({{G.x(), G.y(), G.z()}});
    fig.data({{-1.4, 0, -0.8}, {1.4, 0, -0.8}, {1.4, 0, 1.5}, {-1.4, 0, 1.5}, {-1.4, 0, -0.8}});
}

void draw(kit::Scene& scene, const Result& r) {
    kit::Figure fig(scene, "grioli_frames.svg", 1300, 640);
    if (!fig.enabled()) return;
    const Frames& fr = r.fr;
    const Vec3 k = fr.R0 * fr.g.k, b = fr.R0 * fr.g.b;
    const Mat3 e = fr.R0 * fr.E, &A2 = fr.fig2.axes, &A3 = fr.fig3.axes;
    const std::string black = "#000000", blue = "#0072B2", red = "#D55E00", grey = "#777777", green = "#009E73",
                      purple = "#CC79A7", sky = "#56B4E9";
    fig.script(kit::gp::grioli_frames);
    const double L = 1.3;
    panel(fig, r, "[P] Figure 2: t = −T/4",
          {{1.45 * k, "k", black, Vec3(0.05, 0, 0.05)},
           {L * e.col(0), "e_1 = a", grey, Vec3(0.0, 0, -0.15), "lw 1.5 dt 2"},
           {L * e.col(1), "e_2 = b", blue, Vec3(0.06, 0, 0.04), "lw 1.5 dt 2"},
           {L * e.col(2), "e_3 = [a, b]", red, Vec3(-0.2, 0, 0.08), "lw 1.5 dt 2"},
           {1.0 * A2.col(0), "R_A", green, Vec3(-0.14, 0, 0.05)},
           {1.0 * A2.col(1), "R_B", purple, Vec3(-0.3, 0, 0.02)},
           {1.0 * A2.col(2), "R_C", sky, Vec3(0.05, 0, -0.1)}},
          fr.fig2.z);
    fig.script(kit::gp::next_panel);
    panel(fig, r, "[P] Figure 3: t = 0",
          {{1.45 * k, "k", black, Vec3(0.05, 0, 0.05)},
           {L * b, "b", blue, Vec3(0.06, 0, 0.04), "lw 1.5 dt 2"},
           {L * fr.fig3.z, "a = z(0)", red, Vec3(0.0, 0, -0.15), "lw 1.5 dt 2"},
           {1.0 * A3.col(0), "R_A", green, Vec3(-0.14, 0, 0.05)},
           {1.0 * A3.col(1), "R_B", purple, Vec3(-0.2, 0, 0.0)},
           {1.0 * A3.col(2), "R_C", sky, Vec3(-0.12, 0, 0.08)}},
          fr.fig3.z);
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("grioli_frames",
                      "Chapter 5: the paper's Figures 2 and 3, one Grioli precession at t = -T/4 and t = 0");
    kit::heavy_body_options(opts, p.body);
    return kit::run(argc, argv, opts, [&](const kit::Options&, kit::Scene& scene) {
        const Result r = compute(p);
        report(scene, r);
        draw(scene, r);
    });
}
