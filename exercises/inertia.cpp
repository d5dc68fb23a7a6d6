// Chapter 6 exercises: the Grioli lines. Contracts, conventions and equation numbers are in
// rigid/inertia.hpp; hints in exercises/hints.md. Replace each todo(...) with your code.
#include "rigid/inertia.hpp"

#include "rigid/require.hpp"
#include "rigid/todo.hpp"

namespace rigid {

// TODO: [P, (5.2)] the direct sum over the point masses, about `origin`.
Mat3 inertia_tensor(const std::vector<PointMass>& points, const Vec3& origin) { todo("inertia_tensor"); }

// TODO: six masses mu/6 on the axes, at the distances the second moments S_i give.
std::vector<PointMass> six_point_body(const BodyAtG& body) { todo("six_point_body"); }

// TODO: [P, (5.2)] Huygens-Steiner: I_G + mu (|r|^2 1 - r r^T).
Mat3 shifted_inertia(const Mat3& I_G, double mu, const Vec3& r) { todo("shifted_inertia"); }

// TODO: [P, (5.3), (5.4)] exactly as printed.
ShiftedMoments printed_moments(const BodyAtG& body, double L, const Vec3& z) { todo("printed_moments"); }

// TODO: [P, (5.3), (5.4)] without losing digits.
ShiftedMoments shifted_moments(const BodyAtG& body, double L, const Vec3& z) { todo("shifted_moments"); }

// TODO: [P, (5.6)] the squared cosine of the critical angle.
double critical_cos2(const BodyAtG& body) { todo("critical_cos2"); }

// TODO: [P, (5.7)] the left side of the hyperbola.
double hyperbola_lhs(const BodyAtG& body, double x_A, double x_C) { todo("hyperbola_lhs"); }

// TODO: [P, (5.8)] where the line along z meets the hyperbola (+infinity if never).
double critical_h(const BodyAtG& body, const Vec3& z) { todo("critical_h"); }

// TODO: the region I..VI of Figure 5 (0 on a boundary).
int region(const BodyAtG& body, double x_A, double x_C) { todo("region"); }

// TODO: [P, (5.12)] cos^2 and sin^2 of the angle between R_A and z, without cancellation.
Cos2Sin2 smallest_axis_tilt(const BodyAtG& body, double L, const Vec3& z) { todo("smallest_axis_tilt"); }

// TODO: [P, (5.13)] (B - A)/(C - A) and (C - B)/(C - A) from the differences.
Cos2Sin2 grioli_ratio(const ShiftedMoments& m) { todo("grioli_ratio"); }

// TODO: [P, (5.2), (5.9), (5.10)] the tensor at O, its moments and right-handed principal frame.
PrincipalFrame principal_frame(const BodyAtG& body, double L, const Vec3& z) { todo("principal_frame"); }

// TODO: [P, (5.14), (5.15)] the unit vector along a Grioli line.
Vec3 grioli_direction(const BodyAtG& body, int sign) { todo("grioli_direction"); }

// TODO: everything at a suspension point on a Grioli line, from the exact line.
GrioliSuspension grioli_suspension(const BodyAtG& body, double L, int sign) { todo("grioli_suspension"); }

// TODO: the normals of the circular sections of x^T I x = 1 (Grioli's description).
std::array<Vec3, 2> circular_section_normals(const Mat3& I) { todo("circular_section_normals"); }

// TODO: (derivation) write (z, I' z) with (5.2) and the z of (5.14); it will not depend on L.
double grioli_line_axial_moment(const BodyAtG& body) { todo("grioli_line_axial_moment"); }

}  // namespace rigid
