// Chapter 5 scene: the two regular precessions of Theorem 1 (the paper's Figure 4): the paths
// of the centre of mass and of the tip of the intermediate axis R_B, in a lab whose vertical
// is e3, over one period, for the counter-clockwise and the clockwise sense.
//
// Both bodies start in the position of Item II (rigid::place_item_II). Their paths come from
// an integration of the Euler-Poisson equations (3.1)-(3.2), drawn as points, on top of the
// curves of R^b(sigma alpha t) R^a(sigma alpha t) R0. The error is the largest distance
// between the two, over both senses.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "figure.hpp"
#include "grioli_paths.gp.hpp"
#include "heavy_body.hpp"
#include "motion.hpp"
#include "precession.hpp"
#include "rigid/grioli.hpp"
#include "rigid/heavy_top.hpp"
#include "rigid/ode.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"
#include "stability.hpp"

using rigid::Mat3;
using rigid::Vec3;
using rigid::VecX;
using std::numbers::pi;

namespace {

struct Paths {
    std::vector<Vec3> cm, tip, cm_exact, tip_exact;
};

// snippet: ch05_paths
// Integrates the body placed by Item II for one period and records, in the lab, the centre of
// mass R(t) z(0) and the tip of the intermediate axis R(t) e_B, integrated and exact.
Paths paths(const rigid::Moments& m, double f, rigid::Sense sense, int samples) {
    const rigid::LabPlacement p = rigid::place_item_II(m, f, sense, Vec3::UnitZ(), Vec3::UnitX());
    const rigid::GrioliPrecession g = rigid::grioli_precession(m, f, sense);
    const double s = sense == rigid::Sense::ccw ? 1.0 : -1.0, T = 2 * pi / p.alpha;
    Paths out;
    // In the inertia frame, R(0) = 1: Euler's equations on the gaps (Chapter 6 says why).
    rigid::integrate_gsl(
        [&](double, const VecX& y) {
            return rigid::pack(rigid::euler_poisson_rhs_gaps(m, g.f, g.k, g.z0, rigid::unpack(y)));
        },
        rigid::pack(rigid::grioli_initial_state(g)), rigid::linspace(0, T, samples),
        [&](double t, const VecX& y) {
            const Mat3 R_lab = p.R0 * rigid::unpack(y).R;  // body -> inertia frame at 0 -> lab
            const Mat3 R_exact = kit::precession_rotation({p.a, s * p.alpha, p.b, s * p.alpha}, t) * p.R0;
            out.cm.push_back(R_lab * g.z0);
            out.tip.push_back(R_lab * Vec3::UnitY());
            out.cm_exact.push_back(R_exact * g.z0);
            out.tip_exact.push_back(R_exact * Vec3::UnitY());
        },
        {.method = "rk8pd", .rel_tol = 1e-12, .abs_tol = 1e-12 * std::min(1.0, p.alpha)});
    return out;
}
// end snippet

std::vector<std::vector<double>> rows(const std::vector<Vec3>& v) {
    std::vector<std::vector<double>> r;
    for (const Vec3& x : v) r.push_back({x.x(), x.y(), x.z()});
    return r;
}

struct Params {
    kit::HeavyBody body;
    int samples = 240;
    std::string motion_file;  // --motion: the book's viewer data (motion.hpp)
};

void declare(kit::Options& opts, Params& p) {
    kit::heavy_body_options(opts, p.body)
        .integer("samples", &p.samples, "points per period", 16, 100000)
        .file("motion", &p.motion_file, kit::motion_help);
}

// The two precessions' paths, and the counter-clockwise one's placement in the lab.
struct Both {
    Paths ccw, cw;
    rigid::LabPlacement p;
    double run_time;
};

Both compute(const kit::Options& o, const Params& prm) {
    const rigid::Moments m = kit::grioli_moments(prm.body.moments);
    const double f = prm.body.f;
    // Three timed runs of both senses and one more for the stability's steps (report_stability),
    // about 2e-6 s an output point, and the monodromy matrix counted in the same units.
    kit::require_budget(
        o, {7.0 * prm.samples + kit::monodromy_seconds(kit::monodromy_tol) / 2e-6, 2e-6, "output points", "--samples"});
    Both r;
    r.run_time = kit::min_time(
        [&] {
            r.ccw = paths(m, f, rigid::Sense::ccw, prm.samples);
            r.cw = paths(m, f, rigid::Sense::cw, prm.samples);
        },
        3);
    r.p = rigid::place_item_II(m, f, rigid::Sense::ccw, Vec3::UnitZ(), Vec3::UnitX());
    return r;
}

// The stability of the precession the paths follow (the clockwise one, its time reversal, has the
// same multipliers; Chapter 7 checks it). Over one period no instability grows a deviation by more
// than |mu|, 1.43 at most over Chapter 7's map of shapes: the report says which the precession is,
// and that the error is not the instability's. The steps are those of the same integration (Item
// II's body in its inertia frame, rk8pd at 1e-12, the same output times), run once more.
void report_stability(kit::Scene& scene, const Params& prm, double err) {
    const rigid::Moments m = kit::grioli_moments(prm.body.moments);
    const rigid::GrioliPrecession g = rigid::grioli_precession(m, prm.body.f, rigid::Sense::ccw);
    const rigid::PrecessionCheck c = rigid::integrate_grioli(
        m, g, 1, prm.samples, {.method = "rk8pd", .rel_tol = 1e-12, .abs_tol = 1e-12 * std::min(1.0, g.alpha)});
    kit::report_stability(scene.report, m, rigid::Sense::ccw, {1, err, 1e-12, kit::rk8pd_steps(c.stats.rhs_calls)});
}

// Returns the error it reports.
double report(kit::Scene& scene, const Both& r) {
    double err = 0;
    for (const Paths* P : {&r.ccw, &r.cw})
        for (std::size_t i = 0; i < P->cm.size(); ++i)
            err = std::max({err, (P->cm[i] - P->cm_exact[i]).norm(), (P->tip[i] - P->tip_exact[i]).norm()});
    scene.report.headline("max distance between integrated and exact paths of G and of the tip of R_B (unit lengths)",
                          err, r.run_time);
    scene.report.add("alpha", r.p.alpha);
    scene.report.add("b", r.p.b, "lab, k = e3");
    scene.report.add("a", r.p.a, "lab");
    scene.report.add("cm_height", r.p.z0.z(), "k.z(0): the centre of mass starts level with O");
    double lowest = 1, highest = -1;
    for (const Vec3& x : r.ccw.cm_exact) lowest = std::min(lowest, x.z()), highest = std::max(highest, x.z());
    scene.report.add("cm_height_range", std::vector<double>{lowest, highest}, "+- sin(theta): G circles b");
    return err;
}

std::string xyz(const Vec3& v) {
    return std::to_string(v.x()) + "," + std::to_string(v.y()) + "," + std::to_string(v.z());
}

// One panel: k, b, arrows along both paths, the paths integrated and exact, their starts.
void draw_panel(kit::Figure& fig, const Paths& P, const Vec3& b, int panel) {
    const char* names[] = {"counter-clockwise: R^b(αt) R^a(αt)", "clockwise: R^b(-αt) R^a(-αt)"};
    fig.script(kit::gp::panel, {{"title", names[panel]}, {"b", xyz(1.2 * b)}, {"b_label", xyz(1.25 * b)}});
    // Arrows along both paths show the sense of motion: the clockwise paths are the same
    // curves, run backwards.
    int id = 10;
    for (const std::vector<Vec3>* path : {&P.cm_exact, &P.tip_exact})
        for (std::size_t i = path->size() / 8; i + 8 < path->size(); i += path->size() / 4)
            fig.script(kit::gp::sense_arrow,
                       {{"n", std::to_string(id++)}, {"from", xyz((*path)[i])}, {"to", xyz((*path)[i + 8])}});
    // Start markers: where G and the tip are at t = 0.
    auto title = [&](const char* text) { return panel ? std::string("''") : kit::quoted(text); };
    fig.script(kit::gp::curves, {{"G_exact", title("G, exact")},
                                 {"G_integrated", title("G, integrated")},
                                 {"tip_exact", title("tip of R_B, exact")},
                                 {"tip_integrated", title("tip of R_B, integrated")},
                                 {"start", title("t = 0")}});
    std::vector<std::vector<double>> thin_cm, thin_tip;
    for (std::size_t i = 0; i < P.cm.size(); i += 6) {
        thin_cm.push_back({P.cm[i].x(), P.cm[i].y(), P.cm[i].z()});
        thin_tip.push_back({P.tip[i].x(), P.tip[i].y(), P.tip[i].z()});
    }
    fig.data(rows(P.cm_exact)).data(thin_cm).data(rows(P.tip_exact)).data(thin_tip);
    fig.data({{P.cm_exact[0].x(), P.cm_exact[0].y(), P.cm_exact[0].z()},
              {},
              {P.tip_exact[0].x(), P.tip_exact[0].y(), P.tip_exact[0].z()}});
}

void draw(kit::Scene& scene, const Both& r) {
    kit::Figure fig(scene, "two_precessions.svg", 1000, 600);
    if (!fig.enabled()) return;
    fig.script(kit::gp::grioli_paths);
    draw_panel(fig, r.ccw, r.p.b, 0);
    draw_panel(fig, r.cw, r.p.b, 1);
    fig.finish();
}

// The book's motion viewer: the two senses side by side in one lab (k up), two periods of
// R(t) = R^b(sigma alpha t) R^a(sigma alpha t) R0, the curves the integration is checked against.
void write_two_motions(kit::Scene& scene, const std::string& file, const rigid::Moments& m, double f, double err) {
    if (file.empty()) return;
    std::vector<kit::Motion> bodies;
    for (const rigid::Sense sense : {rigid::Sense::ccw, rigid::Sense::cw}) {
        const rigid::LabPlacement p = rigid::place_item_II(m, f, sense, Vec3::UnitZ(), Vec3::UnitX());
        const rigid::GrioliPrecession g = rigid::grioli_precession(m, f, sense);
        const double s = sense == rigid::Sense::ccw ? 1.0 : -1.0, T = 2 * pi / p.alpha;
        kit::Motion b;
        b.label = s > 0 ? "left: counter-clockwise, R^b(αt) R^a(αt) R0" : "right: clockwise, R^b(−αt) R^a(−αt) R0";
        b.title = "the two regular precessions of Theorem 1 in one lab, k up (left counter-clockwise, right clockwise)";
        b.parameters = fmt::format("A = {:g}, B = {:g}, C = {:g}, f = {:g}; two periods 2π/α", m.A, m.B, m.C, f);
        b.error = err;
        b.error_measure = "max distance between the integrated and these exact paths of G and of the tip of R_B";
        b.moments = {m.A, m.B, m.C};
        b.size = 0.55;
        b.centre_of_mass = g.z0;
        b.fixed_point = Vec3(s > 0 ? -1.7 : 1.7, 0, 0);
        b.speed = T / 8;
        for (int i = 0; i <= 400; ++i) {
            const double t = 2 * T * i / 400;
            b.sample(t,
                     rigid::rotation_about(p.b, s * p.alpha * t) * rigid::rotation_about(p.a, s * p.alpha * t) * p.R0);
        }
        bodies.push_back(std::move(b));
    }
    kit::write_motion(scene, file, bodies);
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts(
        "grioli_paths",
        "Chapter 5: the two regular precessions (the paper's Figure 4), paths of G and of the tip of R_B");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        const Both r = compute(o, p);
        const double err = report(scene, r);
        report_stability(scene, p, err);
        write_two_motions(scene, p.motion_file, kit::grioli_moments(p.body.moments), p.body.f, err);
        draw(scene, r);
    });
}
