// Chapter 5: Lemma 2 and Theorem 1, the two Grioli precessions, [P, Introduction, Sect. 5,
// (4.1)-(4.15), (int.1)-(int.4)].
//
// Conventions for this file
//   * The inertia frame: the principal axes at the fixed point O, ordered A < B < C, as a
//     right-handed frame (R_A, R_B, R_C). Vectors "in the inertia frame" have components
//     (A, B, C). As in [P, Sect. 5], the lab frame is this frame at t = 0: R(0) = 1.
//   * The body of Theorem 1: J = diag(A, B, C) and z(0) = a of [P, (4.10)], the centre of mass
//     on the rotation axis, at the angle phi to R_A with cos phi = sqrt((B - A)/(C - A))
//     [P, (int.2)]. k is the upward vertical, b the precession vector, f = g L mu > 0.
//   * Theorem 1: R(t) = R^b(sigma alpha t) R^a(sigma alpha t), sigma = +1 (counter-clockwise)
//     or -1 (clockwise), with the same a, b, k, z(0) for both senses.
//   * Every difference of moments is formed from the gaps B - A and C - B, which Moments
//     carries as numbers of their own, so that a nearly symmetric body keeps its digits:
//     C - A = (B - A) + (C - B) and A + C - B = A + (C - B) have no cancellation.
//   * Bad input throws std::invalid_argument naming the value and the rule it breaks.
//
// How it is graded (tests/grading/README.md): each test calls your functions in a sandboxed
// process of their own, which keeps its state between the calls of one test; the grader runs in
// another. Threads are allowed (up to 16 besides the main one); starting a process or another
// program is not.
#pragma once

#include "rigid/heavy_top.hpp"
#include "rigid/ode.hpp"
#include "rigid/types.hpp"

namespace rigid {

// snippet: grioli_moments
// The principal moments at O, A < B < C [P, (int.1)], with the gaps B - A and C - B.
struct Moments {
    double A, B, C;
    double B_minus_A, C_minus_B;
};

// From A, B, C. Rules, checked in this order: all finite; A, B, C > 0; A < B; B < C;
// A + B >= C (the triangle inequality; equality is a flat body). The gaps are B - A and
// C - B, formed once.
Moments moments(double A, double B, double C);

// From A and the two gaps, which are kept exactly as given (B and C are rounded sums).
// Rules: all finite; A > 0; B - A > 0; C - B > 0; C - B <= A (that is A + B >= C).
Moments moments_from_gaps(double A, double B_minus_A, double C_minus_B);
// end snippet

// snippet: grioli_closed_form
// The root that all of Theorem 1's numbers share [P, (int.3), (int.4), (4.5), (4.11)]:
//   S = sqrt((C - B)(B - A) + (A + C - B)^2)
double grioli_root(const Moments& m);

// The frequency of both the rotation and the precession, alpha = sqrt(f / S)
// [P, (int.4), (4.5)]. f finite and > 0.
double grioli_alpha(const Moments& m, double f);

// The angle theta between the vertical k and the precession vector b (the intermediate axis
// at t = 0): cos theta = (A + C - B) / S [P, (int.3), (4.6)]. Computed with atan2, so that a
// nearly symmetric body's small theta keeps its digits.
double grioli_theta(const Moments& m);

// The rotation vector, in the inertia frame [P, (4.10)]:
//   a = ( sqrt((B - A)/(C - A)), 0, -sqrt((C - B)/(C - A)) )
Vec3 grioli_rotation_vector(const Moments& m);

// The vertical, in the inertia frame [P, (4.11)]:
//   k = ( (C - B) sqrt((B - A)/(C - A)), A + C - B, (B - A) sqrt((C - B)/(C - A)) ) / S
Vec3 grioli_vertical(const Moments& m);
// end snippet

// snippet: grioli_precession
enum class Sense { ccw, cw };  // sigma = +1, -1

// One of the two regular precessions of Theorem 1, in the inertia frame at t = 0.
struct GrioliPrecession {
    Sense sense;
    double f, alpha, theta;
    Vec3 a, b, k, z0;  // a (4.10), b = R_B(0) = (0, 1, 0), k (4.11), z0 = a
};

// Builds it from the moments, f > 0 and the sense.
GrioliPrecession grioli_precession(const Moments& m, double f, Sense sense);

// R(t) = R^b(sigma alpha t) R^a(sigma alpha t)                            [P, Theorem 1]
Mat3 grioli_rotation(const GrioliPrecession& g, double t);

// Omega(t) = sigma alpha (a + R^a(sigma alpha t)^T b)                      [P, (1.5)]
Vec3 grioli_angular_velocity(const GrioliPrecession& g, double t);

// The heavy top it belongs to: J = diag(A, B, C), f, k, z(0).
HeavyTop grioli_top(const Moments& m, const GrioliPrecession& g);

// The Euler-Poisson state at t = 0: (Omega(0), R(0) = 1).
BodyState grioli_initial_state(const GrioliPrecession& g);
// end snippet

// snippet: grioli_gap_form
// The Euler-Poisson equations (3.1)-(3.2) of a body with J = diag(A, B, C) (its inertia frame),
// with Euler's equations written on the moment gaps                           [P, (3.1), (3.2)]
//   A Omega_dot_A = (B - C) Omega_B Omega_C + f [R^T k, z(0)]_A
//   B Omega_dot_B = (C - A) Omega_C Omega_A + f [R^T k, z(0)]_B
//   C Omega_dot_C = (A - B) Omega_A Omega_B + f [R^T k, z(0)]_C,      R_dot = R hat(Omega),
// where B - C = -(C - B), C - A = (B - A) + (C - B) and A - B = -(B - A) come from the gaps of m,
// never from subtracting A, B, C. The same equations as euler_poisson_rhs with J = diag(A, B, C),
// but they keep their digits when two moments agree to more digits than a double holds (far out
// on a Grioli line C - B is 1e-9 of B, or less). f > 0, k and z0 unit vectors: not checked,
// this runs millions of times.
BodyState euler_poisson_rhs_gaps(const Moments& m, double f, const Vec3& k, const Vec3& z0, const BodyState& s);
// end snippet

// snippet: grioli_item_II
// The body placed in a lab frame whose upward vertical is `up` (any finite non-zero vector),
// by the recipe of Item II [P, Introduction], with its quadrant rule replaced by one that
// works (see the chapter):
//   1. start with the intermediate axis R_B along k (the shortest turn taking e_B to k);
//   2. tilt by theta about the horizontal lab axis h = [k, `toward`] / |...|, so that
//      b := R_B has the angle theta with k; `toward` is any vector not along k (it fixes the
//      plane of the tilt, "the plane of the paper sheet");
//   3. a := [b, k] / |[b, k]|; turn about b until the centre of mass points along +a;
//   4. the rule: the smallest axis must lie inside the right angle between z(0) and the
//      projection of k on the (R_A, R_C) plane; if not, turn by pi about b (steps 1-3 always
//      give a placement that obeys it; the check is there for placements made otherwise).
struct LabPlacement {
    Sense sense;
    double alpha, theta;
    Mat3 R0;           // body -> lab at t = 0: its columns are R_A, R_B, R_C in the lab
    Vec3 Omega0;       // angular velocity at t = 0, body frame
    Vec3 k, b, a, z0;  // lab vectors at t = 0 (z0 = R0 z(0))
};

// In the lab, the body then moves as R(t) = R^b(sigma alpha t) R^a(sigma alpha t) R0.
LabPlacement place_item_II(const Moments& m, double f, Sense sense, const Vec3& up = Vec3::UnitZ(),
                           const Vec3& toward = Vec3::UnitX());

// The corrected rule of step 4, for the four placements R0 (body -> lab) of the Theorem 1 body
// that steps 1-3 leave open: its intermediate axis on the line of b and its centre-of-mass axis
// on the line of a (so k is perpendicular to it). True when R_A lies inside the right angle
// between the centre-of-mass axis z(0) and the projection of k on the plane of R_A and R_C.
bool item_II_rule_holds(const Moments& m, const Mat3& R0, const Vec3& k);
// end snippet

// snippet: grioli_integrate
// Theorem 1 checked by integration: the Euler-Poisson equations (3.1)-(3.2) of grioli_top in
// their gap form (euler_poisson_rhs_gaps), started from grioli_initial_state and integrated
// with integrate_gsl over `periods` periods 2 pi / alpha, compared with grioli_rotation (and
// grioli_angular_velocity) at the times linspace(0, periods 2 pi / alpha, n), n = ceil(periods
// samples_per_period): `samples_per_period` points per period, both ends included.
struct PrecessionCheck {
    double max_rotation_error;  // max geodesic_angle(R_integrated, R_exact), radians
    double max_omega_error;     // max |Omega - Omega_exact| / alpha
    double max_energy_drift;    // max |H - H(0)| / f
    double orthogonality;       // orthogonality_defect of the final R
    OdeStats stats;
};

// periods > 0, samples_per_period >= 1. Implicit methods get euler_poisson_jacobian of grioli_top.
PrecessionCheck integrate_grioli(const Moments& m, const GrioliPrecession& g, double periods, int samples_per_period,
                                 const OdeSettings& settings);
// end snippet

// A derivation exercise (Chapter 5, "Exercises"): the total energy of the Theorem 1 precession,
// H = (Omega, J Omega) / 2 + f (k, R z(0)) with J = diag(A, B, C) (the energy heavy_top_energy
// computes; the potential is zero when G is level with O), as a closed form in the moments and
// f alone. Derive it by hand first: the function must not build the precession or integrate
// anything. The same for both senses. Every digit must survive a nearly symmetric or flat
// body, as for grioli_root. f finite and > 0 (std::invalid_argument otherwise).
double grioli_energy(const Moments& m, double f);

}  // namespace rigid
