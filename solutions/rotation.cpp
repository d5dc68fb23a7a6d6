// Chapter 1 reference solutions: pure rotations. Contracts in rigid/rotation.hpp.
#include "rigid/rotation.hpp"

#include <cmath>
#include <numbers>

#include "rigid/require.hpp"

namespace rigid {

Mat3 hat(const Vec3& w) {
    Mat3 W;
    // clang-format off
    W <<      0, -w.z(),  w.y(),
          w.z(),      0, -w.x(),
         -w.y(),  w.x(),      0;
    // clang-format on
    return W;
}

Vec3 vee(const Mat3& W) {
    // Omega_k = -1/2 eps_kij W_ij: only the antisymmetric part survives the contraction.
    return 0.5 * Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
}

Mat3 rotation_about(const Vec3& a, double phi) {
    const Vec3 u = require_axis(a, "rotation axis");
    require_finite(phi, "rotation angle");
    const double c = std::cos(phi), s = std::sin(phi);
    // -eps_ijk a_k sin(phi) is sin(phi) hat(a)_ij.
    return c * Mat3::Identity() + (1 - c) * u * u.transpose() + s * hat(u);
}

Vec3 body_angular_velocity(const Mat3& R, const Mat3& R_dot) { return vee(R.transpose() * R_dot); }

Vec3 lab_angular_velocity(const Mat3& R, const Mat3& R_dot) { return vee(R_dot * R.transpose()); }

double orthogonality_defect(const Mat3& R) { return (R.transpose() * R - Mat3::Identity()).norm(); }

bool is_rotation(const Mat3& R, double tol) {
    require_finite(tol, "tolerance");
    if (tol < 0) throw std::invalid_argument("tolerance must be >= 0");
    // Written so that NaN anywhere gives false.
    return R.allFinite() && orthogonality_defect(R) <= tol && R.determinant() > 0;
}

AxisAngle axis_angle(const Mat3& R) {
    if (!is_rotation(R, 1e-9))
        throw std::invalid_argument("axis_angle needs a rotation matrix (finite, R^T R = 1 to 1e-9, det R > 0)");
    const Vec3 v = vee(R);                   // sin(phi) a
    const double c = 0.5 * (R.trace() - 1);  // cos(phi)
    const double phi = std::atan2(v.norm(), c);
    if (v.norm() == 0 && c > 0) return {Vec3::UnitZ(), 0.0};
    if (c >= 0) return {v.normalized(), phi};
    // Past pi/2, sin(phi) shrinks while 1 - cos(phi) >= 1: read the axis from the symmetric
    // part (R + R^T)/2 - cos(phi) 1 = (1 - cos(phi)) a a^T, using its largest column.
    const Mat3 B = 0.5 * (R + R.transpose()) - c * Mat3::Identity();
    Eigen::Index j;
    B.diagonal().maxCoeff(&j);
    Vec3 a = B.col(j).normalized();
    if (a.dot(v) < 0) a = -a;
    return {a, phi};
}

AxisAngle compose(const AxisAngle& first, const AxisAngle& second) {
    const Vec3 a1 = require_axis(first.axis, "first rotation axis");
    const Vec3 a2 = require_axis(second.axis, "second rotation axis");
    require_finite(first.angle, "first rotation angle");
    require_finite(second.angle, "second rotation angle");
    // Half-angle (unit quaternion) form of R2 R1: scalar s, vector v.
    const double c1 = std::cos(first.angle / 2), s1 = std::sin(first.angle / 2);
    const double c2 = std::cos(second.angle / 2), s2 = std::sin(second.angle / 2);
    double s = c2 * c1 - s2 * s1 * a2.dot(a1);
    Vec3 v = c2 * s1 * a1 + c1 * s2 * a2 + s2 * s1 * a2.cross(a1);
    if (s < 0) {  // (s, v) and (-s, -v) are the same rotation; keep the angle in [0, pi]
        s = -s;
        v = -v;
    }
    const double n = v.norm();
    if (n == 0) return {Vec3::UnitZ(), 0.0};
    return {v / n, 2 * std::atan2(n, s)};
}

double geodesic_angle(const Mat3& R1, const Mat3& R2) {
    const Mat3 M = R1.transpose() * R2;
    return std::atan2(vee(M).norm(), 0.5 * (M.trace() - 1));
}

Mat3 rotation_between(const Vec3& u, const Vec3& v) {
    const Vec3 p = require_axis(u, "direction u"), q = require_axis(v, "direction v");
    // The plane of p and q is turned into itself: axis p x q, angle atan2(|p x q|, p . q).
    const Vec3 n = p.cross(q);
    const double s = n.norm(), c = p.dot(q);
    if (s > 1e-300) return rotation_about(n, std::atan2(s, c));
    if (c > 0) return Mat3::Identity();
    // Antiparallel: a half turn about any axis orthogonal to p; take the one farthest from p's
    // largest component, so that the cross product is well conditioned.
    Vec3 e = Vec3::Zero();
    int k = 0;
    p.cwiseAbs().minCoeff(&k);
    e(k) = 1;
    return rotation_about(p.cross(e), std::numbers::pi);
}

}  // namespace rigid
