// Chapter 8 scene: the nonlinear spin equation (6.2). From any initial angle S lines up with B
// (acute start) or against it (obtuse start), while it precesses about B; with beta = 0 it only
// precesses and keeps its angle. The student's (6.2) is integrated by rk8pd and compared with the
// exact solution (spin_exact); the scene also measures the claims of [P, Sect. 7]: |S| constant,
// the sense and rate of the precession, the motion in the plane of B and S, the rate of
// alignment, and the 90-degree start.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

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

Vec3 vec(const VecX& y) { return Vec3(y(0), y(1), y(2)); }
VecX vecx(const Vec3& v) { return VecX{{v(0), v(1), v(2)}}; }

// The least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
    const double n = double(x.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

int main(int argc, char** argv) {
    kit::Options opts("aligning_spin", "Chapter 8: the spin equation (6.2) lines S up with B or against it");
    opts.vector("B", Vec3(0.3, -0.4, 1.2), "the magnetic field B", kit::nonzero_vector(-1e3, 1e3))
        .real("e_over_mc", 2.0, "e/mc (either sign: the sign of the charge)", kit::between(-1e3, 1e3))
        .real("beta", 0.5, "beta, the strength of the aligning term (0: plain precession)", kit::between(0, 1e3))
        .real("S", 1.0, "the length of the spin |S|", kit::between(1e-3, 1e3))
        .real("T", 12, "time span", kit::between(1e-2, 1e6))
        .integer("outputs", 600, "output times", 10, 100000)
        .integer("repeats", 3, "timing repetitions (the minimum is kept)", 1, 50);

    return kit::run(argc, argv, opts, [](const kit::Options& o, kit::Scene& scene) {
        const rigid::SpinField field{o.vector("B"), o.real("e_over_mc"), o.real("beta")};
        rigid::SpinField plain = field;
        plain.beta = 0;
        const double s = o.real("S"), T = o.real("T"), Bn = field.B.norm();
        const int repeats = static_cast<int>(o.integer("repeats"));
        const auto times = rigid::linspace(0, T, static_cast<int>(o.integer("outputs")));
        const Vec3 b = field.B.normalized(), e1 = b.unitOrthogonal(), e2 = b.cross(e1);
        auto start = [&](double deg) { return Vec3(s * (std::cos(deg * pi / 180) * b + std::sin(deg * pi / 180) * e1)); };
        const double omega_L = -field.e_over_mc * Bn;  // the precession rate about b
        const double period = omega_L != 0 ? 2 * pi / std::abs(omega_L) : T;
        // The work: 12 starting angles, (6.2) `repeats` times and beta = 0 once, over T; the
        // phase turned is (|omega_L| + beta |B| |S|) T radians a run.
        kit::require_budget(o, {12.0 * (repeats + 1) * (std::abs(omega_L) + field.beta * Bn * s) * T + 200, 6e-5,
                                "radians of phase", "--T, --B, --e_over_mc, --beta, --S, --repeats"});
        kit::require_budget(o, {12.0 * (repeats + 1) * double(times.size()), 3e-6, "output times (all runs)", "--outputs, --repeats"});

        // The fan of initial angles, with (6.2) and with beta = 0.
        const std::vector<double> fan{5, 20, 40, 60, 80, 89, 91, 100, 120, 140, 160, 175};
        std::vector<std::vector<std::vector<double>>> angle_curves, plain_curves;
        std::vector<std::vector<double>> finals;  // start deg, final deg (beta), final deg (beta = 0)
        double err = 0, err_plain = 0, norm_drift = 0, off_plane = 0, plain_angle_drift = 0, run_time = 0;
        for (double deg : fan) {
            const Vec3 S0 = start(deg);
            scene8::Run run, run0;
            run_time += kit::min_time([&] { run = scene8::integrate(rigid::spin_equations(field), vecx(S0), times, "rk8pd", 1e-12); },
                                      repeats);
            run0 = scene8::integrate(rigid::spin_equations(plain), vecx(S0), times, "rk8pd", 1e-12);
            const Vec3 n_plane = b.cross(S0).normalized();
            std::vector<std::vector<double>> c, c0;
            for (std::size_t i = 0; i < times.size(); ++i) {
                const Vec3 S = vec(run.y[i]), P = vec(run0.y[i]);
                if (!S.allFinite()) throw kit::NumericalFailure("S is not finite at t = " + std::to_string(times[i]));
                err = std::max(err, (S - rigid::spin_exact(field, S0, times[i])).norm() / s);
                err_plain = std::max(err_plain, (P - rigid::spin_exact(plain, S0, times[i])).norm() / s);
                norm_drift = std::max(norm_drift, std::abs(S.norm() - s) / s);
                // Undo the precession: what is left must stay in the plane of B and S0.
                const Vec3 back = rigid::rotation_about(b, -omega_L * times[i]) * S;
                off_plane = std::max(off_plane, std::abs(back.dot(n_plane)) / s);
                const double th = rigid::spin_angle(field.B, S) * 180 / pi, th0 = rigid::spin_angle(field.B, P) * 180 / pi;
                plain_angle_drift = std::max(plain_angle_drift, std::abs(th0 - deg));
                c.push_back({times[i], th});
                c0.push_back({times[i], th0});
            }
            angle_curves.push_back(c), plain_curves.push_back(c0);
            finals.push_back({deg, angle_curves.back().back()[1], plain_curves.back().back()[1]});
        }
        scene.report.headline("max |S(t) - S_exact(t)| / |S| over a fan of 12 initial angles, the student's (6.2) "
                              "integrated by rk8pd at tol 1e-12",
                              err, run_time);
        scene.report.add("error_beta_0", err_plain, "the same for beta = 0 against the exact precession R^B(-(e/mc)|B|t) S0");
        scene.report.add("norm_drift", norm_drift, "max | |S(t)| - |S(0)| | / |S|");
        scene.report.add("out_of_plane", off_plane,
                         "max distance from the plane of B and S0 after undoing the precession, / |S|");
        scene.report.add("angle_drift_beta_0", plain_angle_drift, "degrees: beta = 0 keeps the angle");
        scene.report.table("final_angles", {"start_deg", "final_deg", "final_deg_beta_0"}, finals);

        // The precession: its sense and rate, from the azimuth of S about b (beta = 0, 60 degrees).
        {
            const auto fine = rigid::linspace(0, std::min(T, 0.9 * period), 200);
            const scene8::Run run = scene8::integrate(rigid::spin_equations(plain), vecx(start(60)), fine, "rk8pd", 1e-12);
            std::vector<double> phi;
            double prev = 0, turn = 0;
            for (std::size_t i = 0; i < fine.size(); ++i) {
                const Vec3 S = vec(run.y[i]);
                double a = std::atan2(S.dot(e2), S.dot(e1));
                if (i > 0 && a - prev > pi) turn -= 2 * pi;
                if (i > 0 && a - prev < -pi) turn += 2 * pi;
                prev = a;
                phi.push_back(a + turn);
            }
            const double rate = slope(fine, phi);
            scene.report.add("precession_rate_measured", rate, "d(azimuth about B)/dt, counter-clockwise > 0");
            scene.report.add("precession_rate_predicted", omega_L, "-(e/mc)|B|");
            if (omega_L != 0) scene.report.add("precession_rate_mismatch", std::abs(rate / omega_L - 1), "relative");
        }

        // The rate of alignment: ln tan(theta) falls at beta |B| (40 degrees, while 1e-9 < theta < 0.5).
        if (field.beta > 0) {
            const auto fine = rigid::linspace(0, T, 400);
            const scene8::Run run = scene8::integrate(rigid::spin_equations(field), vecx(start(40)), fine, "rk8pd", 1e-13);
            std::vector<double> t, l;
            for (std::size_t i = 0; i < fine.size(); ++i) {
                const double th = rigid::spin_angle(field.B, vec(run.y[i]));
                if (th > 1e-9 && th < 0.5) t.push_back(fine[i]), l.push_back(std::log(std::tan(th)));
            }
            if (t.size() >= 5) {
                scene.report.add("alignment_rate_measured", -slope(t, l), "-d ln tan(theta)/dt at 40 degrees");
                scene.report.add("alignment_rate_mismatch", std::abs(-slope(t, l) / (field.beta * Bn) - 1), "relative");
            }
            scene.report.add("alignment_rate_predicted", field.beta * Bn, "beta |B|");

            // 90 degrees: an equilibrium of the angle, left at the same rate beta |B|.
            const scene8::Run eq = scene8::integrate(rigid::spin_equations(field), vecx(s * e1), fine, "rk8pd", 1e-13);
            double stays = 0;
            for (const auto& y : eq.y) stays = std::max(stays, std::abs(vec(y).dot(b)) / s);
            scene.report.add("equator_stays", stays, "started at exactly 90 degrees: max |cos theta|");
            const scene8::Run off = scene8::integrate(rigid::spin_equations(field), vecx(start(90 - 1e-7)), fine, "rk8pd", 1e-13);
            std::vector<double> t2, l2;
            for (std::size_t i = 0; i < fine.size(); ++i) {
                const double d = std::abs(rigid::spin_angle(field.B, vec(off.y[i])) - pi / 2);
                if (d > 1e-8 && d < 0.1) t2.push_back(fine[i]), l2.push_back(std::log(d));
            }
            if (t2.size() >= 5) {
                scene.report.add("equator_escape_rate", slope(t2, l2), "d ln|theta - 90 deg|/dt from 90 - 1e-7 deg");
                scene.report.add("equator_rate_mismatch", std::abs(slope(t2, l2) / (field.beta * Bn) - 1), "relative");
            }
        }

        kit::Figure fig(scene, "spin_alignment.svg", 820, 520);
        if (fig.enabled()) {
            char head[200];
            std::snprintf(head, sizeof head,
                          "set title '(6.2) with β = %g, |{/:Bold B}| = %g, e/mc = %g: the angle between {/:Bold S} and {/:Bold B}'\n", field.beta, Bn,
                          field.e_over_mc);
            std::string cmd = std::string(head) +
                              "set xlabel 't'\nset ylabel 'angle (degrees)'\nset yrange [0:180]\nset ytics 30\n"
                              "set key outside right top font ',9'\nplot ";
            for (std::size_t j = 0; j < fan.size(); ++j)
                cmd += std::string(j ? ", " : "") + "'-' with lines ls " + std::to_string(j % 8 + 1) + " lw 2 " +
                       (j == 0 ? "title '(6.2)'" : "notitle");
            for (std::size_t j = 0; j < fan.size(); ++j)
                cmd += ", '-' with lines ls " + std::to_string(j % 8 + 1) + " dt 2 lw 1 " +
                       (j == 0 ? "title 'β = 0'" : "notitle");
            fig << cmd + "\n";
            for (const auto& c : angle_curves) fig.data(c);
            for (const auto& c : plain_curves) fig.data(c);
            fig.finish();
        }

        kit::Figure fs(scene, "spin_sphere.svg", 700, 520);
        if (fs.enabled()) {
            // Draw in coordinates (e1, e2, b), so that B points up.
            auto local = [&](const Vec3& v) { return std::vector<double>{v.dot(e1), v.dot(e2), v.dot(b)}; };
            fs << "set view 70, 25, 1.45, 1.45\nset view equal xyz\nset xrange [-1.05:1.05]\nset yrange [-1.05:1.05]\nset zrange [-1.05:1.45]\nunset border\nunset tics\nunset grid\n"
                  "set xyplane 0\nset key at screen 0.99, 0.99 top right font ',9'\nset margins 0, 0, 0, 0\n"
                  "set arrow from 0, 0, 1 to 0, 0, 1.4 head filled lw 3 lc rgb 'black'\n"
                  "set label 'B' at 0.08, 0, 1.35 font ',14'\n";
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
                    sphere.push_back({std::cos(a) * std::cos(lon * pi / 180), std::cos(a) * std::sin(lon * pi / 180), std::sin(a)});
                }
                sphere.push_back({});
                sphere.push_back({});
            }
            std::vector<double> shown{30, 80, 100, 150};
            std::vector<std::vector<std::vector<double>>> paths;
            for (double deg : shown) {
                const auto fine = rigid::linspace(0, T, 1200);
                const scene8::Run run = scene8::integrate(rigid::spin_equations(field), vecx(start(deg)), fine, "rk8pd", 1e-12);
                std::vector<std::vector<double>> p;
                for (const auto& y : run.y) p.push_back(local(vec(y) / s));
                paths.push_back(p);
            }
            std::vector<std::vector<double>> circle;  // beta = 0 from 60 degrees: one circle
            for (int k = 0; k <= 120; ++k)
                circle.push_back(local(rigid::spin_exact(plain, start(60), period * k / 120) / s));
            std::string cmd = "splot '-' with lines lc rgb '#cccccc' lw 0.7 notitle, "
                              "'-' with lines lc rgb 'black' dt 2 lw 1.5 title 'β = 0 from 60°'";
            for (std::size_t j = 0; j < shown.size(); ++j) {
                char t[64];
                std::snprintf(t, sizeof t, "(6.2) from %g degrees", shown[j]);
                cmd += ", '-' with lines ls " + std::to_string(j + 1) + " lw 2 title '" + t + "'";
            }
            fs << cmd + "\n";
            fs.data(sphere).data(circle);
            for (const auto& p : paths) fs.data(p);
            fs.finish();
        }
    });
}
