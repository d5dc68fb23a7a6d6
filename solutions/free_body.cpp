// Chapter 3 reference solutions: the free body. Contracts in rigid/free_body.hpp.
#include "rigid/free_body.hpp"

#include <stdexcept>
#include <string>

#include "rigid/require.hpp"
#include "rigid/rotation.hpp"

namespace rigid {

Vec3 euler_rhs(const Vec3& I, const Vec3& Omega) {
    // (I Omega) x Omega by components, each on its moment gap: I2 - I3 of two given doubles is
    // exact when they are within a factor 2, where I2 Omega2 Omega3 - I3 Omega3 Omega2 would
    // leave round-off of eps I2 / I1 (Chapter 6 meets this far out on a Grioli line).
    const Vec3& W = Omega;
    return Vec3((I(1) - I(2)) * W(1) * W(2) / I(0), (I(2) - I(0)) * W(2) * W(0) / I(1),
                (I(0) - I(1)) * W(0) * W(1) / I(2));
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

double wobble_frequency_squared(const Vec3& I, int axis, double spin) {
    require_principal_moments(I);
    if (axis < 0 || axis > 2)
        throw std::invalid_argument("wobble_frequency_squared: axis must be 0, 1 or 2, not " + std::to_string(axis));
    require_finite(spin, "spin");
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    return spin * spin * (I(axis) - I(i)) * (I(axis) - I(j)) / (I(i) * I(j));
}

}  // namespace rigid
