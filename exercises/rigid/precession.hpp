// Chapter 2: regular precession as kinematics, [P, Sect. 2, (1.4)-(1.7)].
//
// Conventions for this file
//   * A regular precession is R(t) = R^b(beta t) R^a(alpha t) [P, (1.4)]: first the pure
//     rotation about a (the rotation vector), then the pure rotation about b (the precession
//     vector), both with the rotation_about of Chapter 1.
//   * a and b may have any finite non-zero length; they are normalised. [P] takes positive
//     frequencies only (a clockwise turn is written with -a), so alpha and beta must be finite
//     and > 0. [P] also asks a and b not to be collinear; the functions here do not need it
//     (collinear a, b give a pure rotation, and a circle of radius 0).
//   * Bad input throws std::invalid_argument naming the value and the rule.
//
// How it is graded (tests/grading/README.md): each test calls your functions in a sandboxed
// process of their own, which keeps its state between the calls of one test; the grader runs in
// another. Threads are allowed (up to 16 besides the main one); starting a process or another
// program is not.
#pragma once

#include <vector>

#include "rigid/types.hpp"

namespace rigid {

// snippet: regular_precession
// The four constants of a regular precession                                        [P, (1.4)]
// (Chapter 4 calls the same struct TrialPrecession.)
struct RegularPrecession {
    Vec3 a;        // rotation vector (normalised by every function)
    double alpha;  // rotation frequency, > 0
    Vec3 b;        // precession vector, fixed in space (normalised by every function)
    double beta;   // precession frequency, > 0
};

// R(t) = R^b(beta t) R^a(alpha t)                                                    [P, (1.4)]
Mat3 precession_rotation(const RegularPrecession& p, double t);
// end snippet

// snippet: precession_omega
// The body angular velocity of (1.4), Omega = vee(R^T dR/dt)                         [P, (1.5)]
//   Omega(t) = Omega^a + R^a(alpha t)^T Omega^b = alpha a + beta R^a(alpha t)^T b
Vec3 precession_body_angular_velocity(const RegularPrecession& p, double t);

// The lab angular velocity omega = R Omega = beta b + alpha R^b(beta t) a: it turns about b.
Vec3 precession_lab_angular_velocity(const RegularPrecession& p, double t);
// end snippet

// snippet: precession_constants
// |Omega(t)|^2, constant in time. [P, (1.6)] prints (alpha + beta)^2; direct evaluation of
// (1.5) gives alpha^2 + beta^2 + 2 alpha beta (a, b), which is what this returns (the two
// agree only for (a, b) = 1, collinear a and b: see the chapter's checking.md). [P, (1.6)]
double precession_omega_squared(const RegularPrecession& p);

// (a, Omega(t)) = alpha + beta (a, b), constant in time                              [P, (1.7)]
double precession_axial_component(const RegularPrecession& p);
// end snippet

// A circle in space: its centre, the unit normal of its plane, and its radius.
struct Circle {
    Vec3 centre;
    Vec3 normal;
    double radius;
};

// snippet: precession_circle
// The circle that Omega(t) traces [P, after (1.7)]: in the plane (a, Omega) = alpha + beta (a, b)
// orthogonal to a, centred on the a axis, radius beta |a x b|. Normal: a (normalised).
// Omega(t) runs round it once per 2 pi / alpha, clockwise seen from the tip of a.
Circle precession_omega_circle(const RegularPrecession& p);
// end snippet

// snippet: fit_circle
// The best-fit plane and circle through a set of points, and how far the points are from them.
//   plane:  through the centroid, normal = the direction of least scatter (the right singular
//           vector of the smallest singular value of the centred points): total least squares;
//   circle: in that plane, the algebraic (Kasa) least-squares circle through the projected
//           points: minimises sum (|q - c|^2 - r^2)^2 over the centre c and radius r.
//   plane_residual  = max over the points of their distance from the plane;
//   circle_residual = max over the points of | distance of the projected point from c - r |.
// The fitted normal has either sign. Points on one circle give both residuals ~ 0 (round-off). Throws
// std::invalid_argument for fewer than 3 points, a non-finite point, or points that do not span a plane (all equal, or
// on one line: the second singular value at most 1e-12 times the largest).
struct CircleFit {
    Circle circle;
    double plane_residual;
    double circle_residual;
};
CircleFit fit_circle(const std::vector<Vec3>& points);
// end snippet

// snippet: precession_lab_circle
// A derivation exercise (Chapter 2): the circle that the lab angular velocity omega(t) of
// the precession traces (centre, unit normal pointing along b, radius). Throws
// std::invalid_argument as precession_rotation does.
Circle precession_lab_circle(const RegularPrecession& p);
// end snippet

}  // namespace rigid
