// Chapter 3 scene: error against run time for the free body. The student's fixed-step RK4
// (a sweep of steps) and GSL's rkf45 and rk8pd (a sweep of tolerances) integrate the student's
// Euler-Poisson equations (6.7)-(6.8); every run is measured against the exact motion
// (rigid/free_body_exact.hpp): the error of Omega and of R, the drift of the two integrals (6.9),
// and the orthogonality defect ||R^T R - 1||. Run time: the minimum over repetitions.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "body.hpp"
#include "figure.hpp"
#include "free_body_scene.hpp"
#include "free_body_work_precision.gp.hpp"
#include "rigid/free_body_exact.hpp"
#include "rigid/require.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

using rigid::Mat3;
using rigid::Vec3;

namespace {

struct Params {
    Vec3 I = Vec3(2, 3, 4);
    Vec3 Omega0 = Vec3(1.0, 0.6, -0.8);
    double T = 20;
    int outputs = 40;
    int repeats = 5;
};

void declare(kit::Options& opts, Params& p) {
    opts.vector("I", &p.I, "principal moments I1,I2,I3", kit::components_between(1e-3, 1e3))
        .vector("Omega0", &p.Omega0, "initial angular velocity (body frame)", kit::components_between(-1e3, 1e3))
        .real("T", &p.T, "time span", kit::between(1e-3, 1e6))
        .integer("outputs", &p.outputs, "output times where the error is measured", 1, 10000)
        .integer("repeats", &p.repeats, "timing repetitions (the minimum is kept)", 1, 50);
}

void check(const kit::Options& o, const Params& p) {
    kit::require_moments(p.I, "I", {kit::Order::any});
    if (!(p.Omega0.norm() > 0)) throw kit::BadInput("--Omega0 must not be zero");
    // The work: RK4 at eight steps h (sum of T / h = 1885 T steps), rkf45 and rk8pd at ten
    // and eleven tolerances (about 9000 evaluations per radian turned), each `repeats` times.
    kit::require_budget(o, {p.repeats * (1885 * p.T * 4 + 9000 * p.Omega0.norm() * p.T), 1.5e-7,
                            "evaluations of the equations", "--T, --Omega0, --repeats"});
    // Every output time stops each of the 29 runs and is measured: about 1.2 us each.
    kit::require_budget(
        o, {29.0 * p.repeats * double(p.outputs), 1.2e-6, "output times (all runs)", "--outputs, --repeats"});
}

// The exact motion at the output times, and what it costs.
struct Reference {
    std::vector<double> times;
    rigid::FreeBodyMotion exact;
    std::vector<Vec3> W;
    std::vector<Mat3> R;
    double time;
};

Reference reference(const Params& p) {
    Reference ref{rigid::linspace(0, p.T, p.outputs), {}, {}, {}, 0};
    ref.time = kit::min_time(
        [&] {
            ref.exact = rigid::free_body_motion(p.I, p.Omega0);
            ref.W.clear();
            for (double t : ref.times) ref.W.push_back(rigid::free_body_exact_omega(ref.exact, t));
            ref.R = rigid::free_body_exact_rotations(ref.exact, ref.times);
        },
        p.repeats);
    return ref;
}

// The sweep against the reference. Rows: method id, param, time, rhs, err_Omega, err_R, dE, dM, orth.
std::vector<std::vector<double>> sweep(const Params& p, const Reference& ref) {
    const Vec3 &I = p.I, &w0 = p.Omega0;
    const double E0 = rigid::rotational_energy(I, w0), M0 = rigid::angular_momentum_squared(I, w0);
    return kit::timed_sweep(
        p.repeats, [&](const kit::SweepCase& c) { return scene3::integrate(I, w0, ref.times, c.method, c.param); },
        [&](const kit::SweepCase& c, const scene3::Run& run, double t) {
            double eO = 0, eR = 0, dE = 0, dM = 0, orth = 0;
            for (std::size_t k = 0; k < ref.times.size(); ++k) {
                eO = std::max(eO, (run.Omega[k] - ref.W[k]).norm() / w0.norm());
                eR = std::max(eR, rigid::geodesic_angle(ref.R[k], run.R[k]));
                dE = std::max(dE, std::abs(rigid::rotational_energy(I, run.Omega[k]) - E0) / E0);
                dM = std::max(dM, std::abs(rigid::angular_momentum_squared(I, run.Omega[k]) - M0) / M0);
                orth = std::max(orth, rigid::orthogonality_defect(run.R[k]));
            }
            return std::vector<double>{
                kit::sweep_method_id(c.method), c.param, t, double(run.work), eO, eR, dE, dM, orth};
        });
}

void report(kit::Scene& scene, const Params& p, const Reference& ref, const std::vector<std::vector<double>>& rows) {
    double head_err = 0, head_time = 0;
    for (const auto& r : rows)
        if (r[0] == 2 && r[1] == 1e-12) head_err = std::max(r[4], r[5]), head_time = r[2];
    scene.report.headline(
        "rk8pd at tol 1e-12: max over outputs of |Omega - Omega_exact| / |Omega(0)| and the "
        "angle between R and R_exact",
        head_err, head_time);
    scene.report.add("T", p.T);
    scene.report.add("m", ref.exact.m, "elliptic parameter of the motion");
    scene.report.add("reference_time_s", ref.time, "exact Omega and R at every output time");
    scene.report.table("work_precision",
                       {"method(0=rk4,1=rkf45,2=rk8pd)", "h_or_tol", "time_s", "rhs_calls", "err_Omega", "err_R_rad",
                        "energy_drift", "momentum_drift", "orthogonality"},
                       rows);
}

void draw(kit::Scene& scene, const Params& p, const std::vector<std::vector<double>>& rows) {
    auto series = [&](int id, int col) { return kit::points_where(rows, 0, id, 2, {std::size_t(col)}); };
    kit::Figure fig(scene, "free_body_work_precision.svg", 820, 520);
    fig.script(kit::gp::free_body_work_precision, {{"T", std::to_string(int(p.T))}});
    for (int id = 0; id < 3; ++id) fig.data(kit::points_where(rows, 0, id, 2, {4, 5}));
    fig.finish();

    kit::Figure fd(scene, "free_body_drift.svg", 1000, 430);
    fd.script(kit::gp::drift);
    fd.data(series(0, 6)).data(series(1, 6)).data(series(2, 6));
    fd.script(kit::gp::orthogonality);
    fd.data(series(0, 8)).data(series(1, 8)).data(series(2, 8));
    fd.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("free_body_work_precision",
                      "Chapter 3: error against run time, student RK4 vs GSL rkf45 and rk8pd");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        check(o, p);
        const Reference ref = reference(p);
        const auto rows = sweep(p, ref);
        report(scene, p, ref, rows);
        draw(scene, p, rows);
    });
}
