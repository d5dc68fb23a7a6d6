// Chapter 3 reference solutions: the free body. Contracts in rigid/free_body.hpp.
#include "rigid/free_body.hpp"

#include "rigid/require.hpp"
#include "rigid/rotation.hpp"

namespace rigid {

Vec3 euler_rhs(const Vec3& I, const Vec3& Omega) {
    const Vec3 m = I.cwiseProduct(Omega);  // body angular momentum I Omega
    return m.cross(Omega).cwiseQuotient(I);
}

Mat3 poisson_rhs(const Mat3& R, const Vec3& Omega) { return R * hat(Omega); }

OdeRhs free_body_equations(const Vec3& I) {
    require_principal_moments(I);
    return [I](double, const VecX& y) {
        const BodyState s = unpack(y);
        return pack({euler_rhs(I, s.Omega), poisson_rhs(s.R, s.Omega)});
    };
}

double rotational_energy(const Vec3& I, const Vec3& Omega) { return 0.5 * Omega.dot(I.cwiseProduct(Omega)); }

double angular_momentum_squared(const Vec3& I, const Vec3& Omega) { return I.cwiseProduct(Omega).squaredNorm(); }

}  // namespace rigid
