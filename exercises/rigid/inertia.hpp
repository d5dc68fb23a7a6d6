// Chapter 6: the Grioli lines, [P, Sect. 6, (5.1)-(5.15)].
//
// Conventions for this file
//   * The G-frame: origin at the centre of mass G, axes along the principal axes of inertia at
//     G, in the order x_A, x_B, x_C with A_g < B_g < C_g, so that I_G = diag(A_g, B_g, C_g).
//     Every vector and tensor below is written in the G-frame unless a comment says otherwise.
//   * The suspension point O sits at L z from G, z a unit vector [P, (5.1.1)]. Note the sign:
//     this z points from G to O, while [P]'s z(0) of (3.1) points from O to G. Only z z^T
//     enters the tensor, so the moments and axes at O do not care.
//   * h = mu L^2 is the shift-induced inertia [P, (5.2)].
//   * The moments at O keep the names of [P, (5.3)]: B = B_g + h is the moment about x_B (that
//     axis never moves), A <= C are the two roots in the (x_A, x_C) plane. A < B always; C < B
//     happens (regions V and VI of Figure 5), and the struct says so through C_minus_B < 0.
//   * The planar functions take z in the principal plane: finite, |z| = 1 and z_B = 0, each to
//     within 1e-12; L must be finite and > 0. Bad input throws std::invalid_argument naming
//     the rule broken, as do the checks of require_body below.
//   * [P] writes alpha in (5.10) for an auxiliary number of this section; it is NOT the
//     frequency alpha of Theorem 1. This file calls it alpha_510 where it needs it.
//
// How it is graded (tests/grading/README.md): each test calls your functions in a sandboxed
// process of their own, which keeps its state between the calls of one test; the grader runs in
// another. Threads are allowed (up to 16 besides the main one); starting a process or another
// program is not.
#pragma once

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "rigid/require.hpp"
#include "rigid/types.hpp"

namespace rigid {

// snippet: body_at_g
// A rigid body given at its centre of mass: principal moments A_g < B_g < C_g and mass mu.
struct BodyAtG {
    double A_g, B_g, C_g;
    double mu;
};

// The rules a body must obey (provided, not an exercise; every function below calls it):
// finite numbers, A_g > 0, strictly ordered A_g < B_g < C_g (an asymmetric body, [P, (int.1.1)]),
// the triangle inequality A_g + B_g > C_g (a real body: its second moments are positive),
// and mu > 0. Throws std::invalid_argument naming the rule.
inline void require_body(const BodyAtG& b) {
    require_positive(b.A_g, "A_g");
    require_positive(b.B_g, "B_g");
    require_positive(b.C_g, "C_g");
    require_positive(b.mu, "the mass mu");
    auto fail = [&b](const std::string& rule) {
        std::ostringstream s;
        s.precision(17);
        s << "the moments at G must " << rule << " (got A_g = " << b.A_g << ", B_g = " << b.B_g << ", C_g = " << b.C_g
          << ")";
        throw std::invalid_argument(s.str());
    };
    if (!(b.A_g < b.B_g && b.B_g < b.C_g)) fail("be strictly ordered, A_g < B_g < C_g");
    if (!(b.A_g + b.B_g > b.C_g)) fail("obey the triangle inequality A_g + B_g > C_g");
}
// end snippet

// snippet: point_masses
// A point mass m at x.
struct PointMass {
    double m;
    Vec3 x;
};

// The inertia tensor about `origin` of point masses, by the direct sum               [P, (5.2)]
//   I'_ij = sum_N m_N [ (x'_N)^2 delta_ij - x'^i_N x'^j_N ],   x'_N = x_N - origin
// Throws std::invalid_argument for no points, a mass that is not finite and > 0, or a
// non-finite position or origin.
Mat3 inertia_tensor(const std::vector<PointMass>& points, const Vec3& origin);

// A body with exactly these moments at G: six masses mu/6 at +-s_A e_A, +-s_B e_B, +-s_C e_C,
// where 2 (mu/6) s_i^2 = S_i, the second moments
//   S_A = (B_g + C_g - A_g)/2,  S_B = (C_g + A_g - B_g)/2,  S_C = (A_g + B_g - C_g)/2.
// S_C > 0 is the triangle inequality. Points in the order +s_A e_A, -s_A e_A, +s_B e_B, ...
std::vector<PointMass> six_point_body(const BodyAtG& body);
// end snippet

// snippet: shifted_inertia
// The inertia tensor at O = G + r from the one at G (Huygens-Steiner)                [P, (5.2)]
//   I' = I_G + mu (|r|^2 1 - r r^T)  =  I_G + h (1 - z z^T),   r = L z,  h = mu L^2
// For any r, in the principal plane or not. Throws std::invalid_argument when I_G is not
// finite and symmetric (to 1e-12 of its largest entry), mu is not finite and > 0, or r is
// not finite.
Mat3 shifted_inertia(const Mat3& I_G, double mu, const Vec3& r);
// end snippet

// The unit vector z = (cos phi_g, 0, sin phi_g): angle phi_g from x_A towards x_C [P, (5.1.1)].
// Provided. Throws std::invalid_argument for a non-finite phi_g.
inline Vec3 shift_direction(double phi_g) {
    require_finite(phi_g, "the angle phi_g");
    return Vec3(std::cos(phi_g), 0.0, std::sin(phi_g));
}

// snippet: shifted_moments
// The principal moments at O = G + L z, z in the principal plane, with their differences.
struct ShiftedMoments {
    double A, B, C;    // [P, (5.3)]: A <= C the roots in the (x_A, x_C) plane, B = B_g + h
    double C_minus_A;  // sqrt(D) >= 0, D the discriminant of [P, (5.4)]
    double C_minus_B;  // > 0 in regions I-IV and on the Grioli lines, 0 on the hyperbola, < 0 in V-VI
    double B_minus_A;  // > 0 always: the smallest moment stays the smallest
};

// (5.3) exactly as printed, with D from the last form of (5.4):
//   D = h^2 + 2 (C_g - A_g)(z_A^2 - z_C^2) h + (C_g - A_g)^2,
//   C, A = (A_g + C_g + h +- sqrt(D))/2,  B = B_g + h,
// and the three differences by subtracting those. Loses digits: see shifted_moments.
ShiftedMoments printed_moments(const BodyAtG& body, double L, const Vec3& z);

// The same moments, written so that every field keeps its digits for L from 1e-6 to 1e6
// body sizes and for nearly symmetric bodies (relative error a few eps, C_minus_B and
// B_minus_A within a few eps of their condition number):
//   sqrt(D) = |(h + (C_g - A_g) cos 2phi_g,  (C_g - A_g) sin 2phi_g)|   (a sum of squares),
//   C = (A_g + C_g + h + sqrt(D))/2,   A = (A_g C_g + h Delta_+)/C      (A C = det, no cancellation),
//   (C - B)(B - A) = (B_g - A_g)(C_g - B_g) + h [(C_g - B_g) z_A^2 - (B_g - A_g) z_C^2],
//   (C - B) + (B - A) = sqrt(D): form the one of the two without cancellation, divide for the other.
ShiftedMoments shifted_moments(const BodyAtG& body, double L, const Vec3& z);
// end snippet

// snippet: critical
// The squared cosine of the critical angle, z_A^2 = (B_g - A_g)/(C_g - A_g)          [P, (5.6)]
double critical_cos2(const BodyAtG& body);

// The left side of the hyperbola (5.7), in the coordinates (x_A, x_C) of the point O = G + x:
//   -x_A^2 / ((B_g - A_g)/mu) + x_C^2 / ((C_g - B_g)/mu)                            [P, (5.7)]
// It is 1 where B = C, 0 on the asymptotes (5.15). Throws for non-finite x_A, x_C.
double hyperbola_lhs(const BodyAtG& body, double x_A, double x_C);

// The shift h = mu L^2 at which the line through G along z meets the hyperbola, B = C [P, (5.8)]
//   h_crit = (B_g - A_g)(C_g - B_g) / [(B_g - A_g) z_C^2 - (C_g - B_g) z_A^2],
// written so that the denominator does not cancel; +infinity when the line never meets the
// hyperbola (z_A^2 >= the critical value (5.6)).
double critical_h(const BodyAtG& body, const Vec3& z);

// The region of Figure 5 that holds the point O = G + (x_A, 0, x_C), as 1..6 for I..VI:
//   1 (I)   x_A > 0 beyond the asymptotes (z_A^2 > critical)     A < B < C
//   2 (II)  x_A < 0 beyond the asymptotes                        A < B < C
//   3 (III) x_C > 0, between the asymptotes, short of the hyperbola   A < B < C
//   4 (IV)  x_C < 0, between the asymptotes, short of the hyperbola   A < B < C
//   5 (V)   x_C > 0, past the hyperbola                          A < C < B
//   6 (VI)  x_C < 0, past the hyperbola                          A < C < B
// and 0 on a boundary: G itself, an asymptote, or the hyperbola. Throws for non-finite input.
int region(const BodyAtG& body, double x_A, double x_C);
// end snippet

// snippet: tilt
// A squared cosine and sine that add up to 1, each with its own digits.
struct Cos2Sin2 {
    double cos2, sin2;
};

// The angle phi between the smallest axis R_A at O and the centre-of-mass line z  [P, (5.12)]
//   cos^2 phi = 1/2 + (h + (C_g - A_g) cos 2phi_g) / (2 sqrt(D)),
// with sin^2 phi from the same, each formed without cancellation (one of the two is
// (C_g - A_g)^2 sin^2 2phi_g / (2 sqrt(D) (sqrt(D) +- ...))). At the one point where A = C
// (phi_g = pi/2, h = C_g - A_g) R_A is taken as x_A, as principal_frame does.
Cos2Sin2 smallest_axis_tilt(const BodyAtG& body, double L, const Vec3& z);

// The right side of Theorem 1's condition [P, (int.2)], from the moments          [P, (5.13)]
//   cos2 = (B - A)/(C - A),   sin2 = (C - B)/(C - A)   (sin2 < 0 where C < B).
// Uses the differences in m, never A, B, C themselves.
Cos2Sin2 grioli_ratio(const ShiftedMoments& m);
// end snippet

// snippet: principal_frame
// The inertia tensor at O and its principal frame.
struct PrincipalFrame {
    Mat3 I;                  // the tensor at O, (5.2), in the G-frame
    ShiftedMoments moments;  // as shifted_moments
    Mat3 R;                  // columns R_A, R_B, R_C: the axes of A, B, C in the G-frame;
                             // R_B = e_B, R_C = R_A x R_B (right-handed), R_A . e_A >= 0
};

// The frame at O = G + L z, z in the principal plane. R_A is x_A turned towards x_C by
//   theta_A = 1/2 atan2(2 h z_A z_C, alpha_510),  alpha_510 = (C_g - A_g) + h (z_A^2 - z_C^2),
// [P, (5.9)-(5.10)] in angle form; R^T I R = diag(A, B, C).
PrincipalFrame principal_frame(const BodyAtG& body, double L, const Vec3& z);
// end snippet

// snippet: grioli
// The unit vector from G along a Grioli line                                 [P, (5.14), (5.15)]
//   z = ( sqrt((B_g - A_g)/(C_g - A_g)),  0,  sign sqrt((C_g - B_g)/(C_g - A_g)) ),
// on the line x_C = sign sqrt((C_g - B_g)/(B_g - A_g)) x_A; sign is +1 or -1. The other half of
// each line, -z, has the same moments and axes. Throws std::invalid_argument for another sign.
Vec3 grioli_direction(const BodyAtG& body, int sign);

// Everything about a suspension point O = G + L z on a Grioli line, for Theorem 1.
struct GrioliSuspension {
    Vec3 z;                // grioli_direction(body, sign): unit, from G towards O
    Vec3 O;                // L z: the suspension point, from G
    PrincipalFrame frame;  // at O; A < B < C holds on the whole line
    Vec3 z0;               // the unit vector from O to G in the frame (R_A, R_B, R_C): R^T (-z),
                           // Theorem 1's z(0) when the body frame is the principal frame at O
    Cos2Sin2 tilt;         // cos^2 and sin^2 of the angle between R_A and the line, (5.12)
    Cos2Sin2 expected;     // (B - A)/(C - A) and (C - B)/(C - A), (5.13)
};

// The moments, axes and ratios are those of the exact line, cos^2 phi_g = (B_g - A_g)/(C_g - A_g)
// (no rounding of z enters them), so tilt == expected to a few eps at every L. frame.I is
// (5.2) with the rounded z; its eigenvalues agree with the moments to a few eps |I|.
GrioliSuspension grioli_suspension(const BodyAtG& body, double L, int sign);

// The unit normals of the two circular sections, through the centre, of the ellipsoid
// x^T I x = 1 (I symmetric positive definite with three distinct eigenvalues): Grioli's
// description of his lines. With u_A, u_C the eigenvectors of the smallest and largest
// eigenvalues (each with its largest component positive),
//   n_+- = sqrt((B - A)/(C - A)) u_A +- sqrt((C - B)/(C - A)) u_C.
// Throws std::invalid_argument when I is not finite and symmetric, or its eigenvalues are not
// positive and distinct.
std::array<Vec3, 2> circular_section_normals(const Mat3& I);
// end snippet

// A derivation exercise (Chapter 6, "Exercises"): the moment of inertia (z, I' z) at a point
// O = G + L z of a Grioli line (grioli_direction, either sign) about the line OG itself. Show
// on paper that it does not depend on L or on the sign, and find it in closed form from A_g,
// B_g, C_g; the function must not build a tensor. Bad bodies throw as require_body says.
double grioli_line_axial_moment(const BodyAtG& body);

}  // namespace rigid
