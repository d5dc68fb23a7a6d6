// The heavy body of a Grioli precession, shared by the scenes of Chapters 5, 6 and 8: its moments
// at O checked into rigid::Moments (the body's options --A --B --C --f are kit::HeavyBody's, in
// body.hpp), and what one period of a Grioli precession costs to integrate with a GSL method.
//
// Header-only: a scene that includes it links the grioli topic (rigid/grioli.hpp).
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "body.hpp"
#include "rigid/grioli.hpp"
#include "scene.hpp"

namespace kit {

// The moments of --A --B --C. A scene that forms J Omega itself (the residual E - f T of a
// trial precession, or Euler's equations in a frame where J is not diagonal) loses about
// eps C / A of its digits there (B Omega_B Omega_C - C Omega_C Omega_B cancels when B and C are
// close and A is small); it passes the largest C / A for which its checks still hold.
// rigid::moments' own message is passed on, prefixed by the options it concerns.
inline rigid::Moments grioli_moments(const MomentsAtO& given,
                                     double max_C_over_A = std::numeric_limits<double>::infinity()) {
    require_moments(given);
    rigid::Moments m{};
    try {
        m = rigid::moments(given.A, given.B, given.C);  // the exact rule C - B <= A, on the gaps
    } catch (const std::invalid_argument& e) {
        throw BadInput(std::string("--A, --B, --C: ") + e.what());
    }
    if (!(m.C <= max_C_over_A * m.A))
        throw BadInput("--A, --C: C / A = " + std::to_string(m.C / m.A) +
                       "; this scene forms J Omega and needs C / A <= " + std::to_string(max_C_over_A) +
                       " (beyond, the round-off eps C / A of its residuals passes its thresholds)");
    return m;
}

// About how long one period of a Grioli precession takes to integrate with a GSL method at
// tolerance tol: c tol^(-1/p) seconds, c and p fitted to runs at tol = 1e-6, 1e-9, 1e-12 on one
// core (the number of steps per period does not depend on the moments or on f), then doubled.
inline double seconds_per_period(const std::string& method, double tol) {
    struct Fit {
        const char* method;
        double c, p;
    };
    static const Fit fits[] = {{"rk8pd", 1.9e-6, 8},  {"rkf45", 1.1e-6, 5}, {"rkck", 8e-7, 5},
                               {"rk4", 7.3e-7, 3.5},  {"rk2", 9.6e-7, 2.8}, {"msadams", 1.4e-5, 11},
                               {"bsimp", 4e-5, 6.3},  {"msbdf", 2e-5, 7.5}, {"rk4imp", 8e-5, 5.5},
                               {"rk2imp", 3.2e-5, 3}, {"rk1imp", 6.3e-5, 2}};
    for (const Fit& f : fits)
        if (method == f.method) return 2 * f.c * std::pow(tol, -1.0 / f.p);
    return 1e-3 * std::pow(tol, -0.5);  // an unknown method: assume the worst
}

}  // namespace kit
