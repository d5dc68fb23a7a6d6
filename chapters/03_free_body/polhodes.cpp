// Chapter 3 scene: polhodes on the energy ellipsoid [P, (6.7), (6.9)].
//
// For one energy E, a family of motions with M^2 = 2 E D for D from I_lo to I_hi: each is
// integrated with the student's Euler-Poisson equations (GSL, method by name) over one period
// and compared with the exact elliptic motion. The curves Omega(t) are the polhodes: the
// intersections of the energy ellipsoid with the ellipsoid |I Omega|^2 = M^2 (6.9). The two
// plane ellipses through the middle axis, drawn in black, are the separatrix.
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "body.hpp"
#include "figure.hpp"
#include "free_body_scene.hpp"
#include "motion.hpp"
#include "polhodes.gp.hpp"
#include "rigid/free_body_exact.hpp"
#include "rigid/require.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

using rigid::Vec3;

namespace {

struct Params {
    Vec3 I = Vec3(2, 3, 4);
    double energy = 0.5;
    int curves = 4;
    std::string method = "rk8pd";
    double tol = 1e-12;
    int samples = 200;
    std::string motion_file;  // --motion: the book's viewer data (motion.hpp)
    double off_axis = 0.05;   // --motion: each start's component along the other two axes / its spin
};

void declare(kit::Options& opts, Params& p) {
    opts.vector("I", &p.I, "principal moments I1,I2,I3 (triangle inequality)", kit::components_between(1e-3, 1e3))
        .real("energy", &p.energy, "kinetic energy E of every curve", kit::between(1e-6, 1e6))
        .integer("curves", &p.curves, "polhodes on each side of the separatrix", 1, 20)
        .choice("method", &p.method, {"rk2", "rk4", "rkf45", "rkck", "rk8pd", "msadams"},
                "GSL method for the integrations (rk4 here is GSL's; the student's RK4 is in the other scenes)")
        .real("tol", &p.tol, "GSL tolerance (relative and absolute)", kit::between(1e-14, 1e-3))
        .integer("samples", &p.samples, "output times per period", 10, 100000)
        .file("motion", &p.motion_file, kit::motion_help)
        .real("off-axis", &p.off_axis,
              "with --motion: each body's Omega(0) along the two other axes, as a fraction of its spin",
              kit::between(1e-4, 0.2));
}

void check(const kit::Options& o, const Params& p) {
    kit::require_moments(p.I, "I", {kit::Order::distinct});  // polhodes about two axes
    // The work: 2 curves polhodes, one period each (about 8 radians of phase; more near the
    // separatrix), 3 timed runs, at the method's steps per radian for this tolerance; with
    // --motion, three bodies over the middle-axis period (about 50 radians each at --off-axis
    // 0.05; the period grows as the log of 1 / off-axis).
    const double longer = std::max(1.0, std::log(1 / p.off_axis) / std::log(20.0));
    const double motion = p.motion_file.empty() ? 0.0 : 3 * 60.0 * longer;
    kit::require_budget(
        o, {(2.0 * p.curves * 3 * 12 + motion) * scene3::steps_per_radian(p.method, p.tol) + 6.0 * p.curves * p.samples,
            1.5e-6, "steps", "--curves, --tol, --method, --samples, --motion"});
}

using Curves = std::vector<std::vector<std::vector<double>>>;

// Every polhode integrated and compared with the exact motion.
struct Polhodes {
    double err = 0, drift_E = 0, drift_M = 0, orth = 0, run_time = 0;
    long work = 0;
    std::vector<std::vector<double>> summary;  // D, m, m_c, period, omega error, rhs calls
    Curves lo, hi;                             // the curves about the smallest and the largest axis
};

// One polhode, M^2 = 2 E D: integrated over one period, against the exact elliptic motion.
void integrate_polhode(const Params& p, double D, Polhodes& out) {
    const Vec3& I = p.I;
    const auto [lo, mid, hi] = scene3::sorted_axes(I);
    const Vec3 w0 = scene3::polhode_start(I, p.energy, D);
    const auto exact = rigid::free_body_motion(I, w0);
    const auto times = rigid::linspace(0, exact.period, p.samples);
    scene3::Run run;
    out.run_time += kit::min_time([&] { run = scene3::integrate_gsl(I, w0, times, p.method, p.tol); }, 3);
    out.work += run.work;
    const double E0 = rigid::rotational_energy(I, w0), M0 = rigid::angular_momentum_squared(I, w0);
    double e = 0;
    std::vector<std::vector<double>> pts;
    for (std::size_t k = 0; k < times.size(); ++k) {
        const Vec3& w = run.Omega[k];
        e = std::max(e, (w - rigid::free_body_exact_omega(exact, times[k])).norm() / w0.norm());
        out.drift_E = std::max(out.drift_E, std::abs(rigid::rotational_energy(I, w) - E0) / E0);
        out.drift_M = std::max(out.drift_M, std::abs(rigid::angular_momentum_squared(I, w) - M0) / M0);
        out.orth = std::max(out.orth, (run.R[k].transpose() * run.R[k] - rigid::Mat3::Identity()).norm());
        pts.push_back({w.x(), w.y(), w.z()});
    }
    out.err = std::max(out.err, e);
    // -Omega(t) is a motion too: the mirror polhode about the other end of the same axis.
    std::vector<std::vector<double>> mirror;
    for (const auto& x : pts) mirror.push_back({-x[0], -x[1], -x[2]});
    (D < I(mid) ? out.lo : out.hi).push_back(pts);
    (D < I(mid) ? out.lo : out.hi).push_back(mirror);
    out.summary.push_back({D, exact.m, exact.m_c, exact.period, e, double(run.work)});
}

Polhodes compute(const Params& p) {
    const auto [lo, mid, hi] = scene3::sorted_axes(p.I);
    Polhodes out;
    // D = M^2 / 2E on both sides of I_mid, evenly in the fraction of the way to the axis.
    for (int k = 1; k <= p.curves; ++k) {
        const double f = double(k) / (p.curves + 1);
        integrate_polhode(p, p.I(mid) - f * (p.I(mid) - p.I(lo)), out);
        integrate_polhode(p, p.I(mid) + f * (p.I(hi) - p.I(mid)), out);
    }
    return out;
}

void report(kit::Scene& scene, const Params& p, const Polhodes& r) {
    scene.report.headline("max |Omega_integrated - Omega_exact| / |Omega(0)| over every polhode, one period each",
                          r.err, r.run_time);
    scene.report.add("method", p.method);
    scene.report.add("tol", p.tol);
    scene.report.add("rhs_calls", r.work);
    scene.report.add("energy_drift", r.drift_E, "max |E(t) - E(0)| / E(0), [P, (6.9)]");
    scene.report.add("momentum_drift", r.drift_M, "max |M^2(t) - M^2(0)| / M^2(0), [P, (6.9)]");
    scene.report.add("orthogonality_defect", r.orth, "max ||R^T R - 1||_F");
    scene.report.table("polhodes", {"D", "m", "m_c", "period", "omega_error", "rhs_calls"}, r.summary);
}

// The energy ellipsoid as a light mesh of meridians and parallels.
std::vector<std::vector<double>> ellipsoid(const Vec3& semi) {
    std::vector<std::vector<double>> mesh;
    for (int i = 0; i < 12; ++i) {
        const double ph = std::numbers::pi * i / 12;
        for (int k = 0; k <= 60; ++k) {
            const double th = 2 * std::numbers::pi * k / 60;
            mesh.push_back({semi.x() * std::sin(th) * std::cos(ph), semi.y() * std::sin(th) * std::sin(ph),
                            semi.z() * std::cos(th)});
        }
        mesh.push_back({});
        mesh.push_back({});
    }
    return mesh;
}

// The separatrix: the energy ellipsoid cut by I_lo (I_mid - I_lo) W_lo^2 = I_hi (I_hi - I_mid) W_hi^2.
std::vector<std::vector<double>> separatrix(const Vec3& I, double E, const Vec3& semi) {
    const auto [lo, mid, hi] = scene3::sorted_axes(I);
    std::vector<std::vector<double>> sep;
    const double c_lo = std::sqrt(I(hi) * (I(hi) - I(mid))), c_hi = std::sqrt(I(lo) * (I(mid) - I(lo)));
    for (double sign : {1.0, -1.0}) {
        Vec3 u = Vec3::Zero();
        u(lo) = c_lo;
        u(hi) = sign * c_hi;
        u *= std::sqrt(2 * E / (I(lo) * u(lo) * u(lo) + I(hi) * u(hi) * u(hi)));
        for (int k = 0; k <= 200; ++k) {
            const double th = 2 * std::numbers::pi * k / 200;
            Vec3 x = std::cos(th) * u;
            x(mid) = semi(mid) * std::sin(th);
            sep.push_back({x.x(), x.y(), x.z()});
        }
        sep.push_back({});
        sep.push_back({});
    }
    return sep;
}

std::vector<std::vector<double>> join(const Curves& cs) {
    std::vector<std::vector<double>> out;
    for (const auto& c : cs) {
        out.insert(out.end(), c.begin(), c.end());
        out.push_back({});
        out.push_back({});
    }
    return out;
}

void draw(kit::Scene& scene, const Params& p, const Polhodes& r) {
    kit::Figure fig(scene, "polhodes.svg", 760, 640);
    if (!fig.enabled()) return;
    const Vec3& I = p.I;
    const double E = p.energy;
    const Vec3 semi(std::sqrt(2 * E / I(0)), std::sqrt(2 * E / I(1)), std::sqrt(2 * E / I(2)));
    fig.script(kit::gp::polhodes);
    fig.data(ellipsoid(semi)).data(join(r.lo)).data(join(r.hi)).data(separatrix(I, E, semi));
    fig.finish();
}

// ------------------------------------------------------------------ the book's motion viewer
// With --motion: three boxes with the moments I and the energy E, each started spinning about
// one principal axis with a small component (--off-axis of the spin) along the other two, integrated
// as the polhodes are (--method, --tol) over one period of the middle-axis motion. Each lab is
// turned so that the body's angular momentum M, fixed in space, points up.
void write_axes_motion(kit::Scene& scene, const Params& p) {
    if (p.motion_file.empty()) return;
    const Vec3& I = p.I;
    const auto axes = scene3::sorted_axes(I);
    const char* names[] = {"smallest", "middle", "largest"};
    std::vector<Vec3> starts;
    for (int j = 0; j < 3; ++j) {
        Vec3 w = Vec3::Constant(p.off_axis);
        w(axes[j]) = 1;
        starts.push_back(w * std::sqrt(2 * p.energy / w.dot(I.cwiseProduct(w))));  // energy E
    }
    const double T = rigid::free_body_motion(I, starts[1]).period;
    const auto times = rigid::linspace(0, T, 400);
    std::vector<kit::Motion> bodies;
    double err = 0;
    for (int j = 0; j < 3; ++j) {
        const scene3::Run run = scene3::integrate_gsl(I, starts[j], times, p.method, p.tol);
        const auto exact = rigid::free_body_exact_rotations(rigid::free_body_motion(I, starts[j]), times);
        const rigid::Mat3 W =
            Eigen::Quaterniond::FromTwoVectors(I.cwiseProduct(starts[j]), Vec3::UnitZ()).toRotationMatrix();
        kit::Motion b;
        b.label = fmt::format("{}: spin about the {} axis", j == 0 ? "left" : j == 1 ? "middle" : "right", names[j]);
        b.moments = I;
        b.shape = "box";
        b.fixed_point = Vec3(2.8 * (j - 1), 0, 0);
        b.speed = T / 20;
        double tilt = 0;  // the largest angle between the spin's axis and M
        for (std::size_t k = 0; k < times.size(); ++k) {
            err = std::max(err, rigid::geodesic_angle(run.R[k], exact[k]));
            b.sample(times[k], W * run.R[k]);
            tilt = std::max(tilt, std::acos(std::clamp(b.R.back()(2, axes[j]), -1.0, 1.0)));
        }
        scene.report.add(fmt::format("motion_tilt_{}", names[j]), tilt * 180 / std::numbers::pi,
                         "--motion: largest angle (degrees) between that axis and M");
        bodies.push_back(std::move(b));
    }
    bodies[0].title =
        "the free body spun about each principal axis, slightly off: smallest (left), middle, largest "
        "(right)";
    bodies[0].parameters = fmt::format(
        "I = ({:g}, {:g}, {:g}), E = {:g}, each Ω(0) along its axis with {:g} of it along the other two; "
        "t from 0 to {:.3g}, one period of the middle-axis motion; each lab turned so that M points up",
        I(0), I(1), I(2), p.energy, p.off_axis, T);
    bodies[0].error = err;
    bodies[0].error_measure = fmt::format(
        "max geodesic angle (rad) between the integrated R(t) ({}, tolerance {:g}) "
        "and the exact one, over the three bodies",
        p.method, p.tol);
    scene.report.add("motion_period", T, "--motion: one period of the middle-axis motion");
    scene.report.add("motion_error", err, "--motion: max geodesic angle, integrated against exact R(t), rad");
    kit::write_motion(scene, p.motion_file, bodies);
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("polhodes", "Chapter 3: polhodes on the energy ellipsoid, integrated and exact");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        check(o, p);
        const Polhodes r = compute(p);
        report(scene, p, r);
        draw(scene, p, r);
        write_axes_motion(scene, p);
    });
}
