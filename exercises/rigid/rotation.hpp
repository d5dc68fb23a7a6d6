// Chapter 1: pure rotations, [P, Sect. 2, (1.1)-(1.3)].
//
// Conventions for this file
//   * R maps body coordinates to lab coordinates: x_lab = R x_body. The columns of R are the
//     body axes R_i(t) written in the lab frame [P, Notation].
//   * Rotations are active and right-handed: rotation_about(a, phi) turns a point
//     counter-clockwise about a by phi when seen from the tip of a [P, (1.1)]. It equals
//     Eigen::AngleAxisd(phi, a), and the tests pin that.
//   * hat(w) is the skew matrix with hat(w) x = w x x ([a, b]_i = eps_ijk a_j b_k in [P]);
//     vee is its inverse, the map [P, (1.1.1)] uses: Omega_k = -1/2 eps_kij W_ij.
//   * Functions that take an axis accept any finite non-zero vector and normalise it; a zero
//     or non-finite axis, or a non-finite angle, throws std::invalid_argument naming it.
//
// How it is graded (tests/grading/README.md): each test calls your functions in a sandboxed
// process of their own, which keeps its state between the calls of one test; the grader runs in
// another. Threads are allowed (up to 16 besides the main one); starting a process or another
// program is not.
#pragma once

#include "rigid/types.hpp"

namespace rigid {

// snippet: hat_vee
// The skew matrix of w: hat(w) x = w x x, for every x.
//   hat(w) = [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]]
Mat3 hat(const Vec3& w);

// The vector of the skew part of W, Omega_k = -1/2 eps_kij W_ij                   [P, (1.1.1)]
// vee(hat(w)) == w; for a general W only (W - W^T)/2 counts.
Vec3 vee(const Mat3& W);
// end snippet

// snippet: rotation_about
// The pure rotation about the axis a by the angle phi                              [P, (1.1)]
//   R^a_ij(phi) = delta_ij cos(phi) + (1 - cos(phi)) a_i a_j - eps_ijk a_k sin(phi)
// a is normalised first. Throws std::invalid_argument for a zero or non-finite a, or a
// non-finite phi.
Mat3 rotation_about(const Vec3& a, double phi);
// end snippet

// snippet: angular_velocity
// Angular velocity in the body frame from R and dR/dt                            [P, (1.1.1)]
//   Omega_k = -1/2 eps_kij (R^T Rdot)_ij,   i.e.  Omega = vee(R^T Rdot)
Vec3 body_angular_velocity(const Mat3& R, const Mat3& R_dot);

// Angular velocity in the lab frame, omega_k = -1/2 eps_kij (Rdot R^T)_ij.
// For an exact rotation and its exact derivative, omega = R Omega             [P, Sect. 2]
Vec3 lab_angular_velocity(const Mat3& R, const Mat3& R_dot);
// end snippet

// snippet: is_rotation
// How far R is from orthogonal: the Frobenius norm of R^T R - 1 (0 for a rotation).
double orthogonality_defect(const Mat3& R);

// True when R is a rotation to within tol: every entry finite, orthogonality_defect(R) <= tol
// and det R > 0 (a reflection has defect 0 and det -1). Throws std::invalid_argument for a
// negative or non-finite tol.
bool is_rotation(const Mat3& R, double tol = 1e-12);
// end snippet

// An axis (unit vector) and an angle in [0, pi]; together they name a rotation.
struct AxisAngle {
    Vec3 axis;
    double angle;
};

// snippet: axis_angle
// The inverse of rotation_about: the unit axis a and the angle phi in [0, pi] with
// rotation_about(a, phi) == R. For phi == 0 the axis is arbitrary and returned as e3; for
// phi == pi, a and -a name the same rotation and either may be returned. Accurate for every
// angle (it must not lose the axis near pi). Throws std::invalid_argument when R is not a
// rotation to within 1e-9 (is_rotation(R, 1e-9) is false).
AxisAngle axis_angle(const Mat3& R);
// end snippet

// snippet: compose
// The composition "first, then second" in axis-angle form, without building a matrix:
//   rotation_about(c.axis, c.angle) == rotation_about(second...) * rotation_about(first...)
// by Rodrigues' composition rule for half angles. Angle in [0, pi]; for the identity the
// axis is e3. Throws std::invalid_argument as rotation_about does.
AxisAngle compose(const AxisAngle& first, const AxisAngle& second);
// end snippet

// snippet: geodesic_angle
// The angle of the rotation R1^T R2: how far apart two orientations are, in [0, pi].
// Computed with atan2, so that angles far below 1e-8 keep their digits (acos of the trace
// cannot: cos(1e-9) == 1 in double precision). Non-finite input gives NaN.
double geodesic_angle(const Mat3& R1, const Mat3& R2);
// end snippet

// snippet: rotation_between
// A derivation exercise (Chapter 1): the rotation by the smallest angle that takes the
// direction of u to the direction of v (u and v need not be unit vectors). Its axis is
// orthogonal to both; for v along u it is the identity; for v along -u every axis
// orthogonal to u gives a half turn, and any of them may be returned. Throws
// std::invalid_argument for a zero or non-finite u or v.
Mat3 rotation_between(const Vec3& u, const Vec3& v);
// end snippet

}  // namespace rigid
