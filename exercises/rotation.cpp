// Chapter 1 exercises: pure rotations. Contracts, conventions and equation numbers are in
// rigid/rotation.hpp; hints in exercises/hints.md. Replace each todo(...) with your code.
#include "rigid/rotation.hpp"

#include "rigid/require.hpp"
#include "rigid/todo.hpp"

namespace rigid {

// TODO: the skew matrix with hat(w) x == w.cross(x).
Mat3 hat(const Vec3& w) { todo("hat"); }

// TODO: [P, (1.1.1)] Omega_k = -1/2 eps_kij W_ij.
Vec3 vee(const Mat3& W) { todo("vee"); }

// TODO: [P, (1.1)] the pure rotation about a by phi (normalise a; reject bad input).
Mat3 rotation_about(const Vec3& a, double phi) { todo("rotation_about"); }

// TODO: [P, (1.1.1)] Omega from R and dR/dt.
Vec3 body_angular_velocity(const Mat3& R, const Mat3& R_dot) { todo("body_angular_velocity"); }

// TODO: omega from R and dR/dt (omega = R Omega).
Vec3 lab_angular_velocity(const Mat3& R, const Mat3& R_dot) { todo("lab_angular_velocity"); }

// TODO: the Frobenius norm of R^T R - 1.
double orthogonality_defect(const Mat3& R) { todo("orthogonality_defect"); }

// TODO: finite, orthogonal to within tol, det > 0.
bool is_rotation(const Mat3& R, double tol) { todo("is_rotation"); }

// TODO: the inverse of rotation_about, accurate at every angle up to pi.
AxisAngle axis_angle(const Mat3& R) { todo("axis_angle"); }

// TODO: "first, then second" in axis-angle form (Rodrigues' composition rule).
AxisAngle compose(const AxisAngle& first, const AxisAngle& second) { todo("compose"); }

// TODO: the angle of R1^T R2, computed with atan2.
double geodesic_angle(const Mat3& R1, const Mat3& R2) { todo("geodesic_angle"); }

// TODO (derivation): derive the axis and the angle from u and v, then build the matrix.
Mat3 rotation_between(const Vec3& u, const Vec3& v) { todo("rotation_between"); }

}  // namespace rigid
