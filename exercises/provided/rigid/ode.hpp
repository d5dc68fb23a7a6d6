// Integration of ordinary differential equations through GSL's odeiv2: the workbook's one
// interface to library solvers. Provided, not an exercise (the student writes a fixed-step
// RK4 in Chapter 3; the rest of the book uses this).
//
// Conventions for this file
//   * A state is an Eigen::VectorXd y; the equations are dy/dt = f(t, y).
//   * The Euler-Poisson state of a rigid body [P, (6.7)-(6.8), (3.1)-(3.2)] is packed as
//     y = (Omega_1, Omega_2, Omega_3, R_11, R_12, R_13, R_21, ..., R_33): Omega first, then
//     R row by row. pack() and unpack() are the only places that know this layout.
//   * Method names are GSL's: rk2, rk4 (GSL's, with step doubling), rkf45, rkck, rk8pd,
//     msadams (explicit); rk1imp, rk2imp, rk4imp, bsimp, msbdf (implicit: they need the
//     Jacobian df/dy, passed as the last argument).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rigid/types.hpp"

namespace rigid {

using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;

using OdeRhs = std::function<VecX(double t, const VecX& y)>;  // f(t, y)
// The same in place, as GSL itself calls a right-hand side: dydt = f(t, y) written into dydt,
// y and dydt of the state's size, no allocation (Chapter 7 measures what that saves).
using OdeRhsInPlace = std::function<void(double t, const double* y, double* dydt)>;
using OdeJacobian = std::function<MatX(double t, const VecX& y)>;  // df/dy, n x n
using OdeObserver = std::function<void(double t, const VecX& y)>;

struct OdeSettings {
    std::string method = "rk8pd";
    double rel_tol = 1e-12;
    double abs_tol = 1e-12;
    double first_step = 1e-3;
    long max_steps = 0;  // per output interval; 0 = no limit
    // Explicit Runge-Kutta methods only: our own loop around gsl_odeiv2_step_apply and
    // gsl_odeiv2_control_hadjust (the steps and step sizes of GSL's driver), with the time kept
    // as an exact two-part sum t = t_hi + t_lo, so that the steps add up without rounding and
    // each output time is reached after exactly that much time (Chapter 7).
    bool compensated_time = false;
};

struct OdeStats {
    long rhs_calls = 0;
    long jacobian_calls = 0;
};

// The method names integrate_gsl accepts, and whether one needs a Jacobian.
const std::vector<std::string>& gsl_methods();
bool gsl_method_needs_jacobian(const std::string& method);

// Integrates dy/dt = f(t, y) with y(times.front()) = y0, calling observe(t, y) at every
// time in `times` (strictly increasing; the first call is the initial state itself).
// Throws std::invalid_argument for an unknown method, bad tolerances, times not increasing,
// a non-finite y0, or an implicit method without a Jacobian; std::runtime_error when the
// solver fails (its GSL status and the time reached are in the message). An exception
// thrown by f (say, a stub's not_implemented) reaches the caller unchanged.
OdeStats integrate_gsl(const OdeRhs& f, const VecX& y0, const std::vector<double>& times, const OdeObserver& observe,
                       const OdeSettings& settings = {}, const OdeJacobian& jacobian = {});
// The same with a right-hand side in place.
OdeStats integrate_gsl(const OdeRhsInPlace& f, const VecX& y0, const std::vector<double>& times,
                       const OdeObserver& observe, const OdeSettings& settings = {}, const OdeJacobian& jacobian = {});

// The run time, in seconds, of `calls` evaluations of f at states near y, each made through
// the very function that integrate_gsl hands GSL (for an OdeRhs: the call, a new VecX, a copy
// into GSL's array). For benchmarks of a right-hand side (Chapter 7). Returns the last dy/dt.
double time_gsl_calls(const OdeRhs& f, const VecX& y, long calls, VecX* last = nullptr);
double time_gsl_calls(const OdeRhsInPlace& f, const VecX& y, long calls, VecX* last = nullptr);

// n + 1 equally spaced times from t0 to t1 (n >= 1), ending exactly at t1.
std::vector<double> linspace(double t0, double t1, int n);

// The rigid body's Euler-Poisson state: body angular velocity and rotation matrix.
struct BodyState {
    Vec3 Omega;
    Mat3 R;
};
VecX pack(const BodyState& s);    // 12 numbers: Omega, then R row by row
BodyState unpack(const VecX& y);  // throws std::invalid_argument unless y.size() == 12

}  // namespace rigid
