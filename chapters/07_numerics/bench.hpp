// What the Chapter 7 scenes share: the scenarios, the methods behind one interface, the
// long-double reference, the error and invariant measures, and the work-precision sweep.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rigid/heavy_top.hpp"
#include "rigid/ode.hpp"

namespace bench {

using rigid::BodyState;
using rigid::HeavyTop;
using rigid::Mat3;
using rigid::Vec3;

// snippet: scenario
// One test problem: a heavy top (f = 0 for a free body; J diagonal: body axes = principal
// axes), its initial state, the time span, where the error is measured, and the fastest
// angular frequency omega (fixed steps are given as h omega, the angle turned per step).
struct Scenario {
    std::string name, title;
    HeavyTop top;
    BodyState s0;
    double T;
    int outputs;  // the error is the largest over `outputs` equally spaced times in (0, T]
    double omega;
    // The closed-form motion at the given times, where there is one (empty otherwise).
    std::function<std::vector<BodyState>(const std::vector<double>&)> exact;
    std::string exact_name;
    std::vector<double> times() const;
};
// end snippet

// Every scenario of the chapter, in the order of the tables.
std::vector<Scenario> scenarios();

// snippet: method
// One integrator behind the one interface: run() integrates the scenario with the step h
// (kind step) or the tolerance tol (kind tolerance), writes the state at every output time
// into `out` (sized by the caller, so that nothing is allocated for the output while the clock
// runs), and returns the number of evaluations of the right-hand side (for a splitting: of the
// torque). It throws std::runtime_error when the solver gives up.
enum class Kind { step, tolerance };

// The family decides the panel of the work-precision diagrams (work_precision.cpp): "implicit"
// methods in one, the other tolerance-driven (adaptive explicit) ones in another, and the
// fixed-step methods in a third; a new method finds its panel, colour and marker by itself.
struct Method {
    std::string name, label, family;
    Kind kind;
    std::function<long(const Scenario&, const std::vector<double>& times, double param, std::vector<BodyState>& out)>
        run;
};
// end snippet

// Your RK4; GSL rkf45, rk8pd, msadams; GSL rk4imp, bsimp, msbdf with the analytic Jacobian;
// RKMK4; Strang's splitting and its triple jump; the Taylor method of degree 16 in double; and
// last, rk8pd again with the time kept as an exact two-part sum (rk8pd_ct).
const std::vector<Method>& methods();
const Method& method(const std::string& name);

// The error and the invariants of one run, measured against a reference at the output times.
struct Metrics {
    double err_R = 0;      // largest geodesic angle between R and the reference R (rad)
    double err_Omega = 0;  // largest |Omega - Omega_ref| / max |Omega_ref|
    double error = 0;      // the larger of the two: the y axis of the diagrams
    double dH = 0;         // largest |H - H(0)| / (kinetic energy(0) + f)
    double dL = 0;         // largest drift of the angular momentum kept by the flow, / |J Omega(0)|:
                           // the vertical component (k, R J Omega) for a heavy top, the whole
                           // vector R J Omega for a free body
    double orth = 0;       // largest ||R^T R - 1||_F
};
Metrics measure(const Scenario& sc, const std::vector<BodyState>& reference, const std::vector<BodyState>& run);

// snippet: reference
// The reference of a scenario: the Taylor method of degree `order` in long double with the
// step h = 0.1 / omega, from the same double-precision initial data as every method.
struct Reference {
    std::vector<BodyState> states;  // at the output times, rounded to double
    double h = 0;
    int order = 24;
    double time_s = 0;             // its run time
    double self_difference = -1;   // largest difference from the same at h/2 (long double); -1: not run
    double exact_difference = -1;  // largest difference from the closed form; -1: none
    double double_floor = 0;       // the same steps in double, against it: the round-off floor
    double kappa = 0;              // how much the flow magnifies a change of the initial state
                                   // (largest over the outputs; measured with a change of 1e-9)
    double expected_floor = 0;     // Brouwer's estimate for that floor: eps kappa sqrt(steps)
};
// conditioning false: kappa and expected_floor are left 0 (one long-double run fewer).
Reference reference(const Scenario& sc, bool self_check, bool conditioning = true);
// end snippet

// How much work a sweep may do. Work, not seconds: a run's cost is its evaluations times the
// method's cost of one (seconds_per_evaluation, a constant), so that the same points are run,
// and the same slopes fitted, on an idle machine and on a loaded one; only the run times differ.
struct Budget {
    std::string name;
    int repeats;         // timing repetitions (the minimum is kept)
    double max_run_s;    // a method's sweep stops after a run whose cost is over this
    double max_sweep_s;  // or when the costs of its runs, repetitions included, add up to more than this
    long max_steps;      // fixed-step sweeps stop before more steps than this
    double step_factor;  // ratio of consecutive steps h
    double tol_factor;   // ratio of consecutive tolerances
    bool self_check;     // run the reference again at h/2
};
Budget budget(const std::string& name);  // "smoke", "quick" or "full"

// The cost of one evaluation of the right-hand side by a method (for the Taylor method: one
// sixteenth of a step), in seconds: the median over the quick sweep's runs longer than 2 ms,
// measured on one core of the 2-core machine, idle. The sweep's stopping rule, never a result.
double seconds_per_evaluation(const std::string& method);

// One point of a work-precision diagram.
struct Point {
    std::string scenario, method;
    double param = 0;   // h or tol
    double time_s = 0;  // minimum over the repetitions
    int repeats = 0;
    long evaluations = 0, steps = 0;
    Metrics m;
    bool failed = false;
    std::string why;  // when failed
};

// The sweep of one method on one scenario: parameters from loose to tight, each run timed
// (minimum over budget.repeats; at least 10 for runs that cost under 5 ms unless the budget asks
// for 1), stopped by the budget (on the runs' costs, not their times) or when the error has not
// improved for two points in a row (the round-off floor). progress() is called before each run.
std::vector<Point> sweep(const Scenario& sc, const Method& meth, const Reference& ref, const Budget& b,
                         const std::function<void(const std::string&)>& progress);

// The run time at which a method's lower envelope first reaches `target`, interpolated
// log-log between the two points around it; NaN if it never does.
double time_to_reach(const std::vector<Point>& points, double target);

// snippet: rhs_cost
// The run time of one evaluation of the right-hand side (3.1)-(3.2), in ns, in one run:
//   teaching: your euler_poisson_rhs through OdeRhs, as integrate_gsl hands it to GSL (a VectorXd
//             view in, pack/unpack, a new VectorXd out, copied; a Cholesky solve with J);
//   fast:     rigid::EulerPoissonInPlace through OdeRhsInPlace, as GSL calls it (in place, J^-1 once);
//   plain:    a hand-written loop on std::array<double, 12>, called directly.
// And how far the three agree on 1000 random states (largest difference / max |dy/dt|).
struct RhsCost {
    double teaching_ns = 0, fast_ns = 0, plain_ns = 0;
    double fast_vs_teaching = 0, fast_vs_plain = 0;
};
// end snippet
RhsCost rhs_cost(const HeavyTop& top, const BodyState& s);

// Smallest error of a sweep, and the point that reached it.
const Point* best(const std::vector<Point>& points);

}  // namespace bench
