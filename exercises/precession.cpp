// Chapter 2 exercises: regular precession. Contracts, conventions and equation numbers are in
// rigid/precession.hpp; hints in exercises/hints.md. Replace each todo(...) with your code.
#include "rigid/precession.hpp"

#include "rigid/require.hpp"
#include "rigid/rotation.hpp"
#include "rigid/todo.hpp"

namespace rigid {

// TODO: [P, (1.4)] R^b(beta t) R^a(alpha t) (check a, b, alpha, beta and t first).
Mat3 precession_rotation(const RegularPrecession& p, double t) { todo("precession_rotation"); }

// TODO: [P, (1.5)] alpha a + beta R^a(alpha t)^T b.
Vec3 precession_body_angular_velocity(const RegularPrecession& p, double t) {
    todo("precession_body_angular_velocity");
}

// TODO: omega = R Omega, written as beta b + alpha R^b(beta t) a.
Vec3 precession_lab_angular_velocity(const RegularPrecession& p, double t) { todo("precession_lab_angular_velocity"); }

// TODO: [P, (1.6)] the constant |Omega|^2, from (1.5) (not the printed value: see the chapter).
double precession_omega_squared(const RegularPrecession& p) { todo("precession_omega_squared"); }

// TODO: [P, (1.7)] the constant (a, Omega).
double precession_axial_component(const RegularPrecession& p) { todo("precession_axial_component"); }

// TODO: the circle of Omega(t): centre on the a axis, normal a, radius beta |a x b|.
Circle precession_omega_circle(const RegularPrecession& p) { todo("precession_omega_circle"); }

// TODO: best-fit plane (smallest scatter direction) and Kasa circle, with both residuals.
CircleFit fit_circle(const std::vector<Vec3>& points) { todo("fit_circle"); }

// TODO (derivation): find the centre, normal and radius of the circle of omega(t) by hand first.
Circle precession_lab_circle(const RegularPrecession& p) { todo("precession_lab_circle"); }

}  // namespace rigid
