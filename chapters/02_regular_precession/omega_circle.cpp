// Chapter 2 scene: the body angular velocity of a regular precession [P, (1.4)-(1.7)].
//
// Omega(t) is computed twice: from the closed form (1.5), and from R(t) alone by an
// eighth-order central difference and (1.1.1). Along one period it checks what [P] says is
// constant: |Omega|^2 (1.6) and (a, Omega) (1.7), and fits a plane and a circle to Omega(t).
// Then it sweeps the angle between a and b and compares the measured |Omega|^2 with the
// value (1.6) prints, (alpha + beta)^2, and with alpha^2 + beta^2 + 2 alpha beta (a, b).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "common.hpp"
#include "figure.hpp"
#include "omega_circle.gp.hpp"
#include "rigid/precession.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

using rigid::Mat3;
using rigid::RegularPrecession;
using rigid::Vec3;

namespace {

// Omega at t from R(t) alone: the difference quotient of R, then (1.1.1).
Vec3 omega_from_rotations(const RegularPrecession& p, double t, double h) {
    return rigid::body_angular_velocity(rigid::precession_rotation(p, t), ch2::rotation_rate(p, t, h));
}

struct Params {
    Vec3 a = Vec3(0, 0, 1), b = Vec3(std::sqrt(3.0) / 2, 0, 0.5);
    double alpha = 2.0, beta = 1.0;
    int samples = 200;
};

void declare(kit::Options& opts, Params& p) {
    opts.vector("a", &p.a, "rotation vector a (normalised)", kit::nonzero_vector(-1e6, 1e6))
        .vector("b", &p.b, "precession vector b (normalised)", kit::nonzero_vector(-1e6, 1e6))
        .real("alpha", &p.alpha, "rotation frequency alpha", kit::between(1e-6, 1e6))
        .real("beta", &p.beta, "precession frequency beta", kit::between(1e-6, 1e6))
        .integer("samples", &p.samples, "instants sampled over one period 2 pi / alpha", 8, 100000);
}

RegularPrecession precession(const kit::Options& o, const Params& prm) {
    const RegularPrecession p{prm.a.normalized(), prm.alpha, prm.b.normalized(), prm.beta};
    // The differences of R are taken over h = 0.02 / (alpha + beta) at times up to 2 pi / alpha:
    // for beta >> alpha the sum t + j h keeps only the leading digits of h (round-off
    // eps t / h), and for beta << alpha the circle's radius beta |a x b| drowns in that noise.
    if (!(p.beta <= 1e3 * p.alpha && p.beta >= 1e-3 * p.alpha))
        throw kit::BadInput("--alpha, --beta: beta / alpha = " + std::to_string(p.beta / p.alpha) +
                            "; it must be between 1e-3 and 1e3 (the finite differences of R lose their digits beyond)");
    if (!(p.a.cross(p.b).norm() >= 1e-3))
        throw kit::BadInput(
            "--a, --b: the angle between a and b must be at least 1e-3 rad (the circle of Omega has radius "
            "beta |a x b|, and the fitted circle needs one)");
    kit::require_budget(o, {double(prm.samples) * 20 + 37 * 3 * 16, 2e-7, "rotations R(t)", "--samples"});
    return p;
}

// Omega(t) over one period: closed form (timed) and from R(t) alone.
struct Period {
    double period, h;
    std::vector<Vec3> closed, fd;
    double run_time;
};

Period compute(const RegularPrecession& p, int samples) {
    Period r{2 * std::numbers::pi / p.alpha, 0.02 / (p.alpha + p.beta),  // h balanced for the eighth-order formula
             std::vector<Vec3>(samples), std::vector<Vec3>(samples), 0};
    r.run_time = kit::min_time([&] {
        for (int k = 0; k < samples; ++k)
            r.closed[k] = rigid::precession_body_angular_velocity(p, r.period * k / samples);
        kit::keep(r.closed);
    });
    for (int k = 0; k < samples; ++k) r.fd[k] = omega_from_rotations(p, r.period * k / samples, r.h);
    return r;
}

void report_period(kit::Scene& scene, const RegularPrecession& p, const Period& r) {
    const auto samples = r.fd.size();
    const double printed = (p.alpha + p.beta) * (p.alpha + p.beta);  // [P, (1.6)] as printed
    const double w2 = rigid::precession_omega_squared(p);
    const double axial = rigid::precession_axial_component(p);
    const rigid::Circle c = rigid::precession_omega_circle(p);
    double err = 0, w2_min = 1e300, w2_max = 0, ax_dev = 0, circ_dev = 0;
    for (std::size_t k = 0; k < samples; ++k) {
        const Vec3& fd = r.fd[k];
        err = std::max(err, (r.closed[k] - fd).norm() / fd.norm());
        w2_min = std::min(w2_min, fd.squaredNorm());
        w2_max = std::max(w2_max, fd.squaredNorm());
        ax_dev = std::max(ax_dev, std::abs(p.a.dot(fd) - axial));
        const Vec3 d = fd - c.centre;
        circ_dev = std::max(circ_dev, std::hypot(d.dot(c.normal), (d - d.dot(c.normal) * c.normal).norm() - c.radius));
    }
    const rigid::CircleFit fit = rigid::fit_circle(r.fd);
    scene.report.headline("max |Omega (1.5) - Omega from finite differences of R(t)| / |Omega| over one period", err,
                          r.run_time / double(samples));
    scene.report.add("a_dot_b", p.a.dot(p.b), "(a, b)");
    scene.report.add("omega2_measured_min", w2_min, "min over t of |Omega_fd|^2");
    scene.report.add("omega2_measured_max", w2_max, "max over t of |Omega_fd|^2");
    scene.report.add("omega2_printed", printed, "(alpha + beta)^2, [P, (1.6)] as printed");
    scene.report.add("omega2_corrected", w2, "alpha^2 + beta^2 + 2 alpha beta (a, b)");
    scene.report.add("axial_component", axial, "alpha + beta (a, b), [P, (1.7)]");
    scene.report.add("axial_deviation", ax_dev, "max |(a, Omega_fd) - (1.7)|");
    scene.report.add("circle_radius", c.radius, "beta |a x b|");
    scene.report.add("circle_deviation", circ_dev, "max distance of Omega_fd from the predicted circle");
    scene.report.add("fit_plane_residual", fit.plane_residual, "best-fit plane, max distance");
    scene.report.add("fit_circle_residual", fit.circle_residual, "best-fit circle, max radial miss");
    scene.report.add("fit_normal_dot_a", std::abs(fit.circle.normal.dot(p.a)));
}

// The sweep over the angle between a and b: (1.6) printed against measured. Rows: angle (deg),
// (a, b), measured, corrected, printed.
std::vector<std::vector<double>> angle_sweep(kit::Scene& scene, const RegularPrecession& p, const Period& r) {
    const double printed = (p.alpha + p.beta) * (p.alpha + p.beta);
    std::vector<std::vector<double>> sweep;
    double worst_formula = 0;
    for (int k = 0; k <= 36; ++k) {
        const double theta = std::numbers::pi * k / 36;
        const Vec3 u = p.a.unitOrthogonal();
        const RegularPrecession q{p.a, p.alpha, std::cos(theta) * p.a + std::sin(theta) * u, p.beta};
        double measured = 0;
        for (double t : {0.0, 0.31 * r.period, 0.77 * r.period})
            measured = std::max(measured, omega_from_rotations(q, t, r.h).squaredNorm());
        const double formula = rigid::precession_omega_squared(q);
        worst_formula = std::max(worst_formula, std::abs(formula - measured) / measured);
        sweep.push_back({theta * 180 / std::numbers::pi, std::cos(theta), measured, formula, printed});
    }
    scene.report.add("sweep_worst_relative_miss", worst_formula, "max |corrected (1.6) - measured| / measured");
    scene.report.table("omega2_vs_angle", {"angle_deg", "a_dot_b", "measured", "corrected", "printed"}, sweep, false);
    return sweep;
}

void draw_circle(kit::Scene& scene, const RegularPrecession& p, const Period& r) {
    kit::Figure fig(scene, "omega_circle.svg", 760, 700);
    if (!fig.enabled()) return;
    const int samples = static_cast<int>(r.fd.size());
    const std::vector<Vec3>& fd = r.fd;
    const rigid::Circle c = rigid::precession_omega_circle(p);
    fig.script(kit::gp::circle);
    const double top = std::max(1.3 * rigid::precession_axial_component(p), 1.0);
    fig.data({{0, 0, 0}, {top * p.a.x(), top * p.a.y(), top * p.a.z()}});
    std::vector<std::vector<double>> rays, circle, pts;
    for (int k = 0; k < samples; k += std::max(1, samples / 24)) {
        rays.push_back({0, 0, 0});
        rays.push_back({fd[k].x(), fd[k].y(), fd[k].z()});
        rays.push_back({});
        rays.push_back({});
    }
    const Vec3 u = c.normal.unitOrthogonal(), v = c.normal.cross(u);
    for (int k = 0; k <= 200; ++k) {
        const double th = 2 * std::numbers::pi * k / 200;
        const Vec3 x = c.centre + c.radius * (std::cos(th) * u + std::sin(th) * v);
        circle.push_back({x.x(), x.y(), x.z()});
    }
    for (int k = 0; k < samples; k += std::max(1, samples / 60)) pts.push_back({fd[k].x(), fd[k].y(), fd[k].z()});
    fig.data(rays).data(circle).data(pts);
    fig.finish();
}

void draw_sweep(kit::Scene& scene, const std::vector<std::vector<double>>& sweep) {
    kit::Figure f2(scene, "omega_squared_vs_angle.svg");
    f2.script(kit::gp::squared_vs_angle);
    std::vector<std::vector<double>> pr, co, me;
    for (const auto& r : sweep) {
        pr.push_back({r[0], r[4]});
        co.push_back({r[0], r[3]});
        me.push_back({r[0], r[2]});
    }
    f2.data(pr).data(co).data(me);
    f2.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params prm;
    kit::Options opts("omega_circle", "Chapter 2: Omega(t) of a regular precession, its circle, and (1.6)-(1.7)");
    declare(opts, prm);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        const RegularPrecession p = precession(o, prm);
        const Period r = compute(p, prm.samples);
        report_period(scene, p, r);
        const auto sweep = angle_sweep(scene, p, r);
        draw_circle(scene, p, r);
        draw_sweep(scene, sweep);
    });
}
