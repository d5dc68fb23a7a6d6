// What the scenes of Chapters 3 and 8 share when they integrate: a method given by name (the
// student's RK4 with a step, or a GSL method with a tolerance) and the grid of their
// work-precision sweeps. Chapter 7's bench (07_numerics/bench.hpp) is the general version:
// many more methods behind one interface, on the heavy top's state only.
//
// Header-only: a scene that includes it links the integrators topic (rigid/integrators.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include "rigid/integrators.hpp"
#include "rigid/ode.hpp"
#include "scene.hpp"

namespace kit {

// method: "rk4" = the student's integrate_rk4 with step h_or_tol; anything else = that GSL
// method at the (relative and absolute) tolerance h_or_tol. Returns the right-hand side calls.
inline long integrate_by_name(const rigid::OdeRhs& f, const rigid::VecX& y0, const std::vector<double>& times,
                              const rigid::OdeObserver& observe, const std::string& method, double h_or_tol) {
    if (method == "rk4") return 4 * rigid::integrate_rk4(f, y0, times, observe, h_or_tol);
    return rigid::integrate_gsl(f, y0, times, observe, {.method = method, .rel_tol = h_or_tol, .abs_tol = h_or_tol})
        .rhs_calls;
}

// One run of a sweep: the method's name and its step (rk4) or tolerance (GSL).
struct SweepCase {
    std::string method;
    double param;
};

// The sweep of Chapters 3 and 8: RK4 at eight steps h from 0.2 to 0.001, rkf45 at the ten
// tolerances 1e-4 ... 1e-13 and rk8pd at the eleven 1e-4 ... 1e-14 (29 runs).
inline std::vector<SweepCase> rk4_rkf45_rk8pd_sweep() {
    std::vector<SweepCase> cases;
    for (double h : {0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001}) cases.push_back({"rk4", h});
    for (int e = 4; e <= 13; ++e) cases.push_back({"rkf45", std::pow(10.0, -e)});
    for (int e = 4; e <= 14; ++e) cases.push_back({"rk8pd", std::pow(10.0, -e)});
    return cases;
}

// The method's column in the sweeps' tables: 0 rk4, 1 rkf45, 2 rk8pd.
inline double sweep_method_id(const std::string& method) { return method == "rk4" ? 0 : method == "rkf45" ? 1 : 2; }

// Every case of that sweep, timed: run(c) integrates once and returns its run (the smallest
// time of `repeats` calls is kept), row(c, run, seconds) makes the case's row of the table.
template <class Run, class Row>
std::vector<std::vector<double>> timed_sweep(int repeats, Run run, Row row) {
    std::vector<std::vector<double>> rows;
    for (const SweepCase& c : rk4_rkf45_rk8pd_sweep()) {
        decltype(run(c)) result;
        const double t = min_time([&] { result = run(c); }, repeats);
        rows.push_back(row(c, result, t));
    }
    return rows;
}

// The points of the rows whose column `key` is `value`, for a log-log figure: (row[x],
// the largest of the row's columns ys, at least 1e-17).
inline std::vector<std::vector<double>> points_where(const std::vector<std::vector<double>>& rows, std::size_t key,
                                                     double value, std::size_t x,
                                                     std::initializer_list<std::size_t> ys) {
    std::vector<std::vector<double>> out;
    for (const auto& r : rows) {
        if (r[key] != value) continue;
        double y = 1e-17;
        for (std::size_t c : ys) y = std::max(y, r[c]);
        out.push_back({r[x], y});
    }
    return out;
}

}  // namespace kit
