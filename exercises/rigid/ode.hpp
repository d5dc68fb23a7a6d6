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

using OdeRhs = std::function<VecX(double t, const VecX& y)>;       // f(t, y)
using OdeJacobian = std::function<MatX(double t, const VecX& y)>;  // df/dy, n x n
using OdeObserver = std::function<void(double t, const VecX& y)>;

struct OdeSettings {
    std::string method = "rk8pd";
    double rel_tol = 1e-12;
    double abs_tol = 1e-12;
    double first_step = 1e-3;
    long max_steps = 0;  // per output interval; 0 = no limit
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
OdeStats integrate_gsl(const OdeRhs& f, const VecX& y0, const std::vector<double>& times,
                       const OdeObserver& observe, const OdeSettings& settings = {},
                       const OdeJacobian& jacobian = {});

// n + 1 equally spaced times from t0 to t1 (n >= 1), ending exactly at t1.
std::vector<double> linspace(double t0, double t1, int n);

// The rigid body's Euler-Poisson state: body angular velocity and rotation matrix.
struct BodyState {
    Vec3 Omega;
    Mat3 R;
};
VecX pack(const BodyState& s);          // 12 numbers: Omega, then R row by row
BodyState unpack(const VecX& y);        // throws std::invalid_argument unless y.size() == 12

}  // namespace rigid
