// Chapter 8 scene: error against run time for the three motions of this chapter that have an
// exact solution: the plain precession (6.2) with beta = 0 (S(t) = R^B(-(e/mc)|B| t) S0), the
// aligning spin (6.2) with beta > 0 (spin_exact), and the oscillator (6.1) started on a level
// (harmonic, frequency omega / sqrt(m)). The student's fixed-step RK4 (a sweep of steps) and
// GSL's rkf45 and rk8pd (a sweep of tolerances) integrate the student's right-hand sides; each
// run is measured against the exact motion, with its invariant (|S|, the energy) alongside.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "figure.hpp"
#include "quantized_scene.hpp"
#include "rigid/ode.hpp"
#include "rigid/quantized.hpp"
#include "scene.hpp"

using rigid::Vec3;
using rigid::VecX;

int main(int argc, char** argv) {
    kit::Options opts("quantized_work_precision",
                      "Chapter 8: error against run time, student RK4 vs GSL rkf45 and rk8pd, on the exact motions");
    opts.vector("B", Vec3(0.3, -0.4, 1.2), "the magnetic field B", kit::nonzero_vector(-1e3, 1e3))
        .real("e_over_mc", 2.0, "e/mc (either sign)", kit::between(-1e3, 1e3))
        .real("beta", 0.5, "beta of the aligning spin (the plain precession has beta = 0)", kit::between(1e-6, 1e3))
        .vector("S0", Vec3(0.8, 0.5, 0.3), "the initial spin", kit::nonzero_vector(-1e3, 1e3));
    scene8::oscillator_options(opts, 0.5, 2.0);
    opts.integer("level", 2, "the level n the oscillator starts on, E = n E0", 1, 100)
        .real("T", 20, "time span", kit::between(1e-2, 1e6))
        .integer("outputs", 40, "output times where the error is measured", 1, 10000)
        .integer("repeats", 5, "timing repetitions (the minimum is kept)", 1, 50);

    return kit::run(argc, argv, opts, [](const kit::Options& o, kit::Scene& scene) {
        const rigid::SpinField aligning{o.vector("B"), o.real("e_over_mc"), o.real("beta")};
        rigid::SpinField plain = aligning;
        plain.beta = 0;
        const Vec3 S0 = o.vector("S0");
        const rigid::Oscillator osc = scene8::oscillator_from(o);
        const rigid::LevelFriction k = scene8::friction_from(o);
        const double T = o.real("T"), E_on = double(o.integer("level")) * k.E0, w = osc.omega / std::sqrt(osc.m);
        const int repeats = static_cast<int>(o.integer("repeats"));
        const auto times = rigid::linspace(0, T, static_cast<int>(o.integer("outputs")));
        const VecX y_osc = scene8::at_energy(osc, E_on);
        // The work, per problem (three) and repetition: RK4 at eight steps h (1885 T steps in
        // all, 4 evaluations each) and rkf45, rk8pd at 21 tolerances (about 9000 evaluations per
        // radian of the fastest phase: the spin's precession or the oscillator's).
        const double rate = std::max({std::abs(aligning.e_over_mc) * aligning.B.norm() * (1 + aligning.beta * S0.norm()), w, 1.0});
        // Every output time stops the adaptive methods too: at least 21 x 15 evaluations each.
        kit::require_budget(o, {3.0 * repeats * (1885 * T * 4 + 9000 * rate * T + 29 * 15 * double(times.size())), 1e-7,
                                "evaluations", "--T, --repeats, --outputs, --B, --e_over_mc, --beta, --omega, --m"});

        // The three problems: right-hand side, initial state, error and invariant drift at output i.
        struct Problem {
            std::string name;
            rigid::OdeRhs f;
            VecX y0;
            std::function<double(std::size_t, const VecX&)> error, drift;
        };
        auto spin_problem = [&](const std::string& name, const rigid::SpinField& field) {
            std::vector<Vec3> exact;
            for (double t : times) exact.push_back(rigid::spin_exact(field, S0, t));
            return Problem{name, rigid::spin_equations(field), VecX{{S0(0), S0(1), S0(2)}},
                           [exact, s = S0.norm()](std::size_t i, const VecX& y) {
                               return (Vec3(y(0), y(1), y(2)) - exact[i]).norm() / s;
                           },
                           [s = S0.norm()](std::size_t, const VecX& y) { return std::abs(Vec3(y(0), y(1), y(2)).norm() - s) / s; }};
        };
        std::vector<Problem> problems{
            spin_problem("plain precession (6.2), β = 0", plain),
            spin_problem("aligning spin (6.2)", aligning),
            Problem{"oscillator (6.1) on a level", rigid::oscillator_equations(osc, k), y_osc,
                    [&](std::size_t i, const VecX& y) {
                        const double t = times[i], q0 = y_osc(0);
                        return std::max(std::abs(y(0) - q0 * std::cos(w * t)) / q0,
                                        std::abs(y(1) + q0 * w * std::sin(w * t)) / (q0 * w));
                    },
                    [&](std::size_t, const VecX& y) { return std::abs(rigid::oscillator_energy(osc, y(0), y(1)) - E_on) / E_on; }}};

        const std::vector<kit::SweepCase> cases = kit::rk4_rkf45_rk8pd_sweep();

        std::vector<std::vector<double>> rows;  // problem, method, param, time, rhs calls, error, drift
        double head_err = 0, head_time = 0;
        for (std::size_t p = 0; p < problems.size(); ++p) {
            const Problem& pr = problems[p];
            for (const kit::SweepCase& c : cases) {
                scene8::Run run;
                const double t = kit::min_time([&] { run = scene8::integrate(pr.f, pr.y0, times, c.method, c.param); }, repeats);
                double err = 0, drift = 0;
                for (std::size_t i = 0; i < times.size(); ++i) {
                    err = std::max(err, pr.error(i, run.y[i]));
                    drift = std::max(drift, pr.drift(i, run.y[i]));
                }
                if (!std::isfinite(err)) throw kit::NumericalFailure(pr.name + ": " + c.method + " gave a non-finite state");
                const double id = kit::sweep_method_id(c.method);
                rows.push_back({double(p), id, c.param, t, double(run.work), err, drift});
                if (p == 0 && c.method == "rk8pd" && c.param == 1e-12) head_err = err, head_time = t;
            }
        }
        scene.report.headline("plain precession (beta = 0), rk8pd at tol 1e-12: max |S - R^B(-(e/mc)|B|t) S0| / |S0| "
                              "over the outputs",
                              head_err, head_time);
        scene.report.add("T", T);
        {  // RK4 with the coarsest step leaves the level: its stages feel friction the exact motion does not.
            const scene8::Run coarse = scene8::integrate(problems[2].f, y_osc, times, "rk4", 0.2);
            double lowest = 1e300;
            for (const auto& y : coarse.y) lowest = std::min(lowest, rigid::oscillator_energy(osc, y(0), y(1)) / k.E0);
            scene.report.add("oscillator_rk4_coarse_lowest_energy", lowest, "min E / E0 of the oscillator, RK4 at h = 0.2");
        }
        scene.report.table("work_precision",
                           {"problem(0=precession,1=aligning,2=oscillator)", "method(0=rk4,1=rkf45,2=rk8pd)", "h_or_tol",
                            "time_s", "rhs_calls", "error", "invariant_drift"},
                           rows, false);
        // A few rows in the text report: RK4 at h = 0.01 and rk8pd at 1e-12, for each problem.
        std::vector<std::vector<double>> picked;
        for (const auto& r : rows)
            if ((r[1] == 0 && r[2] == 0.01) || (r[1] == 2 && r[2] == 1e-12)) picked.push_back(r);
        scene.report.table("selected", {"problem", "method", "h_or_tol", "time_s", "rhs_calls", "error", "invariant_drift"},
                           picked);

        kit::Figure fig(scene, "quantized_work_precision.svg", 1200, 430);
        if (fig.enabled()) {
            fig << "set multiplot layout 1, 3 title 'Error against run time (min over repetitions), T = " + std::to_string(int(T)) +
                       "'\nset logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset xlabel 'run time (s)'\n"
                       "";
            for (std::size_t p = 0; p < problems.size(); ++p) {
                fig << std::string(p == 1 ? "set key top right font ',9'\n" : "unset key\n");  // one key, where there is room
                fig << "set title " + kit::quoted(problems[p].name) + "\nset ylabel " +
                           kit::quoted(p == 0 ? "max error (relative)" : "") +
                           "\nplot '-' with linespoints ls 1 title 'student RK4, h = 0.2 ... 0.001', "
                           "'-' with linespoints ls 2 title 'GSL rkf45, tol = 1e-4 ... 1e-13', "
                           "'-' with linespoints ls 3 title 'GSL rk8pd, tol = 1e-4 ... 1e-14'\n";
                for (int id = 0; id < 3; ++id) {
                    std::vector<std::vector<double>> pts;
                    for (const auto& r : rows)
                        if (r[0] == double(p) && r[1] == id) pts.push_back({r[3], std::max(r[5], 1e-17)});
                    fig.data(pts);
                }
            }
            fig << "unset multiplot\n";
            fig.finish();
        }
    });
}
