// Chapter 7 scene: one point of the work-precision diagram. One method of bench::methods() on one
// scenario of bench::scenarios(), with one step (fixed-step methods: --h_omega, the angle turned
// per step) or one tolerance (adaptive methods: --tol), timed (minimum over --repeats) and
// measured exactly as work_precision measures each point of its sweeps: against the long-double
// Taylor reference, at the scenario's output times. Its figure: how that run's error and energy
// drift grow along the time span, beside the double-precision floor. The scene the book's
// Chapter 7 runs live (cmake/book/live/work_precision_point.json).
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "bench.hpp"
#include "figure.hpp"
#include "scene.hpp"
#include "work_precision_point.gp.hpp"

namespace {

// The scene's parameters, bound to its options.
struct Params {
    std::string scenario = "grioli", method = "rk4";
    double h_omega = 0.1, tol = 1e-8;
    long repeats = 3;
};

void declare(kit::Options& opts, Params& p) {
    std::vector<std::string> scenarios, methods;
    for (const bench::Scenario& s : bench::scenarios()) scenarios.push_back(s.name);
    for (const bench::Method& m : bench::methods()) methods.push_back(m.name);
    opts.choice("scenario", &p.scenario, scenarios, "the test problem (work_precision's scenarios)")
        .choice("method", &p.method, methods, "the integrator (work_precision's methods)")
        .real("h_omega", &p.h_omega, "a fixed-step method's step h times the scenario's fastest frequency omega",
              kit::between(1e-3, 2))
        .real("tol", &p.tol, "an adaptive method's tolerance (relative and absolute)", kit::between(1e-14, 1e-2))
        .integer("repeats", &p.repeats, "timing repetitions (the minimum is kept)", 1, 50);
}

// The long-double reference of a scenario (without its conditioning, which the scene does not
// report), computed once per process: the book's page keeps its module loaded and runs the scene
// again at each move of a control, with the same reference (long double is binary128 in
// WebAssembly, in software: seconds there).
const bench::Reference& reference_of(const bench::Scenario& sc) {
    static std::map<std::string, bench::Reference> cache;
    auto it = cache.find(sc.name);
    if (it == cache.end()) it = cache.emplace(sc.name, bench::reference(sc, false, false)).first;
    return it->second;
}

struct Run {
    const bench::Scenario* sc;
    const bench::Method* method;
    double param;  // h or tol
    std::vector<double> times;
    std::vector<rigid::BodyState> out;
    long evaluations = 0;
    double time_s = 0;
    bench::Metrics m;
};

// The work: the method's steps (a fixed step), or about tol^(-1/5) steps a radian (adaptive,
// generous for the fifth-order rkf45), each repetition; a step costs about 2 microseconds.
void require_work(const kit::Options& o, const bench::Scenario& sc, const bench::Method& m, const Params& p) {
    const double radians = sc.T * sc.omega;
    const double steps =
        m.kind == bench::Kind::step ? radians / p.h_omega : radians * std::max(1.0, std::pow(p.tol, -0.2));
    kit::require_budget(o, {steps * double(p.repeats), 2e-6, "steps", "--h_omega, --tol, --scenario, --repeats"});
}

Run run(const bench::Scenario& sc, const bench::Method& method, const Params& p) {
    Run r{&sc, &method, method.kind == bench::Kind::step ? p.h_omega / sc.omega : p.tol, sc.times(), {}, 0, 0, {}};
    r.out.resize(r.times.size());
    try {
        r.time_s = kit::min_time([&] { r.evaluations = method.run(sc, r.times, r.param, r.out); },
                                 static_cast<int>(p.repeats));
    } catch (const std::runtime_error& e) {
        throw kit::NumericalFailure(method.name + " gave up on " + sc.name + ": " + e.what());
    }
    r.m = bench::measure(sc, reference_of(sc).states, r.out);
    // A step too large for the method (an explicit one on the needle, say) blows the solution
    // up: work_precision marks such a point failed; here it is the scene's one result.
    if (!std::isfinite(r.m.error))
        throw kit::NumericalFailure("the solution of " + method.name + " on " + sc.name + " is not finite at " +
                                    (method.kind == bench::Kind::step ? "h omega = " + std::to_string(p.h_omega)
                                                                      : "tol = " + std::to_string(p.tol)) +
                                    ": the method is unstable there (take a smaller step or tolerance)");
    return r;
}

void report_run(kit::Report& report, const Run& r) {
    const bench::Reference& ref = reference_of(*r.sc);
    const bool step = r.method->kind == bench::Kind::step;
    report.headline("one run of " + r.method->label + " on " + r.sc->title +
                        ": the larger of the angle between R and the long-double reference (rad) and "
                        "|Omega - Omega_ref| / max|Omega_ref|, largest over the output times",
                    r.m.error, r.time_s);
    report.add("scenario", r.sc->name);
    report.add("method", r.method->name);
    report.add("kind", std::string(step ? "step" : "tolerance"), "which of --h_omega and --tol the method used");
    report.add("h_or_tol", r.param, "the step h (a fixed-step method) or the tolerance (an adaptive one)");
    report.add("omega", r.sc->omega, "the scenario's fastest angular frequency (rad/s)");
    report.add("evaluations", r.evaluations, "evaluations of the right-hand side (for a splitting: of the torque)");
    report.add("err_R", r.m.err_R, "largest angle between R and the reference (rad)");
    report.add("err_Omega", r.m.err_Omega, "largest |Omega - Omega_ref| / max |Omega_ref|");
    report.add("energy_drift", r.m.dH, "largest |H - H(0)| / (kinetic energy(0) + f)");
    report.add("momentum_drift", r.m.dL, "largest drift of the conserved angular momentum / |J Omega(0)|");
    report.add("orthogonality", r.m.orth, "largest ||R^T R - 1||_F");
    report.add("double_floor", ref.double_floor, "the reference's steps in double against it: the round-off floor");
    report.add("error_over_floor", r.m.error / ref.double_floor);
}

// The error and the energy drift up to each output time (the largest so far, as the diagram's
// error is the largest over them all), and the floor.
void draw_growth(kit::Scene& scene, const Run& r) {
    kit::Figure fig(scene, "work_precision_point.svg", 820, 480);
    if (!fig.enabled()) return;
    const bench::Reference& ref = reference_of(*r.sc);
    std::vector<std::vector<double>> error, energy, floor;
    for (std::size_t i = 1; i < r.times.size(); ++i) {
        const std::vector<rigid::BodyState> want(ref.states.begin(), ref.states.begin() + long(i) + 1),
            got(r.out.begin(), r.out.begin() + long(i) + 1);
        const bench::Metrics m = bench::measure(*r.sc, want, got);
        error.push_back({r.times[i], std::max(m.error, 1e-17)});
        energy.push_back({r.times[i], std::max(m.dH, 1e-17)});
        floor.push_back({r.times[i], ref.double_floor});
    }
    fig.script(kit::gp::work_precision_point,
               {{"title", kit::quoted(r.method->label + " on " + r.sc->title)}, {"T", std::to_string(r.sc->T)}});
    fig.data(error).data(energy).data(floor);
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("work_precision_point",
                      "Chapter 7: one method, one step or tolerance: its point of the work-precision diagram");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&p](const kit::Options& o, kit::Scene& scene) {
        const bench::Method& method = bench::method(p.method);
        const auto all = bench::scenarios();
        const bench::Scenario& sc =
            *std::find_if(all.begin(), all.end(), [&](const auto& s) { return s.name == p.scenario; });
        require_work(o, sc, method, p);
        const Run r = run(sc, method, p);
        report_run(scene.report, r);
        draw_growth(scene, r);
    });
}
