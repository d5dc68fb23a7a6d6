// An honest solution of exercises/rotation.cpp, written by hand from the contracts in
// rigid/rotation.hpp only (not from solutions/ or the hints), for the similarity report's
// measure: it must earn full marks and match neither the reference nor the other honest ones.
// Style: index notation, as [P] writes it (the Levi-Civita symbol), and Shepperd's method.
#include <cmath>
#include <stdexcept>

#include "rigid/require.hpp"
#include "rigid/rotation.hpp"

namespace rigid {

namespace {

// eps_ijk for indices 0..2.
int levi_civita(int i, int j, int k) {
    if (i == j || j == k || k == i) return 0;
    return ((j - i + 3) % 3 == 1) ? 1 : -1;
}

// A unit quaternion (w, x) with w >= 0 read off a rotation matrix: the largest of the four
// squares is taken from the diagonal, the others from off-diagonal sums (Shepperd, 1978).
void quaternion_from(const Mat3& R, double& w, Vec3& x) {
    const double t = R(0, 0) + R(1, 1) + R(2, 2);
    int m = 0;
    for (int i = 1; i < 3; ++i)
        if (R(i, i) > R(m, m)) m = i;
    if (t >= R(m, m)) {
        const double r = std::sqrt(1 + t);
        w = r / 2;
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3, k = (i + 2) % 3;
            x(i) = (R(k, j) - R(j, k)) / (2 * r);
        }
    } else {
        const int j = (m + 1) % 3, k = (m + 2) % 3;
        const double r = std::sqrt(1 + R(m, m) - R(j, j) - R(k, k));
        x(m) = r / 2;
        x(j) = (R(j, m) + R(m, j)) / (2 * r);
        x(k) = (R(k, m) + R(m, k)) / (2 * r);
        w = (R(k, j) - R(j, k)) / (2 * r);
    }
    if (w < 0) {
        w = -w;
        x = -x;
    }
}

}  // namespace

Mat3 hat(const Vec3& w) {
    Mat3 out = Mat3::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) out(i, j) -= levi_civita(i, j, k) * w(k);
    return out;
}

Vec3 vee(const Mat3& W) {
    Vec3 omega = Vec3::Zero();
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) omega(k) -= 0.5 * levi_civita(k, i, j) * W(i, j);
    return omega;
}

Mat3 rotation_about(const Vec3& a, double phi) {
    const Vec3 n = require_axis(a, "rotation_about: the axis a");
    require_finite(phi, "rotation_about: the angle phi");
    const double cp = std::cos(phi), sp = std::sin(phi);
    Mat3 R;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double entry = (i == j ? cp : 0.0) + (1 - cp) * n(i) * n(j);
            for (int k = 0; k < 3; ++k) entry -= levi_civita(i, j, k) * n(k) * sp;
            R(i, j) = entry;
        }
    return R;
}

Vec3 body_angular_velocity(const Mat3& R, const Mat3& R_dot) {
    const Mat3 W = R.transpose() * R_dot;
    return vee(W);
}

Vec3 lab_angular_velocity(const Mat3& R, const Mat3& R_dot) {
    const Mat3 W = R_dot * R.transpose();
    return vee(W);
}

double orthogonality_defect(const Mat3& R) {
    const Mat3 G = R.transpose() * R;
    double sum = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double d = G(i, j) - (i == j ? 1.0 : 0.0);
            sum += d * d;
        }
    return std::sqrt(sum);
}

bool is_rotation(const Mat3& R, double tol) {
    if (!std::isfinite(tol) || tol < 0) throw std::invalid_argument("is_rotation: tol must be finite and >= 0");
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (!std::isfinite(R(i, j))) return false;
    return R.determinant() > 0 && orthogonality_defect(R) <= tol;
}

AxisAngle axis_angle(const Mat3& R) {
    if (!is_rotation(R, 1e-9)) throw std::invalid_argument("axis_angle: R is not a rotation to within 1e-9");
    double w = 0;
    Vec3 x;
    quaternion_from(R, w, x);
    const double s = x.norm();
    if (s == 0) return {Vec3(0, 0, 1), 0.0};
    return {x / s, 2 * std::atan2(s, w)};
}

AxisAngle compose(const AxisAngle& first, const AxisAngle& second) {
    const Vec3 u1 = require_axis(first.axis, "compose: the first axis");
    const Vec3 u2 = require_axis(second.axis, "compose: the second axis");
    require_finite(first.angle, "compose: the first angle");
    require_finite(second.angle, "compose: the second angle");
    // Quaternions q_i = (cos(phi_i/2), sin(phi_i/2) u_i); the product q2 q1 is "first, then second".
    const double w1 = std::cos(first.angle / 2), w2 = std::cos(second.angle / 2);
    const Vec3 x1 = std::sin(first.angle / 2) * u1, x2 = std::sin(second.angle / 2) * u2;
    double w = w2 * w1 - x2.dot(x1);
    Vec3 x = w2 * x1 + w1 * x2 + x2.cross(x1);
    if (w < 0) {
        w = -w;
        x = -x;
    }
    const double s = x.norm();
    if (s == 0) return {Vec3(0, 0, 1), 0.0};
    return {x / s, 2 * std::atan2(s, w)};
}

double geodesic_angle(const Mat3& R1, const Mat3& R2) {
    const Mat3 D = R1.transpose() * R2;
    double s2 = 0;
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        s2 += (D(j, i) - D(i, j)) * (D(j, i) - D(i, j));
    }
    return std::atan2(std::sqrt(s2) / 2, (D(0, 0) + D(1, 1) + D(2, 2) - 1) / 2);
}

// The plane of u and v turns into itself: about their cross product (by the Levi-Civita
// symbol), by the angle between them.
Mat3 rotation_between(const Vec3& u, const Vec3& v) {
    const Vec3 p = require_axis(u, "u"), q = require_axis(v, "v");
    Vec3 n = Vec3::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) n(i) += levi_civita(i, j, k) * p(j) * q(k);
    const double dot = p(0) * q(0) + p(1) * q(1) + p(2) * q(2);
    if (n.norm() == 0) {
        if (dot > 0) return Mat3::Identity();
        // Half turn about a direction across p: p with one zero and two swapped components.
        int big = 0;
        for (int i = 1; i < 3; ++i)
            if (std::abs(p(i)) > std::abs(p(big))) big = i;
        const int next = (big + 1) % 3;
        Vec3 across = Vec3::Zero();
        across(big) = -p(next);
        across(next) = p(big);
        return rotation_about(across, std::atan2(0.0, -1.0));
    }
    return rotation_about(n, std::atan2(n.norm(), dot));
}

}  // namespace rigid
