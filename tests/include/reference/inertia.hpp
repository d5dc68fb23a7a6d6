// Independent computations of the moments at a shifted suspension point, shared by the
// Chapter 6 graders (tests/inertia_test.cpp) and the Chapter 6 scenes: the tensor written out
// from [P, (5.2)] (not through the exercises), Eigen's eigen-solver with the moments named as in
// [P, (5.3)], and the binary128 evaluation of quad_inertia.hpp. Not an exercise and not a
// solution: the yardstick both sides measure the exercises against.
#pragma once

#include <cmath>

#include "reference/quad_inertia.hpp"
#include "rigid/inertia.hpp"

namespace inertia_reference {

using rigid::BodyAtG;
using rigid::Mat3;
using rigid::Vec3;

// The body's size: the largest radius of gyration at G, sqrt(C_g / mu).
inline double size_of(const BodyAtG& b) { return std::sqrt(b.C_g / b.mu); }

// The tensor at O = G + L z from (5.2), written out here: I_G + h (1 - z z^T), h = mu L^2.
inline Mat3 tensor_at(const BodyAtG& b, double L, const Vec3& z) {
    const double h = b.mu * L * L;
    return Vec3(b.A_g, b.B_g, b.C_g).asDiagonal().toDenseMatrix() + h * (Mat3::Identity() - z * z.transpose());
}

// The moments by Eigen's SelfAdjointEigenSolver, named as in [P, (5.3)]: B is the eigenvalue
// whose axis is x_B, A <= C the other two; with their axes.
struct EigenMoments {
    double A, B, C;
    Vec3 vA, vB, vC;
};
inline EigenMoments eigen_moments(const Mat3& I) {
    Eigen::SelfAdjointEigenSolver<Mat3> es(I);
    Eigen::Index iB;
    es.eigenvectors().row(1).cwiseAbs().maxCoeff(&iB);
    int others[2], n = 0;
    for (int i = 0; i < 3; ++i)
        if (i != iB) others[n++] = i;
    const int iA = others[0], iC = others[1];  // eigenvalues come sorted
    return {es.eigenvalues()(iA),      es.eigenvalues()(iB),      es.eigenvalues()(iC),
            es.eigenvectors().col(iA), es.eigenvectors().col(iB), es.eigenvectors().col(iC)};
}

// Where B = C on the line z below the critical angle, found by the eigen-solver alone: a bisection
// on g(h) = C - B (positive at h = 0, negative far out) to 1e-15 relative; h = mu L^2 lies in
// [lo, hi], and h() is the midpoint.
struct Crossing {
    double lo, hi;
    double h() const { return 0.5 * (lo + hi); }
};
inline Crossing crossing_by_bisection(const BodyAtG& b, const Vec3& z) {
    auto g = [&](double h) {
        const EigenMoments e = eigen_moments(tensor_at(b, std::sqrt(h / b.mu), z));
        return e.C - e.B;
    };
    double lo = 0, hi = b.C_g;
    while (g(hi) > 0) hi *= 2;
    for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) (g(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
    return {lo, hi};
}

// The binary128 reference for a double z = (zA, 0, zC).
inline quadref::Moments quad_moments(const BodyAtG& b, double L, const Vec3& z) {
    return quadref::moments(b.A_g, b.B_g, b.C_g, b.mu, L, z.x(), z.z());
}

}  // namespace inertia_reference
