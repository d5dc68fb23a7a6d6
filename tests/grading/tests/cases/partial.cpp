// case: partial credit: acos loses tiny angles, passes the symmetry test
// replace: geodesic_angle
// expect: geodesic_angle: equals the rotation angle | fail | tolerance
// expect: geodesic_angle: is symmetric | pass
// score: geodesic_angle 0.5
namespace rigid {
double geodesic_angle(const Mat3& R1, const Mat3& R2) {
    const Mat3 M = R1.transpose() * R2;
    return std::acos(0.5 * (M.trace() - 1));
}
}  // namespace rigid
