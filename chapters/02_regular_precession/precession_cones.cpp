// Chapter 2 scene: the body cone rolling on the space cone, and the path of a body point, for
// three regular precessions R(t) = R^b(beta t) R^a(alpha t) [P, (1.4)-(1.5)].
//
// The lab angular velocity omega(t) = R(t) Omega(t) sweeps the space cone about b; the body
// cone (the cone of Omega(t) about a, carried by the body, i.e. R(t*) Omega(s) for all s)
// touches it along omega(t*). The scene checks omega(t) against finite differences of R(t),
// and the two constants of the space cone: |omega| and (b, omega) = beta + alpha (a, b).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "common.hpp"
#include "figure.hpp"
#include "motion.hpp"
#include "precession_cones.gp.hpp"
#include "rigid/precession.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

using rigid::Mat3;
using rigid::RegularPrecession;
using rigid::Vec3;

namespace {

// omega = vee(Rdot R^T) with the eighth-order difference quotient of R(t).
Vec3 omega_fd(const RegularPrecession& p, double t, double h) {
    return rigid::lab_angular_velocity(rigid::precession_rotation(p, t), ch2::rotation_rate(p, t, h));
}

std::vector<double> row(const Vec3& x) { return {x.x(), x.y(), x.z()}; }

// The three precessions: the angle between a and b (degrees), alpha and beta of each.
struct Case {
    double angle, alpha, beta;
};
struct Params {
    Case given[3] = {{90, 1.0, 1.0}, {35, 2.0, 0.7}, {125, 0.6, 1.5}};
    std::string motion_file;  // --motion: the book's viewer data (motion.hpp)
};

void declare(kit::Options& opts, Params& p) {
    opts.real("angle1", &p.given[0].angle, "case 1: angle between a and b (degrees)", kit::between(1, 179))
        .real("alpha1", &p.given[0].alpha, "case 1: rotation frequency alpha", kit::between(1e-6, 1e6))
        .real("beta1", &p.given[0].beta, "case 1: precession frequency beta", kit::between(1e-6, 1e6))
        .real("angle2", &p.given[1].angle, "case 2: angle between a and b (degrees)", kit::between(1, 179))
        .real("alpha2", &p.given[1].alpha, "case 2: rotation frequency alpha", kit::between(1e-6, 1e6))
        .real("beta2", &p.given[1].beta, "case 2: precession frequency beta", kit::between(1e-6, 1e6))
        .real("angle3", &p.given[2].angle, "case 3: angle between a and b (degrees)", kit::between(1, 179))
        .real("alpha3", &p.given[2].alpha, "case 3: rotation frequency alpha", kit::between(1e-6, 1e6))
        .real("beta3", &p.given[2].beta, "case 3: precession frequency beta", kit::between(1e-6, 1e6))
        .file("motion", &p.motion_file, kit::motion_help);
}

std::vector<RegularPrecession> precessions(const Params& prm) {
    const Vec3 b = Vec3::UnitZ();
    std::vector<RegularPrecession> cases;
    for (int c = 1; c <= 3; ++c) {
        const Case& g = prm.given[c - 1];
        const double th = g.angle * std::numbers::pi / 180;
        cases.push_back({Vec3(std::sin(th), 0, std::cos(th)), g.alpha, b, g.beta});
        // omega is checked by differences of R over h = 0.02 / (alpha + beta) at times up to
        // 2 pi / beta: for alpha >> beta the sum t + j h keeps only the leading digits of h.
        const double ratio = cases.back().alpha / cases.back().beta;
        if (!(ratio <= 1e3 && ratio >= 1e-3))
            throw kit::BadInput("--alpha" + std::to_string(c) + ", --beta" + std::to_string(c) +
                                ": alpha / beta = " + std::to_string(ratio) +
                                "; it must be between 1e-3 and 1e3 (the finite differences of R "
                                "lose their digits beyond)");
    }
    return cases;
}

constexpr int n = 240;  // instants over one precession period

// One case: omega(t) over a precession period (closed form, timed), and its checks against the
// finite differences of R: angle(a, b), alpha, beta, omega error (relative), the deviations of
// (b, omega) and |omega|^2, where the cones touch, and |omega|^2 = |Omega|^2 itself (1.6 as
// corrected: alpha^2 + beta^2 + 2 alpha beta (a, b), in rad^2/s^2).
struct CaseResult {
    std::vector<Vec3> omega;
    std::vector<double> row;
    double run_time;
};

CaseResult compute(const RegularPrecession& p) {
    const double Tb = 2 * std::numbers::pi / p.beta;
    const double h = 0.02 / (p.alpha + p.beta);
    CaseResult r{std::vector<Vec3>(n + 1), {}, 0};
    r.run_time = kit::min_time([&] {
                     for (int k = 0; k <= n; ++k) r.omega[k] = rigid::precession_lab_angular_velocity(p, Tb * k / n);
                     kit::keep(r.omega);
                 }) /
                 (n + 1);
    const double axial = p.beta + p.alpha * p.a.dot(p.b), w2 = rigid::precession_omega_squared(p);
    double e = 0, dev_axial = 0, dev_norm = 0;
    for (int k = 0; k <= n; k += 4) {
        const Vec3 ref = omega_fd(p, Tb * k / n, h);
        e = std::max(e, (r.omega[k] - ref).norm() / ref.norm());
        dev_axial = std::max(dev_axial, std::abs(p.b.dot(ref) - axial));
        dev_norm = std::max(dev_norm, std::abs(ref.squaredNorm() - w2));
    }
    const double t_star = 0.3 * Tb;
    const Mat3 Rs = rigid::precession_rotation(p, t_star);
    // Where the two cones touch: omega(t*) and R(t*) Omega(t*) must be the same vector.
    const double touch =
        (Rs * rigid::precession_body_angular_velocity(p, t_star) - rigid::precession_lab_angular_velocity(p, t_star))
            .norm();
    const double ab = p.a.dot(p.b);
    r.row = {std::acos(ab) * 180 / std::numbers::pi, p.alpha, p.beta, e, dev_axial, dev_norm, touch, w2};
    return r;
}

// A cone: its rim through `rim`, and a ray from the origin to every 12th point.
void cone(const std::vector<Vec3>& rim_points, std::vector<std::vector<double>>& rays,
          std::vector<std::vector<double>>& rim) {
    for (std::size_t k = 0; k < rim_points.size(); ++k) {
        rim.push_back(row(rim_points[k]));
        if (k % 12 == 0) {
            rays.push_back({0, 0, 0});
            rays.push_back(row(rim_points[k]));
            rays.push_back({});
            rays.push_back({});
        }
    }
}

void draw_case(kit::Figure& fig, const RegularPrecession& p, const CaseResult& r) {
    const double Tb = 2 * std::numbers::pi / p.beta, Ta = 2 * std::numbers::pi / p.alpha;
    const double t_star = 0.3 * Tb;
    const Mat3 Rs = rigid::precession_rotation(p, t_star);
    // Space cone: rays to omega(t) over one precession period, and its rim.
    std::vector<std::vector<double>> space_rays, space_rim, body_rays, body_rim, path, contact;
    cone(r.omega, space_rays, space_rim);
    // Body cone at t*: Omega(s) for one rotation period, carried by R(t*).
    std::vector<Vec3> body(n + 1);
    for (int k = 0; k <= n; ++k) body[k] = Rs * rigid::precession_body_angular_velocity(p, Ta * k / n);
    cone(body, body_rays, body_rim);
    // A body point on the unit sphere, off both axes, over several precession periods.
    const Vec3 x0 = (p.a.unitOrthogonal() + 0.6 * p.a).normalized() * std::sqrt(rigid::precession_omega_squared(p));
    for (int k = 0; k <= 600; ++k) path.push_back(row(rigid::precession_rotation(p, Tb * k / 600) * x0));
    const Vec3 ws = rigid::precession_lab_angular_velocity(p, t_star);
    contact = {{0, 0, 0}, row(ws)};
    char title[160];
    std::snprintf(title, sizeof title, "angle(a, b) = %.0f deg;  α = %.2g;  β = %.2g",
                  std::acos(p.a.dot(p.b)) * 180 / std::numbers::pi, p.alpha, p.beta);
    fig.script(kit::gp::panel, {{"title", kit::quoted(title)}});
    fig.data(space_rays).data(space_rim).data(body_rays).data(body_rim).data(path).data(contact);
}

void draw(kit::Scene& scene, const std::vector<RegularPrecession>& cases, const std::vector<CaseResult>& results) {
    kit::Figure fig(scene, "precession_cones.svg", 1200, 460);
    if (!fig.enabled()) return;
    fig.script(kit::gp::precession_cones);
    for (std::size_t c = 0; c < cases.size(); ++c) draw_case(fig, cases[c], results[c]);
    fig.finish();
}

void report(kit::Scene& scene, const std::vector<CaseResult>& results) {
    double err = 0, run_time = 0;
    std::vector<std::vector<double>> summary;
    for (const CaseResult& r : results) {
        err = std::max(err, r.row[3]);
        run_time += r.run_time;
        summary.push_back(r.row);
    }
    scene.report.headline("max |omega (closed form) - omega from finite differences of R(t)| / |omega|, three cases",
                          err, run_time / 3);
    scene.report.table(
        "cases",
        {"angle_ab_deg", "alpha", "beta", "omega_error", "b_dot_omega_dev", "omega2_dev", "cones_touch", "omega2"},
        summary);
    scene.report.note(
        "figure: grey = space cone (rays to omega(t)), blue = its rim; light blue = body cone at t* = 0.3 "
        "T_b, orange = its rim; green = path of a body point; black = omega(t*), where the cones touch");
    scene.report.note(
        "units: omega_error relative (dimensionless); b_dot_omega_dev and cones_touch rad/s; omega2_dev and "
        "omega2 = |omega|^2 = |Omega|^2 rad^2/s^2");
}

// The book's motion viewer: case 2 over two precession periods, with its two cones (a box
// stands for the body: the kinematics of R(t) do not depend on its moments).
void write_case_motion(kit::Scene& scene, const std::string& file, const RegularPrecession& p, double err) {
    if (file.empty()) return;
    const double Tb = 2 * std::numbers::pi / p.beta;
    const Vec3 w0 = rigid::precession_lab_angular_velocity(p, 0), W0 = rigid::precession_body_angular_velocity(p, 0);
    kit::Motion m;
    m.title = "a regular precession R(t) = R^b(βt) R^a(αt) and its two cones";
    m.parameters = fmt::format("angle(a, b) = {:.0f}°, α = {:g}, β = {:g}; the body drawn as a box",
                               std::acos(p.a.dot(p.b)) * 180 / std::numbers::pi, p.alpha, p.beta);
    m.error = err;
    m.error_measure = "max |ω (closed form) − ω from finite differences of R(t)| / |ω|";
    m.moments = {1, 2.2, 2.6};
    m.shape = "box";
    m.cones = {{"space cone (about b, fixed in the lab)", p.b, std::acos(p.b.dot(w0) / w0.norm()), false},
               {"body cone (about a, carried by the body)", p.a, std::acos(p.a.dot(W0) / W0.norm()), true}};
    for (int k = 0; k <= 400; ++k) m.sample(2 * Tb * k / 400, rigid::precession_rotation(p, 2 * Tb * k / 400));
    kit::write_motion(scene, file, m);
}

}  // namespace

int main(int argc, char** argv) {
    Params prm;
    kit::Options opts("precession_cones",
                      "Chapter 2: space and body cones, and a body point's path, for three precessions");
    declare(opts, prm);
    return kit::run(argc, argv, opts, [&](const kit::Options&, kit::Scene& scene) {
        const std::vector<RegularPrecession> cases = precessions(prm);
        std::vector<CaseResult> results;
        for (const RegularPrecession& p : cases) results.push_back(compute(p));
        draw(scene, cases, results);
        report(scene, results);
        write_case_motion(scene, prm.motion_file, cases[1], results[1].row[3]);
    });
}
