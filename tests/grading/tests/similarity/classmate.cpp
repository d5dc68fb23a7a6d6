// A classmate's partial exercises/rotation.cpp, written by hand in a style of its own, for the
// similarity report's measure: the class has it once as it is and once renamed and reformatted
// (a copy between students), and the report must pair the two and tie neither to the reference.
#include <cmath>

#include "rigid/require.hpp"
#include "rigid/rotation.hpp"
#include "rigid/todo.hpp"

namespace rigid {

Mat3 hat(const Vec3& w) {
    // Column i of hat(w) is hat(w) e_i = w x e_i.
    Mat3 columns;
    columns.col(0) = w.cross(Vec3::UnitX());
    columns.col(1) = w.cross(Vec3::UnitY());
    columns.col(2) = w.cross(Vec3::UnitZ());
    return columns;
}

Vec3 vee(const Mat3& W) {
    const Vec3 lower(W(2, 1), W(0, 2), W(1, 0));
    const Vec3 upper(W(1, 2), W(2, 0), W(0, 1));
    return (lower - upper) / 2;
}

Mat3 rotation_about(const Vec3& a, double phi) {
    const Vec3 k = require_axis(a, "axis of rotation_about");
    require_finite(phi, "angle of rotation_about");
    // Through the unit quaternion (q0, q) = (cos(phi/2), sin(phi/2) k).
    const double q0 = std::cos(phi / 2);
    const double q1 = std::sin(phi / 2) * k.x(), q2 = std::sin(phi / 2) * k.y(), q3 = std::sin(phi / 2) * k.z();
    Mat3 m;
    m(0, 0) = q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3;
    m(1, 1) = q0 * q0 - q1 * q1 + q2 * q2 - q3 * q3;
    m(2, 2) = q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3;
    m(0, 1) = 2 * (q1 * q2 - q0 * q3);
    m(1, 0) = 2 * (q1 * q2 + q0 * q3);
    m(0, 2) = 2 * (q1 * q3 + q0 * q2);
    m(2, 0) = 2 * (q1 * q3 - q0 * q2);
    m(1, 2) = 2 * (q2 * q3 - q0 * q1);
    m(2, 1) = 2 * (q2 * q3 + q0 * q1);
    return m;
}

Vec3 body_angular_velocity(const Mat3& R, const Mat3& R_dot) { todo("body_angular_velocity"); }

Vec3 lab_angular_velocity(const Mat3& R, const Mat3& R_dot) { todo("lab_angular_velocity"); }

double orthogonality_defect(const Mat3& R) {
    double total = 0;
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) {
            const double dot = R.col(row).dot(R.col(col)) - (row == col ? 1 : 0);
            total += dot * dot;
        }
    return std::sqrt(total);
}

bool is_rotation(const Mat3& R, double tol) { todo("is_rotation"); }

AxisAngle axis_angle(const Mat3& R) { todo("axis_angle"); }

AxisAngle compose(const AxisAngle& first, const AxisAngle& second) { todo("compose"); }

double geodesic_angle(const Mat3& R1, const Mat3& R2) { todo("geodesic_angle"); }

Mat3 rotation_between(const Vec3& u, const Vec3& v) { todo("rotation_between"); }

}  // namespace rigid
