// Chapter 8 scene: error against run time for the three motions of this chapter that have an
// exact solution: the plain precession (6.2) with beta = 0 (S(t) = R^B(-(e/mc)|B| t) S0), the
// aligning spin (6.2) with beta > 0 (spin_exact), and the oscillator (6.1) started on a level
// (harmonic, frequency omega / sqrt(m)). The student's fixed-step RK4 (a sweep of steps) and
// GSL's rkf45 and rk8pd (a sweep of tolerances) integrate the student's right-hand sides; each
// run is measured against the exact motion, with its invariant (|S|, the energy) alongside.
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "figure.hpp"
#include "quantized_scene.hpp"
#include "quantized_work_precision.gp.hpp"
#include "rigid/ode.hpp"
#include "rigid/quantized.hpp"
#include "scene.hpp"

using rigid::Vec3;
using rigid::VecX;

namespace {

struct Params {
    Vec3 B = Vec3(0.3, -0.4, 1.2);
    double e_over_mc = 2.0;
    double beta = 0.5;
    Vec3 S0 = Vec3(0.8, 0.5, 0.3);
    scene8::OscillatorParams osc;
    int level = 2;
    double T = 20;
    int outputs = 40, repeats = 5;
};

void declare(kit::Options& opts, Params& p) {
    opts.vector("B", &p.B, "the magnetic field B", kit::nonzero_vector(-1e3, 1e3))
        .real("e_over_mc", &p.e_over_mc, "e/mc (either sign)", kit::between(-1e3, 1e3))
        .real("beta", &p.beta, "beta of the aligning spin (the plain precession has beta = 0)", kit::between(1e-6, 1e3))
        .vector("S0", &p.S0, "the initial spin", kit::nonzero_vector(-1e3, 1e3));
    scene8::oscillator_options(opts, p.osc);
    opts.integer("level", &p.level, "the level n the oscillator starts on, E = n E0", 1, 100)
        .real("T", &p.T, "time span", kit::between(1e-2, 1e6))
        .integer("outputs", &p.outputs, "output times where the error is measured", 1, 10000)
        .integer("repeats", &p.repeats, "timing repetitions (the minimum is kept)", 1, 50);
}

// A problem with an exact motion: right-hand side, initial state, error and invariant drift at output i.
struct Problem {
    std::string name;
    rigid::OdeRhs f;
    VecX y0;
    std::function<double(std::size_t, const VecX&)> error, drift;
};

struct Setup {
    rigid::SpinField aligning, plain;
    rigid::Oscillator osc;
    rigid::LevelFriction k;
    double E_on, w;  // the oscillator's energy on its level, its frequency omega / sqrt(m)
    std::vector<double> times;
};

Setup setup(const kit::Options& o, const Params& p) {
    Setup u{{p.B, p.e_over_mc, p.beta},        {}, scene8::oscillator_from(p.osc), scene8::friction_from(p.osc), 0, 0,
            rigid::linspace(0, p.T, p.outputs)};
    u.plain = u.aligning;
    u.plain.beta = 0;
    u.E_on = double(p.level) * u.k.E0;
    u.w = u.osc.omega / std::sqrt(u.osc.m);
    // The work, per problem (three) and repetition: RK4 at eight steps h (1885 T steps in
    // all, 4 evaluations each) and rkf45, rk8pd at 21 tolerances (about 9000 evaluations per
    // radian of the fastest phase: the spin's precession or the oscillator's).
    const double rate = std::max(
        {std::abs(u.aligning.e_over_mc) * u.aligning.B.norm() * (1 + u.aligning.beta * p.S0.norm()), u.w, 1.0});
    // Every output time stops the adaptive methods too: at least 21 x 15 evaluations each.
    kit::require_budget(o, {3.0 * p.repeats * (1885 * p.T * 4 + 9000 * rate * p.T + 29 * 15 * double(u.times.size())),
                            1e-7, "evaluations", "--T, --repeats, --outputs, --B, --e_over_mc, --beta, --omega, --m"});
    return u;
}

Problem spin_problem(const std::string& name, const rigid::SpinField& field, const Vec3& S0,
                     const std::vector<double>& times) {
    std::vector<Vec3> exact;
    for (double t : times) exact.push_back(rigid::spin_exact(field, S0, t));
    return Problem{
        name, rigid::spin_equations(field), VecX{{S0(0), S0(1), S0(2)}},
        [exact, s = S0.norm()](std::size_t i, const VecX& y) { return (Vec3(y(0), y(1), y(2)) - exact[i]).norm() / s; },
        [s = S0.norm()](std::size_t, const VecX& y) { return std::abs(Vec3(y(0), y(1), y(2)).norm() - s) / s; }};
}

// The three problems: the plain precession, the aligning spin, the oscillator on a level.
std::vector<Problem> problems(const Setup& u, const Vec3& S0) {
    const VecX y_osc = scene8::at_energy(u.osc, u.E_on);
    return {spin_problem("plain precession (6.2), β = 0", u.plain, S0, u.times),
            spin_problem("aligning spin (6.2)", u.aligning, S0, u.times),
            Problem{"oscillator (6.1) on a level", rigid::oscillator_equations(u.osc, u.k), y_osc,
                    [y_osc, w = u.w, times = u.times](std::size_t i, const VecX& y) {
                        const double t = times[i], q0 = y_osc(0);
                        return std::max(std::abs(y(0) - q0 * std::cos(w * t)) / q0,
                                        std::abs(y(1) + q0 * w * std::sin(w * t)) / (q0 * w));
                    },
                    [osc = u.osc, E_on = u.E_on](std::size_t, const VecX& y) {
                        return std::abs(rigid::oscillator_energy(osc, y(0), y(1)) - E_on) / E_on;
                    }}};
}

// Every problem by every case of the sweep. Rows: problem, method, param, time, rhs calls,
// error, drift.
std::vector<std::vector<double>> sweep(const std::vector<Problem>& problems, const std::vector<double>& times,
                                       int repeats) {
    std::vector<std::vector<double>> rows;
    for (std::size_t p = 0; p < problems.size(); ++p) {
        const Problem& pr = problems[p];
        for (const kit::SweepCase& c : kit::rk4_rkf45_rk8pd_sweep()) {
            scene8::Run run;
            const double t =
                kit::min_time([&] { run = scene8::integrate(pr.f, pr.y0, times, c.method, c.param); }, repeats);
            double err = 0, drift = 0;
            for (std::size_t i = 0; i < times.size(); ++i) {
                err = std::max(err, pr.error(i, run.y[i]));
                drift = std::max(drift, pr.drift(i, run.y[i]));
            }
            if (!std::isfinite(err))
                throw kit::NumericalFailure(pr.name + ": " + c.method + " gave a non-finite state");
            rows.push_back({double(p), kit::sweep_method_id(c.method), c.param, t, double(run.work), err, drift});
        }
    }
    return rows;
}

void report(kit::Scene& scene, const Params& p, const Setup& u, const Problem& oscillator,
            const std::vector<std::vector<double>>& rows) {
    double head_err = 0, head_time = 0;
    for (const auto& r : rows)
        if (r[0] == 0 && r[1] == 2 && r[2] == 1e-12) head_err = r[5], head_time = r[3];
    scene.report.headline(
        "plain precession (beta = 0), rk8pd at tol 1e-12: max |S - R^B(-(e/mc)|B|t) S0| / |S0| "
        "over the outputs",
        head_err, head_time);
    scene.report.add("T", p.T);
    {  // RK4 with the coarsest step leaves the level: its stages feel friction the exact motion does not.
        const scene8::Run coarse = scene8::integrate(oscillator.f, oscillator.y0, u.times, "rk4", 0.2);
        double lowest = 1e300;
        for (const auto& y : coarse.y) lowest = std::min(lowest, rigid::oscillator_energy(u.osc, y(0), y(1)) / u.k.E0);
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
}

void draw(kit::Scene& scene, const Params& p, const std::vector<Problem>& problems,
          const std::vector<std::vector<double>>& rows) {
    kit::Figure fig(scene, "quantized_work_precision.svg", 1200, 430);
    if (!fig.enabled()) return;
    fig.script(kit::gp::quantized_work_precision, {{"T", std::to_string(int(p.T))}});
    for (std::size_t k = 0; k < problems.size(); ++k) {
        // One key, where there is room.
        fig.script(
            k == 1 ? kit::gp::key_panel : kit::gp::panel,
            {{"title", kit::quoted(problems[k].name)}, {"ylabel", kit::quoted(k == 0 ? "max error (relative)" : "")}});
        for (int id = 0; id < 3; ++id) {
            std::vector<std::vector<double>> pts;
            for (const auto& r : rows)
                if (r[0] == double(k) && r[1] == id) pts.push_back({r[3], std::max(r[5], 1e-17)});
            fig.data(pts);
        }
    }
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("quantized_work_precision",
                      "Chapter 8: error against run time, student RK4 vs GSL rkf45 and rk8pd, on the exact motions");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        const Setup u = setup(o, p);
        const std::vector<Problem> probs = problems(u, p.S0);
        const auto rows = sweep(probs, u.times, p.repeats);
        report(scene, p, u, probs[2], rows);
        draw(scene, p, probs, rows);
    });
}
