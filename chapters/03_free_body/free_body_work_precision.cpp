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
#include "rigid/free_body_exact.hpp"
#include "rigid/require.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

using rigid::Mat3;
using rigid::Vec3;

int main(int argc, char** argv) {
    kit::Options opts("free_body_work_precision", "Chapter 3: error against run time, student RK4 vs GSL rkf45 and rk8pd");
    opts.vector("I", Vec3(2, 3, 4), "principal moments I1,I2,I3", kit::components_between(1e-3, 1e3))
        .vector("Omega0", Vec3(1.0, 0.6, -0.8), "initial angular velocity (body frame)", kit::components_between(-1e3, 1e3))
        .real("T", 20, "time span", kit::between(1e-3, 1e6))
        .integer("outputs", 40, "output times where the error is measured", 1, 10000)
        .integer("repeats", 5, "timing repetitions (the minimum is kept)", 1, 50);

    return kit::run(argc, argv, opts, [](const kit::Options& o, kit::Scene& scene) {
        const Vec3 I = o.vector("I"), w0 = o.vector("Omega0");
        kit::require_moments(I, "I", {kit::Order::any});
        if (!(w0.norm() > 0)) throw kit::BadInput("--Omega0 must not be zero");
        const double T = o.real("T");
        const int repeats = static_cast<int>(o.integer("repeats"));
        const auto times = rigid::linspace(0, T, static_cast<int>(o.integer("outputs")));
        // The work: RK4 at eight steps h (sum of T / h = 1885 T steps), rkf45 and rk8pd at ten
        // and eleven tolerances (about 9000 evaluations per radian turned), each `repeats` times.
        kit::require_budget(o, {repeats * (1885 * T * 4 + 9000 * w0.norm() * T), 1.5e-7, "evaluations of the equations",
                                "--T, --Omega0, --repeats"});
        // Every output time stops each of the 29 runs and is measured: about 1.2 us each.
        kit::require_budget(o, {29.0 * repeats * double(times.size()), 1.2e-6, "output times (all runs)", "--outputs, --repeats"});

        // The reference, and what it costs.
        rigid::FreeBodyMotion exact;
        std::vector<Vec3> W;
        std::vector<Mat3> Rx;
        const double ref_time = kit::min_time([&] {
            exact = rigid::free_body_motion(I, w0);
            W.clear();
            for (double t : times) W.push_back(rigid::free_body_exact_omega(exact, t));
            Rx = rigid::free_body_exact_rotations(exact, times);
        }, repeats);
        const double E0 = rigid::rotational_energy(I, w0), M0 = rigid::angular_momentum_squared(I, w0);

        const std::vector<kit::SweepCase> cases = kit::rk4_rkf45_rk8pd_sweep();

        std::vector<std::vector<double>> rows;  // method id, param, time, rhs, err_Omega, err_R, dE, dM, orth
        double head_err = 0, head_time = 0;
        for (const kit::SweepCase& c : cases) {
            scene3::Run run;
            const double t = kit::min_time([&] { run = scene3::integrate(I, w0, times, c.method, c.param); }, repeats);
            double eO = 0, eR = 0, dE = 0, dM = 0, orth = 0;
            for (std::size_t k = 0; k < times.size(); ++k) {
                eO = std::max(eO, (run.Omega[k] - W[k]).norm() / w0.norm());
                eR = std::max(eR, rigid::geodesic_angle(Rx[k], run.R[k]));
                dE = std::max(dE, std::abs(rigid::rotational_energy(I, run.Omega[k]) - E0) / E0);
                dM = std::max(dM, std::abs(rigid::angular_momentum_squared(I, run.Omega[k]) - M0) / M0);
                orth = std::max(orth, rigid::orthogonality_defect(run.R[k]));
            }
            const double id = kit::sweep_method_id(c.method);
            rows.push_back({id, c.param, t, double(run.work), eO, eR, dE, dM, orth});
            if (c.method == "rk8pd" && c.param == 1e-12) head_err = std::max(eO, eR), head_time = t;
        }
        scene.report.headline("rk8pd at tol 1e-12: max over outputs of |Omega - Omega_exact| / |Omega(0)| and the "
                              "angle between R and R_exact",
                              head_err, head_time);
        scene.report.add("T", T);
        scene.report.add("m", exact.m, "elliptic parameter of the motion");
        scene.report.add("reference_time_s", ref_time, "exact Omega and R at every output time");
        scene.report.table("work_precision",
                           {"method(0=rk4,1=rkf45,2=rk8pd)", "h_or_tol", "time_s", "rhs_calls", "err_Omega", "err_R_rad",
                            "energy_drift", "momentum_drift", "orthogonality"},
                           rows);

        auto series = [&](int id, int col) {
            std::vector<std::vector<double>> out;
            for (const auto& r : rows)
                if (int(r[0]) == id) out.push_back({r[2], std::max(r[col], 1e-17)});
            return out;
        };
        auto error_series = [&](int id) {
            std::vector<std::vector<double>> out;
            for (const auto& r : rows)
                if (int(r[0]) == id) out.push_back({r[2], std::max({r[4], r[5], 1e-17})});
            return out;
        };
        kit::Figure fig(scene, "free_body_work_precision.svg", 820, 520);
        fig << "set title 'Free body, T = " + std::to_string(int(T)) + ": error against run time (min over repetitions)'\n"
               "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\n"
               "set xlabel 'run time (s)'\nset ylabel 'max error: Ω (relative) and R (angle, rad)'\nset key top right\n"
               "plot '-' with linespoints ls 1 title 'student RK4, h = 0.2 ... 0.001', "
               "'-' with linespoints ls 2 title 'GSL rkf45, tol = 1e-4 ... 1e-13', "
               "'-' with linespoints ls 3 title 'GSL rk8pd, tol = 1e-4 ... 1e-14'\n";
        fig.data(error_series(0)).data(error_series(1)).data(error_series(2));
        fig.finish();

        kit::Figure fd(scene, "free_body_drift.svg", 1000, 430);
        fd << "set multiplot layout 1, 2 title 'What the integrators do to the invariants (max over the run)'\n"
              "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset xlabel 'run time (s)'\nset key bottom left font ',9'\n"
              "set title 'energy (6.9)'\nset ylabel '|E(t) - E(0)| / E(0)'\n"
              "plot '-' with linespoints ls 1 title 'student RK4', '-' with linespoints ls 2 title 'rkf45', "
              "'-' with linespoints ls 3 title 'rk8pd'\n";
        fd.data(series(0, 6)).data(series(1, 6)).data(series(2, 6));
        fd << "set title 'orthogonality of R'\nset ylabel '‖R^T R − 1‖_F'\n"
              "plot '-' with linespoints ls 1 title 'student RK4', '-' with linespoints ls 2 title 'rkf45', "
              "'-' with linespoints ls 3 title 'rk8pd'\n";
        fd.data(series(0, 8)).data(series(1, 8)).data(series(2, 8));
        fd << "unset multiplot\n";
        fd.finish();
    });
}
