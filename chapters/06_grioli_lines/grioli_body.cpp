// Chapter 6 scene, end to end: a body given at its centre of mass, hung at a distance L on a
// Grioli line, precesses as Theorem 1 says [P, Sect. 6, (5.14), (5.15); Theorem 1, (int.4)].
//
//   1. the suspension point O = L z on the chosen Grioli line, the tensor (5.2) at O, its
//      moments A < B < C and principal frame (Chapter 6: grioli_suspension);
//   2. the angle between the smallest axis at O and the line OG: cos^2 phi against
//      (B - A)/(C - A), the condition of Theorem 1 [P, (int.2), (5.13)];
//   3. the precession of Theorem 1 built from A < B < C and f = g L mu (Chapter 5);
//   4. the body's own data at O (its moments A < B < C with their gaps, from step 1's closed
//      forms, and the direction of G from O in the principal frame of step 1, not the closed
//      form of step 3) integrated with the Euler-Poisson equations (3.1)-(3.2) from the state of
//      step 3, and compared with R^b(alpha t) R^a(alpha t).
// If steps 1 and 3 did not describe the same body, step 4 would drift away at once.
//
// Euler's equations are written on the moment gaps (rigid::euler_poisson_rhs_gaps): far out on
// the line B and C agree to more digits than a double holds, and the naive form
// B Omega_B Omega_C - C Omega_C Omega_B leaves round-off of relative size eps B / A in Omega_dot_A,
// which the step-size control then chases. --form naive shows that (the scene euler_gap_form
// draws it against L).
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "common.hpp"
#include "heavy_body.hpp"
#include "motion.hpp"
#include "rigid/grioli.hpp"
#include "rigid/heavy_top.hpp"
#include "rigid/ode.hpp"
#include "rigid/rotation.hpp"
#include "stability.hpp"

using rigid::Mat3;
using rigid::Vec3;

namespace {

std::string sci(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2g", x);
    return buf;
}

struct Params {
    rigid::BodyAtG body = ch6::default_body;
    double g = 9.81;
    double L = 0.5;
    int line = 1;
    std::string sense = "ccw";
    std::string form = "gaps";
    long periods = 100;
    double tol = 1e-13;
    double off = 0.1;         // --motion: how far the second body's line leaves the Grioli line
    std::string motion_file;  // --motion: the book's viewer data (motion.hpp)
};

void declare(kit::Options& opts, Params& p) {
    ch6::body_options(opts, p.body);
    opts.real("g", &p.g, "acceleration of gravity g", kit::between(1e-6, 1e6))
        .real("L", &p.L,
              "distance from the centre of mass G to the suspension point O, along the Grioli line "
              "(1e-6 to 1e8 body sizes sqrt(C_g / mu))",
              kit::between(1e-12, 1e14))
        .integer("line", &p.line, "which Grioli line (5.15): +1 for x_C = +k x_A, -1 for x_C = -k x_A", -1, 1)
        .choice("sense", &p.sense, {"ccw", "cw"}, "counter-clockwise or clockwise precession (Theorem 1)")
        .choice("form", &p.form, {"gaps", "naive"},
                "Euler's equations on the moment gaps, or the naive form (J Omega) x Omega of Chapter 4")
        .integer("periods", &p.periods, "periods 2 pi / alpha to integrate", 1, 100000)
        .real("tol", &p.tol, "rk8pd relative tolerance", kit::between(1e-15, 1e-2))
        .real("off", &p.off,
              "with --motion: the angle (rad) by which the second body's line OG leaves the Grioli line, towards x_A",
              kit::between(1e-3, 0.5))
        .file("motion", &p.motion_file, kit::motion_help);
}

void check(const kit::Options& o, const Params& p) {
    const double size = ch6::size_of(ch6::body(p.body));
    if (!(p.L >= 1e-6 * size && p.L <= 1e8 * size))
        throw kit::BadInput(
            "--L: got " + std::to_string(p.L) + ", " + std::to_string(p.L / size) +
            " body sizes; it must be from 1e-6 to 1e8 body sizes sqrt(C_g / mu) = " + std::to_string(size));
    if (p.line == 0) throw kit::BadInput("--line: got 0; it must be +1 or -1");
    // The work: about kit::seconds_per_period per period, three timed runs when they are short.
    kit::require_budget(
        o, {3.0 * double(p.periods), kit::seconds_per_period("rk8pd", p.tol), "periods of rk8pd", "--periods, --tol"});
}

// The body hung on the line, Theorem 1's precession for it, and its own equations of motion.
struct Hung {
    rigid::GrioliSuspension s;
    rigid::Moments m;
    double f;
    rigid::GrioliPrecession P;
    Mat3 Q;
    Vec3 z0;
    rigid::OdeRhs rhs;
    double period;
    std::vector<double> times;
};

Hung hang(const Params& p) {
    const rigid::BodyAtG body = ch6::body(p.body);
    const double L = p.L, grav = p.g;
    const int line = p.line;
    const bool gaps = p.form == "gaps";
    const long periods = p.periods;
    // snippet: grioli_body
    // 1-2. The suspension point on the Grioli line, and the moments and axes there.
    const rigid::GrioliSuspension s = rigid::grioli_suspension(body, L, line);
    const rigid::ShiftedMoments& sm = s.frame.moments;
    const rigid::Moments m = rigid::moments_from_gaps(sm.A, sm.B_minus_A, sm.C_minus_B);

    // 3. Theorem 1's precession for these moments and f = g L mu.
    const double f = grav * L * body.mu;
    const rigid::Sense sense = p.sense == "ccw" ? rigid::Sense::ccw : rigid::Sense::cw;
    const rigid::GrioliPrecession P = rigid::grioli_precession(m, f, sense);

    // The principal frame at O is fixed only up to half-turns about its axes; pick the one
    // in which the centre of mass lies along +a, as Theorem 1 places the body.
    const double dA = s.z0.x() * P.z0.x() >= 0 ? 1 : -1, dC = s.z0.z() * P.z0.z() >= 0 ? 1 : -1;
    const Mat3 Q = s.frame.R * Vec3(dA, dA * dC, dC).asDiagonal();  // still right-handed
    const Vec3 z0 = (Q.transpose() * -s.z).normalized();            // O -> G, body frame

    // 4. The body's own equations in its principal frame at O, from the precession's initial
    // state: Euler's equations on the gaps of step 1 (or, to see why, the naive form).
    const rigid::HeavyTop naive = rigid::heavy_top(Vec3(sm.A, sm.B, sm.C).asDiagonal(), f, P.k, z0);
    const rigid::OdeRhs rhs = [=](double, const rigid::VecX& y) {
        const rigid::BodyState x = rigid::unpack(y);
        return rigid::pack(gaps ? rigid::euler_poisson_rhs_gaps(m, f, P.k, z0, x) : rigid::euler_poisson_rhs(naive, x));
    };
    const double period = 2 * std::numbers::pi / P.alpha;
    const auto times = rigid::linspace(0, periods * period, static_cast<int>(16 * periods));
    // end snippet
    return {s, m, f, P, Q, z0, rhs, period, times};
}

struct Integration {
    double max_error = 0, run_time = 0;
    rigid::OdeStats stats;
};

// The equations integrated from the precession's initial state (timed: three runs when short),
// against R^b(alpha t) R^a(alpha t).
Integration integrate(const kit::Options& o, const Params& p, const Hung& h) {
    const rigid::ShiftedMoments& sm = h.s.frame.moments;
    // Steps are capped by the budget: the naive form far out would otherwise run for hours.
    const long max_steps = std::max(1000L, static_cast<long>(o.budget_s() / 3 / 2e-6 / double(h.times.size())));
    Integration r;
    const auto run = [&] {
        r.max_error = 0;
        r.stats = rigid::integrate_gsl(
            h.rhs, rigid::pack(rigid::grioli_initial_state(h.P)), h.times,
            [&](double t, const rigid::VecX& y) {
                r.max_error =
                    std::max(r.max_error, rigid::geodesic_angle(rigid::unpack(y).R, rigid::grioli_rotation(h.P, t)));
            },
            {.method = "rk8pd", .rel_tol = p.tol, .abs_tol = p.tol * std::min(1.0, h.P.alpha), .max_steps = max_steps});
    };
    try {
        r.run_time = kit::min_time(run, 1);
        if (r.run_time < 0.1) r.run_time = std::min(r.run_time, kit::min_time(run, 2));
    } catch (const std::runtime_error& e) {
        throw kit::NumericalFailure(std::string(e.what()) + " (more than " + std::to_string(max_steps) +
                                    " steps between two outputs, the budget's share" +
                                    (p.form == "gaps"
                                         ? std::string(")")
                                         : "; the naive form's steps chase round-off of relative size eps B / A = " +
                                               sci(std::numeric_limits<double>::epsilon() * sm.B / sm.A) +
                                               " in Omega_dot_A: try --form gaps)"));
    }
    if (!std::isfinite(r.max_error)) throw kit::NumericalFailure("the integration produced a non-finite rotation");
    return r;
}

void report(kit::Scene& scene, const Params& p, const Hung& h, const Integration& r) {
    const rigid::GrioliSuspension& s = h.s;
    const rigid::ShiftedMoments& sm = s.frame.moments;
    scene.report.headline(
        "max over t of the geodesic angle between the body's integrated R(t) and "
        "R^b(alpha t) R^a(alpha t) of Theorem 1",
        r.max_error, r.run_time);
    const Mat3 J_body = h.Q.transpose() * s.frame.I * h.Q;  // the body's tensor (5.2) in that frame
    scene.report.add("form", p.form, "Euler's equations on the gaps, or naive");
    scene.report.add("A", sm.A, "principal moments at O (5.3)");
    scene.report.add("B", sm.B);
    scene.report.add("C", sm.C);
    scene.report.add("C_minus_B", sm.C_minus_B, "the gap, from Chapter 6's closed form");
    scene.report.add("C_minus_B_in_double", sm.C - sm.B, "the same gap from C and B rounded to double");
    scene.report.add("naive_round_off", std::numeric_limits<double>::epsilon() * sm.B / sm.A,
                     "eps B / A: the relative round-off the naive form leaves in Omega_dot_A");
    scene.report.add("body_sizes", p.L / ch6::size_of(p.body), "L in body sizes sqrt(C_g / mu)");
    scene.report.add("phi_g", std::atan2(s.z.z(), s.z.x()), "angle of the line from x_A at G, radians (5.14)");
    scene.report.add("cos2phi", s.tilt.cos2, "cos^2 of the angle between R_A at O and the line OG (5.12)");
    scene.report.add("cos2phi_expected", s.expected.cos2, "(B - A)/(C - A), Theorem 1's condition (5.13)");
    scene.report.add("cos2phi_mismatch", std::abs(s.tilt.cos2 - s.expected.cos2) / s.expected.cos2, "relative");
    scene.report.add("alpha", h.P.alpha, "[P, (int.4)] with f = g L mu");
    scene.report.add("f", h.f);
    scene.report.add("O", s.O, "suspension point from G, principal axes at G");
    scene.report.add("z0", h.z0, "O -> G in the principal frame at O");
    scene.report.add("z0_minus_a", (h.z0 - h.P.z0).norm(), "|z(0) - a|: the body's centre of mass against Theorem 1's");
    scene.report.add("J_offdiagonal", (J_body - Vec3(sm.A, sm.B, sm.C).asDiagonal().toDenseMatrix()).norm() / sm.C,
                     "|J - diag(A, B, C)| / C: the body's tensor (5.2) against the closed-form moments");
    scene.report.add("sense", p.sense);
    scene.report.add("periods", p.periods);
    scene.report.add("rhs_calls", r.stats.rhs_calls, "one run");
    scene.report.add("max_rotation_error", r.max_error, "radians");
    scene.report.add("period", h.period);
    // Is the error physics? The Floquet multipliers of this precession (Chapter 7), and whether
    // they, not the arithmetic, made the error (kit/stability.hpp says by which rule).
    kit::report_stability(scene.report, h.m, h.P.sense,
                          {double(p.periods), r.max_error, p.tol, kit::rk8pd_steps(r.stats.rhs_calls)});
}

// ------------------------------------------------------------------ the book's motion viewer
// With --motion: three periods of the body hung on the line (the equations above, integrated
// from Theorem 1's initial state), beside the same body hung at the same L on a line turned by
// --off towards x_A, started in the state Theorem 1 gives for its own moments there, and
// integrated with its own equations. Each R(t) is drawn in the body's frame at G (its moments
// A_g, B_g, C_g), the lab turned so that k is up.

// One body at O, as the integration sees it: its moments and frame at O, Theorem 1's precession
// for them, and its own equations.
struct AtO {
    rigid::Moments m;
    Mat3 Q;   // the principal frame at O (columns, in the G-frame), oriented as Theorem 1 places it
    Vec3 z0;  // O -> G in that frame
    rigid::GrioliPrecession P;
    rigid::OdeRhs rhs;
};

AtO hang_off(const Params& p, const Hung& on) {
    const rigid::BodyAtG body = ch6::body(p.body);
    const Vec3 z = rigid::shift_direction(std::atan2(on.s.z.z(), on.s.z.x()) - p.line * p.off);
    const rigid::PrincipalFrame fr = rigid::principal_frame(body, p.L, z);
    AtO b;
    b.m = rigid::moments_from_gaps(fr.moments.A, fr.moments.B_minus_A, fr.moments.C_minus_B);
    b.P = rigid::grioli_precession(b.m, on.f, on.P.sense);
    // The same choice of half-turns as on the line: G on the side of +a.
    const Vec3 g0 = fr.R.transpose() * -z;
    const double dA = g0.x() * b.P.z0.x() >= 0 ? 1 : -1, dC = g0.z() * b.P.z0.z() >= 0 ? 1 : -1;
    b.Q = fr.R * Vec3(dA, dA * dC, dC).asDiagonal();
    b.z0 = (b.Q.transpose() * -z).normalized();
    const rigid::Moments m = b.m;
    const double f = on.f;
    const Vec3 k = b.P.k, z0 = b.z0;
    b.rhs = [=](double, const rigid::VecX& y) {
        return rigid::pack(rigid::euler_poisson_rhs_gaps(m, f, k, z0, rigid::unpack(y)));
    };
    return b;
}

// R(t) of the body integrated from Theorem 1's initial state (rk8pd at --tol, as above), its
// largest and its last geodesic angle from R^b(alpha t) R^a(alpha t), and the motion drawn.
kit::Motion play(const Params& p, const AtO& b, const Vec3& G_from_O, const std::vector<double>& times, double& max_dev,
                 double& end_dev) {
    const rigid::BodyAtG body = ch6::body(p.body);
    kit::Motion mo;
    mo.moments = {body.A_g, body.B_g, body.C_g};
    // The uniform ellipsoid with these moments and mass: its largest half-axis is the viewer's unit.
    const double a2 = 2.5 / body.mu * (body.B_g + body.C_g - body.A_g);
    mo.centre_of_mass = G_from_O / std::sqrt(a2);
    const Mat3 W = Eigen::Quaterniond::FromTwoVectors(b.P.k, Vec3::UnitZ()).toRotationMatrix();
    max_dev = 0;
    rigid::integrate_gsl(b.rhs, rigid::pack(rigid::grioli_initial_state(b.P)), times,
                         [&](double t, const rigid::VecX& y) {
                             const Mat3 R = rigid::unpack(y).R;
                             end_dev = rigid::geodesic_angle(R, rigid::grioli_rotation(b.P, t));
                             max_dev = std::max(max_dev, end_dev);
                             mo.sample(t, W * R * b.Q.transpose());
                         },
                         {.method = "rk8pd", .rel_tol = p.tol, .abs_tol = p.tol * std::min(1.0, b.P.alpha)});
    return mo;
}

void write_hung_motions(kit::Scene& scene, const Params& p, const Hung& h) {
    if (p.motion_file.empty()) return;
    const AtO on{h.m, h.Q, h.z0, h.P, h.rhs}, off = hang_off(p, h);
    const auto times = rigid::linspace(0, 3 * h.period, 180);
    double on_max = 0, on_end = 0, off_max = 0, off_end = 0;
    kit::Motion a = play(p, on, -h.s.z * p.L, times, on_max, on_end);
    const Vec3 z_off = rigid::shift_direction(std::atan2(h.s.z.z(), h.s.z.x()) - p.line * p.off);
    kit::Motion b = play(p, off, -z_off * p.L, times, off_max, off_end);
    a.label = "left: hung on the Grioli line";
    b.label = fmt::format("right: hung {:g} rad off the line", p.off);
    a.title =
        "the same body hung at the same L on a Grioli line (left) and off it (right), each started as Theorem 1 "
        "says for its moments at O";
    a.parameters = fmt::format(
        "A_g = {:g}, B_g = {:g}, C_g = {:g}, μ = {:g}, g = {:g}, L = {:g}, line {:+d}, {}; "
        "three periods 2π/α = {:.3g}; off the line: the line turned by {:g} rad towards x_A, "
        "its largest angle from Theorem 1's R(t) {:.2g} rad",
        p.body.A_g, p.body.B_g, p.body.C_g, p.body.mu, p.g, p.L, p.line, p.sense, h.period, p.off, off_max);
    a.error = on_max;
    a.error_measure = "on the line: max geodesic angle (rad) between the integrated R(t) and Theorem 1's";
    a.fixed_point = Vec3(-1.5, 0, 0);
    b.fixed_point = Vec3(1.5, 0, 0);
    a.speed = b.speed = h.period / 4;
    scene.report.add("motion_off_angle", p.off, "--off: the second body's line from the Grioli line, rad");
    scene.report.add("motion_on_line_max_angle", on_max, "--motion, three periods: on the line, rad");
    scene.report.add("motion_off_line_max_angle", off_max, "--motion, three periods: off the line by --off, rad");
    scene.report.add("motion_off_line_end_angle", off_end, "the same after three periods, rad");
    kit::write_motion(scene, p.motion_file, std::vector<kit::Motion>{a, b});
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts(
        "grioli_body",
        "Chapter 6: a body given at its centre of mass, hung on a Grioli line, precessing as Theorem 1 says");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        check(o, p);
        const Hung h = hang(p);
        report(scene, p, h, integrate(o, p, h));
        write_hung_motions(scene, p, h);
    });
}
