// Chapter 8: classical systems with "quantized" behaviour, [P, Sect. 7, (6.1), (6.2)].
//
// Conventions for this file
//   * The oscillator (6.1): m q'' + omega^2 q = -k(E) q', E = m q'^2 / 2 + omega^2 q^2 / 2. [P]
//     puts omega^2 (not m omega^2) next to m q'', so the natural frequency is omega / sqrt(m);
//     the two agree only for m = 1. Its state for rigid/ode.hpp and rigid/integrators.hpp is
//     y = (q, q').
//   * The friction is the workbook's choice (Sect. 7 of [P] leaves k(E) open): k(E) =
//     kappa |sin(pi E / E0)|^p, zero exactly on the levels E_n = n E0, n = 0, 1, 2, ..., and
//     positive between them, so the energy never rises. p = 2 is smooth (a double zero at each
//     level); p = 1 has a kink there.
//   * The spin (6.2): dS/dt = -(e/mc) [B, S] + beta (B, S) [S^, [B^, S^]] with [a, b] = a x b and
//     the hats unit vectors. Its state is y = S (3 numbers). (6.2) is homogeneous, of degree 1
//     in S and in B, and the spin functions below keep that for sizes from 1e-300 to 1e300: a
//     size taken as sqrt(|S|^2) is 0 below 1e-154 and infinite above 1e154 (Eigen's stableNorm
//     is not; unit vectors then keep the rest in range).
//   * Bad input throws std::invalid_argument naming the rule (the require_* functions below):
//     m, omega, kappa, E0 finite and > 0; p finite and >= 1; B finite and non-zero; e/mc
//     finite, of either sign (the sign of the charge); beta finite and >= 0.
//
// How it is graded (tests/grading/README.md): each test calls your functions in a sandboxed
// process of their own, which keeps its state between the calls of one test; the grader runs in
// another. Threads are allowed (up to 16 besides the main one); starting a process or another
// program is not.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rigid/ode.hpp"
#include "rigid/require.hpp"
#include "rigid/types.hpp"

namespace rigid {

// ------------------------------------------------------------------- the oscillator (6.1)

// snippet: oscillator_types
// The oscillator of [P, (6.1)]: the mass m and the constant omega of the restoring force
// omega^2 q (its natural frequency is omega / sqrt(m)).
struct Oscillator {
    double m = 1;
    double omega = 1;
};

// The energy-dependent friction coefficient k(E) = kappa |sin(pi E / E0)|^power.
struct LevelFriction {
    double kappa = 1;  // its largest value, reached half-way between two levels
    double E0 = 1;     // the spacing of the levels E_n = n E0
    double power = 2;  // the order of its zero at each level: 2 smooth, 1 a kink
};
// end snippet

// The rules (provided, not exercises; every oscillator function calls them).
inline void require_oscillator(const Oscillator& o) {
    require_positive(o.m, "the mass m");
    require_positive(o.omega, "omega");
}
inline void require_friction(const LevelFriction& k) {
    require_positive(k.kappa, "the friction kappa");
    require_positive(k.E0, "the level spacing E0");
    require_finite(k.power, "the friction power p");
    if (!(k.power >= 1)) {
        std::ostringstream s;
        s.precision(17);
        s << "the friction power p must be >= 1 (k(E) Lipschitz, so solutions are unique), got " << k.power;
        throw std::invalid_argument(s.str());
    }
}

// snippet: oscillator_energy
// The energy of (6.1), E = m q'^2 / 2 + omega^2 q^2 / 2.                           [P, (6.1)]
double oscillator_energy(const Oscillator& osc, double q, double q_dot);

// The friction coefficient k(E) = kappa |sin(pi E / E0)|^power: >= 0, and 0 exactly at E = n E0.
// Any E is accepted (a NaN gives NaN): it is called inside the right-hand side.
double level_friction(const LevelFriction& k, double E);

// The level that a motion started with energy E >= 0 settles onto: the largest n E0 <= E.
// Throws std::invalid_argument for a negative or non-finite E.
double level_below(const LevelFriction& k, double E);
// end snippet

// snippet: oscillator_equations
// (6.1) as a first-order system for y = (q, q'):                                   [P, (6.1)]
//   q' = q',   q'' = -(omega^2 q + k(E) q') / m,   E = oscillator_energy(osc, q, q').
// Checks osc and k once, when it is made.
OdeRhs oscillator_equations(const Oscillator& osc, const LevelFriction& k);

// The energy balance of (6.1): dE/dt = q' (m q'' + omega^2 q) = -k(E) q'^2 <= 0.
double energy_rate(const Oscillator& osc, const LevelFriction& k, double q, double q_dot);
// end snippet

// ------------------------------------------------------------------------- the spin (6.2)

// snippet: spin_types
// The field and couplings of (6.2): the magnetic field B, e/mc and beta.
struct SpinField {
    Vec3 B = Vec3::UnitZ();
    double e_over_mc = 1;
    double beta = 0;  // 0: the plain precession dS/dt = -(e/mc) [B, S]
};
// end snippet

// The rules (provided, not an exercise; every spin function calls it).
inline void require_spin_field(const SpinField& f) {
    require_axis(f.B, "the field B");
    require_finite(f.e_over_mc, "e/mc");
    require_finite(f.beta, "beta");
    if (!(f.beta >= 0)) {
        std::ostringstream s;
        s.precision(17);
        s << "beta must be >= 0 (beta = 0 is the plain precession), got " << f.beta;
        throw std::invalid_argument(s.str());
    }
}

// snippet: spin_rhs
// The right-hand side of (6.2),                                                    [P, (6.2)]
//   dS/dt = -(e/mc) B x S + beta (B . S) S^ x (B^ x S^),   S^ = S / |S|,  B^ = B / |B|.
// At S = 0 it returns 0 (the limit: the second term is O(|S|)).
Vec3 spin_rhs(const SpinField& field, const Vec3& S);

// (6.2) as a right-hand side for rigid/ode.hpp and rigid/integrators.hpp, y = S. Checks the
// field once, when it is made.
OdeRhs spin_equations(const SpinField& field);
// end snippet

// snippet: spin_projection_rate
// The balance of the component of S along B under (6.2): the precession does not change it,
// the second term does,
//   d(S . B^)/dt = beta |B| (S . B^) sin^2(theta),   theta = the angle between S and B,
// with the sign of S . B^: an acute angle closes, an obtuse one opens, 90 degrees stays.
// (|S| itself is constant: the second term of (6.2) is perpendicular to S.) 0 at S = 0.
double spin_projection_rate(const SpinField& field, const Vec3& S);
// end snippet

// snippet: spin_angle
// The angle between S and B, in [0, pi], by atan2(|S x B|, S . B): accurate near 0 and pi,
// where acos of the cosine loses half the digits. Throws std::invalid_argument for a zero or
// non-finite B or S.
double spin_angle(const Vec3& B, const Vec3& S);
// end snippet

// snippet: spin_exact
// The exact solution of (6.2) with S(0) = S0, for every beta >= 0:
//   S(t) = |S0| R^{B^}(-(e/mc) |B| t) normalize(S_par + exp(-beta |B| t) S_perp),
// S_par = (S0 . B^) B^ and S_perp = S0 - S_par: the first term turns S about B (rotation_about,
// Chapter 1), the second moves it in the plane of B and S with tan(theta) = tan(theta0)
// exp(-beta |B| t). For beta = 0 it is the precession R^{B^}(-(e/mc)|B| t) S0. S0 = 0 stays 0;
// S0 at exactly 90 degrees to B stays at 90 degrees. Throws std::invalid_argument for a bad
// field, a non-finite S0 or t.
Vec3 spin_exact(const SpinField& field, const Vec3& S0, double t);
// end snippet

// A derivation exercise (Chapter 8, "Exercises"): the rate d theta/dt at which the angle theta
// between S and B (spin_angle) changes under (6.2), at the state S. Derive it in closed form on
// paper, from (6.2) or from the balance of spin_projection_rate; the function must not
// integrate or difference anything. Accurate near theta = 0 and pi (no acos). Throws
// std::invalid_argument for a bad field and for a zero or non-finite S (theta is undefined).
double spin_angle_rate(const SpinField& field, const Vec3& S);

}  // namespace rigid
