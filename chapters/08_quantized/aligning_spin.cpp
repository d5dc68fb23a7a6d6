// Chapter 8 scene: the nonlinear spin equation (6.2). From any initial angle S lines up with B
// (acute start) or against it (obtuse start), while it precesses about B; with beta = 0 it only
// precesses and keeps its angle. The student's (6.2) is integrated by rk8pd and compared with the
// exact solution (spin_exact); the scene also measures the claims of [P, Sect. 7]: |S| constant,
// the sense and rate of the precession, the motion in the plane of B and S, the rate of
// alignment, and the 90-degree start.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "aligning_spin.gp.hpp"
#include "figure.hpp"
#include "quantized_scene.hpp"
#include "rigid/ode.hpp"
#include "rigid/quantized.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

using rigid::Vec3;
using rigid::VecX;
using std::numbers::pi;

namespace {

// A number as printf's %g writes it (the figures' titles and keys).
std::string gnum(double x) {
    char s[32];
    std::snprintf(s, sizeof s, "%g", x);
    return s;
}

Vec3 vec(const VecX& y) { return Vec3(y(0), y(1), y(2)); }
VecX vecx(const Vec3& v) { return VecX{{v(0), v(1), v(2)}}; }

// The least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
    const double n = double(x.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// The scene's parameters, bound to its options.
struct Params {
    Vec3 B{0.3, -0.4, 1.2};
    double e_over_mc = 2.0, beta = 0.5, S = 1.0, T = 12;
    long outputs = 600, repeats = 3;
};

void declare(kit::Options& opts, Params& p) {
    opts.vector("B", &p.B, "the magnetic field B", kit::nonzero_vector(-1e3, 1e3))
        .real("e_over_mc", &p.e_over_mc, "e/mc (either sign: the sign of the charge)", kit::between(-1e3, 1e3))
        .real("beta", &p.beta, "beta, the strength of the aligning term (0: plain precession)", kit::between(0, 1e3))
        .real("S", &p.S, "the length of the spin |S|", kit::between(1e-3, 1e3))
        .real("T", &p.T, "time span", kit::between(1e-2, 1e6))
        .integer("outputs", &p.outputs, "output times", 10, 100000)
        .integer("repeats", &p.repeats, "timing repetitions (the minimum is kept)", 1, 50);
}

// The field, its frame (e1, e2, b) with b along B, and the precession rate about b.
struct Setup {
    rigid::SpinField field, plain;  // (6.2), and the same with beta = 0
    double s, T, Bn;
    int repeats;
    std::vector<double> times;
    Vec3 b, e1, e2;
    double omega_L, period;
    // S(0) at `deg` degrees from B, of length |S|.
    Vec3 start(double deg) const { return s * (std::cos(deg * pi / 180) * b + std::sin(deg * pi / 180) * e1); }
};

Setup setup(const kit::Options& o, const Params& p) {
    Setup u;
    u.field = {p.B, p.e_over_mc, p.beta};
    u.plain = u.field;
    u.plain.beta = 0;
    u.s = p.S, u.T = p.T, u.Bn = u.field.B.norm();
    u.repeats = static_cast<int>(p.repeats);
    u.times = rigid::linspace(0, u.T, static_cast<int>(p.outputs));
    u.b = u.field.B.normalized(), u.e1 = u.b.unitOrthogonal(), u.e2 = u.b.cross(u.e1);
    u.omega_L = -u.field.e_over_mc * u.Bn;  // the precession rate about b
    u.period = u.omega_L != 0 ? 2 * pi / std::abs(u.omega_L) : u.T;
    // The work: 12 starting angles, (6.2) `repeats` times and beta = 0 once, over T; the
    // phase turned is (|omega_L| + beta |B| |S|) T radians a run.
    kit::require_budget(o, {12.0 * (u.repeats + 1) * (std::abs(u.omega_L) + u.field.beta * u.Bn * u.s) * u.T + 200,
                            6e-5, "radians of phase", "--T, --B, --e_over_mc, --beta, --S, --repeats"});
    kit::require_budget(
        o, {12.0 * (u.repeats + 1) * double(u.times.size()), 3e-6, "output times (all runs)", "--outputs, --repeats"});
    return u;
}

// The fan of initial angles, with (6.2) and with beta = 0: the angle curves and the errors.
struct Fan {
    std::vector<double> degrees{5, 20, 40, 60, 80, 89, 91, 100, 120, 140, 160, 175};
    std::vector<std::vector<std::vector<double>>> angle_curves, plain_curves;
    std::vector<std::vector<double>> finals;  // start deg, final deg (beta), final deg (beta = 0)
    double err = 0, err_plain = 0, norm_drift = 0, off_plane = 0, plain_angle_drift = 0, run_time = 0;
};

Fan integrate_fan(const Setup& u) {
    Fan f;
    const auto& times = u.times;
    for (double deg : f.degrees) {
        const Vec3 S0 = u.start(deg);
        scene8::Run run, run0;
        f.run_time += kit::min_time(
            [&] { run = scene8::integrate(rigid::spin_equations(u.field), vecx(S0), times, "rk8pd", 1e-12); },
            u.repeats);
        run0 = scene8::integrate(rigid::spin_equations(u.plain), vecx(S0), times, "rk8pd", 1e-12);
        const Vec3 n_plane = u.b.cross(S0).normalized();
        std::vector<std::vector<double>> c, c0;
        for (std::size_t i = 0; i < times.size(); ++i) {
            const Vec3 S = vec(run.y[i]), P = vec(run0.y[i]);
            if (!S.allFinite()) throw kit::NumericalFailure("S is not finite at t = " + std::to_string(times[i]));
            f.err = std::max(f.err, (S - rigid::spin_exact(u.field, S0, times[i])).norm() / u.s);
            f.err_plain = std::max(f.err_plain, (P - rigid::spin_exact(u.plain, S0, times[i])).norm() / u.s);
            f.norm_drift = std::max(f.norm_drift, std::abs(S.norm() - u.s) / u.s);
            // Undo the precession: what is left must stay in the plane of B and S0.
            const Vec3 back = rigid::rotation_about(u.b, -u.omega_L * times[i]) * S;
            f.off_plane = std::max(f.off_plane, std::abs(back.dot(n_plane)) / u.s);
            const double th = rigid::spin_angle(u.field.B, S) * 180 / pi,
                         th0 = rigid::spin_angle(u.field.B, P) * 180 / pi;
            f.plain_angle_drift = std::max(f.plain_angle_drift, std::abs(th0 - deg));
            c.push_back({times[i], th});
            c0.push_back({times[i], th0});
        }
        f.angle_curves.push_back(c), f.plain_curves.push_back(c0);
        f.finals.push_back({deg, f.angle_curves.back().back()[1], f.plain_curves.back().back()[1]});
    }
    return f;
}

void report_fan(kit::Report& report, const Fan& f) {
    report.headline(
        "max |S(t) - S_exact(t)| / |S| over a fan of 12 initial angles, the student's (6.2) "
        "integrated by rk8pd at tol 1e-12",
        f.err, f.run_time);
    report.add("error_beta_0", f.err_plain, "the same for beta = 0 against the exact precession R^B(-(e/mc)|B|t) S0");
    report.add("norm_drift", f.norm_drift, "max | |S(t)| - |S(0)| | / |S|");
    report.add("out_of_plane", f.off_plane,
               "max distance from the plane of B and S0 after undoing the precession, / |S|");
    report.add("angle_drift_beta_0", f.plain_angle_drift, "degrees: beta = 0 keeps the angle");
    report.table("final_angles", {"start_deg", "final_deg", "final_deg_beta_0"}, f.finals);
}

// The precession: its sense and rate, from the azimuth of S about b (beta = 0, 60 degrees).
void report_precession_rate(kit::Report& report, const Setup& u) {
    const auto fine = rigid::linspace(0, std::min(u.T, 0.9 * u.period), 200);
    const scene8::Run run = scene8::integrate(rigid::spin_equations(u.plain), vecx(u.start(60)), fine, "rk8pd", 1e-12);
    std::vector<double> phi;
    double prev = 0, turn = 0;
    for (std::size_t i = 0; i < fine.size(); ++i) {
        const Vec3 S = vec(run.y[i]);
        double a = std::atan2(S.dot(u.e2), S.dot(u.e1));
        if (i > 0 && a - prev > pi) turn -= 2 * pi;
        if (i > 0 && a - prev < -pi) turn += 2 * pi;
        prev = a;
        phi.push_back(a + turn);
    }
    const double rate = slope(fine, phi);
    report.add("precession_rate_measured", rate, "d(azimuth about B)/dt, counter-clockwise > 0");
    report.add("precession_rate_predicted", u.omega_L, "-(e/mc)|B|");
    if (u.omega_L != 0) report.add("precession_rate_mismatch", std::abs(rate / u.omega_L - 1), "relative");
}

// The rate of alignment: ln tan(theta) falls at beta |B| (40 degrees, while 1e-9 < theta < 0.5);
// and 90 degrees, an equilibrium of the angle, left at the same rate beta |B|.
void report_alignment(kit::Report& report, const Setup& u) {
    if (!(u.field.beta > 0)) return;
    const auto& field = u.field;
    const auto fine = rigid::linspace(0, u.T, 400);
    const scene8::Run run = scene8::integrate(rigid::spin_equations(field), vecx(u.start(40)), fine, "rk8pd", 1e-13);
    std::vector<double> t, l;
    for (std::size_t i = 0; i < fine.size(); ++i) {
        const double th = rigid::spin_angle(field.B, vec(run.y[i]));
        if (th > 1e-9 && th < 0.5) t.push_back(fine[i]), l.push_back(std::log(std::tan(th)));
    }
    if (t.size() >= 5) {
        report.add("alignment_rate_measured", -slope(t, l), "-d ln tan(theta)/dt at 40 degrees");
        report.add("alignment_rate_mismatch", std::abs(-slope(t, l) / (field.beta * u.Bn) - 1), "relative");
    }
    report.add("alignment_rate_predicted", field.beta * u.Bn, "beta |B|");

    const scene8::Run eq = scene8::integrate(rigid::spin_equations(field), vecx(u.s * u.e1), fine, "rk8pd", 1e-13);
    double stays = 0;
    for (const auto& y : eq.y) stays = std::max(stays, std::abs(vec(y).dot(u.b)) / u.s);
    report.add("equator_stays", stays, "started at exactly 90 degrees: max |cos theta|");
    const scene8::Run off =
        scene8::integrate(rigid::spin_equations(field), vecx(u.start(90 - 1e-7)), fine, "rk8pd", 1e-13);
    std::vector<double> t2, l2;
    for (std::size_t i = 0; i < fine.size(); ++i) {
        const double d = std::abs(rigid::spin_angle(field.B, vec(off.y[i])) - pi / 2);
        if (d > 1e-8 && d < 0.1) t2.push_back(fine[i]), l2.push_back(std::log(d));
    }
    if (t2.size() >= 5) {
        report.add("equator_escape_rate", slope(t2, l2), "d ln|theta - 90 deg|/dt from 90 - 1e-7 deg");
        report.add("equator_rate_mismatch", std::abs(slope(t2, l2) / (field.beta * u.Bn) - 1), "relative");
    }
}

void draw_angles(kit::Scene& scene, const Setup& u, const Fan& f) {
    kit::Figure fig(scene, "spin_alignment.svg", 820, 520);
    if (!fig.enabled()) return;
    std::vector<kit::Fill> after_first;  // the first start's curves are in the script, with their key entries
    for (std::size_t j = 1; j < f.degrees.size(); ++j) after_first.push_back({{"ls", std::to_string(j % 8 + 1)}});
    fig.script(kit::gp::alignment, {{"beta", gnum(u.field.beta)},
                                    {"B", gnum(u.Bn)},
                                    {"e_over_mc", gnum(u.field.e_over_mc)},
                                    {"solid", kit::joined(kit::gp::solid, after_first, "")},
                                    {"plain", kit::joined(kit::gp::plain, after_first, "")}});
    for (const auto& c : f.angle_curves) fig.data(c);
    for (const auto& c : f.plain_curves) fig.data(c);
    fig.finish();
}

// The unit sphere's parallels and meridians, as gnuplot line segments.
std::vector<std::vector<double>> sphere_grid() {
    std::vector<std::vector<double>> sphere;
    for (int lat = -60; lat <= 60; lat += 30) {
        for (int k = 0; k <= 72; ++k) {
            const double a = 2 * pi * k / 72, c = std::cos(lat * pi / 180);
            sphere.push_back({c * std::cos(a), c * std::sin(a), std::sin(lat * pi / 180)});
        }
        sphere.push_back({});
        sphere.push_back({});
    }
    for (int lon = 0; lon < 180; lon += 30) {
        for (int k = 0; k <= 72; ++k) {
            const double a = 2 * pi * k / 72;
            sphere.push_back(
                {std::cos(a) * std::cos(lon * pi / 180), std::cos(a) * std::sin(lon * pi / 180), std::sin(a)});
        }
        sphere.push_back({});
        sphere.push_back({});
    }
    return sphere;
}

void draw_sphere(kit::Scene& scene, const Setup& u) {
    kit::Figure fs(scene, "spin_sphere.svg", 700, 520);
    if (!fs.enabled()) return;
    // Draw in coordinates (e1, e2, b), so that B points up.
    auto local = [&](const Vec3& v) { return std::vector<double>{v.dot(u.e1), v.dot(u.e2), v.dot(u.b)}; };
    const std::vector<std::vector<double>> sphere = sphere_grid();
    std::vector<double> shown{30, 80, 100, 150};
    std::vector<std::vector<std::vector<double>>> paths;
    for (double deg : shown) {
        const auto fine = rigid::linspace(0, u.T, 1200);
        const scene8::Run run =
            scene8::integrate(rigid::spin_equations(u.field), vecx(u.start(deg)), fine, "rk8pd", 1e-12);
        std::vector<std::vector<double>> p;
        for (const auto& y : run.y) p.push_back(local(vec(y) / u.s));
        paths.push_back(p);
    }
    std::vector<std::vector<double>> circle;  // beta = 0 from 60 degrees: one circle
    for (int k = 0; k <= 120; ++k)
        circle.push_back(local(rigid::spin_exact(u.plain, u.start(60), u.period * k / 120) / u.s));
    std::vector<kit::Fill> curves;
    for (std::size_t j = 0; j < shown.size(); ++j)
        curves.push_back({{"ls", std::to_string(j + 1)}, {"degrees", gnum(shown[j])}});
    fs.script(kit::gp::sphere, {{"paths", kit::joined(kit::gp::path, curves, "")}});
    fs.data(sphere).data(circle);
    for (const auto& p : paths) fs.data(p);
    fs.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("aligning_spin", "Chapter 8: the spin equation (6.2) lines S up with B or against it");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&p](const kit::Options& o, kit::Scene& scene) {
        const Setup u = setup(o, p);
        const Fan fan = integrate_fan(u);
        report_fan(scene.report, fan);
        report_precession_rate(scene.report, u);
        report_alignment(scene.report, u);
        draw_angles(scene, u, fan);
        draw_sphere(scene, u);
    });
}
