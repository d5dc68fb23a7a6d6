// Chapter 5 exercises: Lemma 2 and Theorem 1. Contracts, conventions and equation numbers are
// in rigid/grioli.hpp; hints in exercises/hints.md. Replace each todo(...) with your code.
#include "rigid/grioli.hpp"

#include "rigid/require.hpp"
#include "rigid/rotation.hpp"
#include "rigid/todo.hpp"

namespace rigid {

// TODO: check the rules in the documented order; the gaps are B - A and C - B.
Moments moments(double A, double B, double C) { todo("moments"); }

// TODO: keep the gaps as given; B = A + (B - A), C = B + (C - B).
Moments moments_from_gaps(double A, double B_minus_A, double C_minus_B) { todo("moments_from_gaps"); }

// TODO: [P, (4.5)] S = sqrt((C - B)(B - A) + (A + C - B)^2), from the gaps.
double grioli_root(const Moments& m) { todo("grioli_root"); }

// TODO: [P, (int.4)] alpha^2 = f / S.
double grioli_alpha(const Moments& m, double f) { todo("grioli_alpha"); }

// TODO: [P, (int.3), (4.6)] the angle with cos theta = (A + C - B) / S, by atan2.
double grioli_theta(const Moments& m) { todo("grioli_theta"); }

// TODO: [P, (4.10)] a = (sqrt((B - A)/(C - A)), 0, -sqrt((C - B)/(C - A))).
Vec3 grioli_rotation_vector(const Moments& m) { todo("grioli_rotation_vector"); }

// TODO: [P, (4.11)] the vertical k in the inertia frame.
Vec3 grioli_vertical(const Moments& m) { todo("grioli_vertical"); }

// TODO: alpha, theta, a, b = e_B, k, z0 = a, for the given sense.
GrioliPrecession grioli_precession(const Moments& m, double f, Sense sense) { todo("grioli_precession"); }

// TODO: [P, Theorem 1] R^b(sigma alpha t) R^a(sigma alpha t).
Mat3 grioli_rotation(const GrioliPrecession& g, double t) { todo("grioli_rotation"); }

// TODO: [P, (1.5)] sigma alpha (a + R^a(sigma alpha t)^T b).
Vec3 grioli_angular_velocity(const GrioliPrecession& g, double t) { todo("grioli_angular_velocity"); }

// TODO: heavy_top(diag(A, B, C), f, k, z0).
HeavyTop grioli_top(const Moments& m, const GrioliPrecession& g) { todo("grioli_top"); }

// TODO: (Omega(0), R(0) = 1).
BodyState grioli_initial_state(const GrioliPrecession& g) { todo("grioli_initial_state"); }

// TODO: [P, (3.1), (3.2)] Euler's equations on the gaps: A Omega_dot_A = (B - C) Omega_B Omega_C + f [R^T k, z0]_A, ...
BodyState euler_poisson_rhs_gaps(const Moments& m, double f, const Vec3& k, const Vec3& z0, const BodyState& s) {
    todo("euler_poisson_rhs_gaps");
}

// TODO: (derivation) derive H on paper first; chapter 5's worked example shows where to start.
double grioli_energy(const Moments& m, double f) { todo("grioli_energy"); }

// TODO: [P, Item II] R_B along k, tilt by theta, turn about b until z(0) = +a, check the rule.
LabPlacement place_item_II(const Moments& m, double f, Sense sense, const Vec3& up, const Vec3& toward) {
    todo("place_item_II");
}

// TODO: R_A inside the right angle between z(0) and the projection of k.
bool item_II_rule_holds(const Moments& m, const Mat3& R0, const Vec3& k) { todo("item_II_rule_holds"); }

// TODO: integrate (3.1)-(3.2) in the gap form with integrate_gsl and compare with grioli_rotation.
PrecessionCheck integrate_grioli(const Moments& m, const GrioliPrecession& g, double periods, int samples_per_period,
                                 const OdeSettings& settings) {
    todo("integrate_grioli");
}

}  // namespace rigid
