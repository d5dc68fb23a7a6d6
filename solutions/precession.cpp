// Chapter 2 reference solutions: regular precession. Contracts in rigid/precession.hpp.
#include "rigid/precession.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rigid/require.hpp"
#include "rigid/rotation.hpp"

namespace rigid {

namespace {

// The constants, checked and with unit axes.
RegularPrecession checked(const RegularPrecession& p) {
    RegularPrecession q = p;
    q.a = require_axis(p.a, "rotation vector a");
    q.b = require_axis(p.b, "precession vector b");
    require_positive(p.alpha, "rotation frequency alpha");
    require_positive(p.beta, "precession frequency beta");
    return q;
}

}  // namespace

Mat3 precession_rotation(const RegularPrecession& p, double t) {
    const RegularPrecession q = checked(p);
    require_finite(t, "time t");
    return rotation_about(q.b, q.beta * t) * rotation_about(q.a, q.alpha * t);
}

Vec3 precession_body_angular_velocity(const RegularPrecession& p, double t) {
    const RegularPrecession q = checked(p);
    require_finite(t, "time t");
    return q.alpha * q.a + q.beta * rotation_about(q.a, q.alpha * t).transpose() * q.b;
}

Vec3 precession_lab_angular_velocity(const RegularPrecession& p, double t) {
    const RegularPrecession q = checked(p);
    require_finite(t, "time t");
    return q.beta * q.b + q.alpha * rotation_about(q.b, q.beta * t) * q.a;
}

double precession_omega_squared(const RegularPrecession& p) {
    const RegularPrecession q = checked(p);
    return q.alpha * q.alpha + q.beta * q.beta + 2 * q.alpha * q.beta * q.a.dot(q.b);
}

double precession_axial_component(const RegularPrecession& p) {
    const RegularPrecession q = checked(p);
    return q.alpha + q.beta * q.a.dot(q.b);
}

Circle precession_omega_circle(const RegularPrecession& p) {
    const RegularPrecession q = checked(p);
    // |a x b| rather than sqrt(1 - (a, b)^2): no cancellation for nearly collinear a, b.
    return {precession_axial_component(q) * q.a, q.a, q.beta * q.a.cross(q.b).norm()};
}

CircleFit fit_circle(const std::vector<Vec3>& points) {
    if (points.size() < 3)
        throw std::invalid_argument("fit_circle needs at least 3 points, got " + std::to_string(points.size()));
    Vec3 centroid = Vec3::Zero();
    for (const Vec3& x : points) {
        if (!x.allFinite()) throw std::invalid_argument("fit_circle: every point must be finite, got " + describe(x));
        centroid += x;
    }
    centroid /= double(points.size());
    Eigen::MatrixXd D(points.size(), 3);
    for (std::size_t i = 0; i < points.size(); ++i) D.row(Eigen::Index(i)) = (points[i] - centroid).transpose();
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(D, Eigen::ComputeFullV);  // singular values descending
    const Vec3 sv = svd.singularValues();
    if (!(sv(0) > 0)) throw std::invalid_argument("fit_circle: all points coincide");
    if (!(sv(1) > 1e-12 * sv(0))) throw std::invalid_argument("fit_circle: the points lie on one line");
    const Vec3 u = svd.matrixV().col(0), v = svd.matrixV().col(1), n = svd.matrixV().col(2);

    // Kasa: 2 c.q + k = |q|^2 in plane coordinates q = (x, y), k = r^2 - |c|^2.
    Eigen::MatrixXd A(points.size(), 3);
    Eigen::VectorXd rhs(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3 d = points[i] - centroid;
        const double x = d.dot(u), y = d.dot(v);
        A.row(Eigen::Index(i)) << 2 * x, 2 * y, 1.0;
        rhs(Eigen::Index(i)) = x * x + y * y;
    }
    const Eigen::Vector3d sol = A.colPivHouseholderQr().solve(rhs);
    const double cx = sol(0), cy = sol(1);
    const double radius = std::sqrt(std::max(0.0, sol(2) + cx * cx + cy * cy));
    const Vec3 centre = centroid + cx * u + cy * v;

    double plane_res = 0, circle_res = 0;
    for (const Vec3& x : points) {
        const Vec3 d = x - centre;
        const double h = d.dot(n);
        plane_res = std::max(plane_res, std::abs(h));
        circle_res = std::max(circle_res, std::abs((d - h * n).norm() - radius));
    }
    return {{centre, n, radius}, plane_res, circle_res};
}

Circle precession_lab_circle(const RegularPrecession& p) {
    precession_rotation(p, 0.0);  // the bad-input rules of (1.4)
    const Vec3 a = p.a.stableNormalized(), b = p.b.stableNormalized();
    // omega(t) = beta b + alpha R^b(beta t) a: the part of a along b stays, the rest turns.
    return Circle{(p.beta + p.alpha * a.dot(b)) * b, b, p.alpha * a.cross(b).norm()};
}

}  // namespace rigid
