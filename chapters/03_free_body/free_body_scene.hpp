// What the Chapter 3 scenes share: initial data on a chosen polhode, and one way to integrate
// the student's free-body equations with either the student's RK4 or a GSL method.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "rigid/free_body.hpp"
#include "rigid/integrators.hpp"
#include "rigid/ode.hpp"
#include "sweep.hpp"

namespace scene3 {

using rigid::Mat3;
using rigid::Vec3;
using rigid::VecX;

// The axes sorted by moment: lo, mid, hi.
inline std::array<int, 3> sorted_axes(const Vec3& I) {
    std::array<int, 3> o{0, 1, 2};
    std::stable_sort(o.begin(), o.end(), [&](int x, int y) { return I(x) < I(y); });
    return o;
}

// snippet: polhode_start
// A point of the polhode with energy E and M^2 = 2 E D (I_lo <= D <= I_hi) where it crosses
// the plane Omega_mid = 0: solve I_lo W_lo^2 + I_hi W_hi^2 = 2E, I_lo^2 W_lo^2 + I_hi^2 W_hi^2 = 2E D.
inline Vec3 polhode_start(const Vec3& I, double E, double D) {
    const auto [lo, mid, hi] = sorted_axes(I);
    Vec3 w = Vec3::Zero();
    w(lo) = std::sqrt(std::max(0.0, 2 * E * (I(hi) - D) / (I(lo) * (I(hi) - I(lo)))));
    w(hi) = std::sqrt(std::max(0.0, 2 * E * (D - I(lo)) / (I(hi) * (I(hi) - I(lo)))));
    (void)mid;
    return w;
}
// end snippet

// About how many steps a GSL method takes per radian of a free body's phase at tolerance tol
// (for the scenes' work estimates; measured on the default bodies, within a factor 3).
inline double steps_per_radian(const std::string& method, double tol) {
    const int order = method == "rk2" ? 2 : method == "rk8pd" ? 8 : method == "msadams" ? 6 : 4;
    return 0.3 * std::pow(tol, -1.0 / order);
}

// The trajectory of one integration, at the output times.
struct Run {
    std::vector<Vec3> Omega;
    std::vector<Mat3> R;
    long work = 0;  // right-hand side calls
};

// Records each output time's Omega and R into run.
inline rigid::OdeObserver recorder(Run& run, std::size_t n) {
    run.Omega.reserve(n);
    run.R.reserve(n);
    return [&run](double, const VecX& y) {
        const rigid::BodyState s = rigid::unpack(y);
        run.Omega.push_back(s.Omega);
        run.R.push_back(s.R);
    };
}

// method: "rk4" = the student's integrate_rk4 with step h; anything else = that GSL method at tol.
inline Run integrate(const Vec3& I, const Vec3& Omega0, const std::vector<double>& times, const std::string& method,
                     double tol_or_h) {
    Run run;
    const rigid::OdeObserver observe = recorder(run, times.size());
    run.work = kit::integrate_by_name(rigid::free_body_equations(I), rigid::pack({Omega0, Mat3::Identity()}), times,
                                      observe, method, tol_or_h);
    return run;
}

// Always a GSL method by name, at tolerance tol: "rk4" is GSL's (polhodes --method).
inline Run integrate_gsl(const Vec3& I, const Vec3& Omega0, const std::vector<double>& times, const std::string& method,
                         double tol) {
    Run run;
    const rigid::OdeObserver observe = recorder(run, times.size());
    run.work = rigid::integrate_gsl(rigid::free_body_equations(I), rigid::pack({Omega0, Mat3::Identity()}), times,
                                    observe, {.method = method, .rel_tol = tol, .abs_tol = tol})
                   .rhs_calls;
    return run;
}

}  // namespace scene3
