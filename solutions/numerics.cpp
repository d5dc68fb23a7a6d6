// Chapter 7 reference solutions: geometric integrators. Contracts in rigid/numerics.hpp.
#include "rigid/numerics.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "rigid/rotation.hpp"

namespace rigid {

Mat3 expm1_so3(const Vec3& w) {
    const double theta = w.norm();
    if (theta == 0) return Mat3::Zero();
    const Mat3 W = hat(w);
    // sin(x)/x and (1 - cos x)/x^2 = 1/2 (sin(x/2)/(x/2))^2: no cancellation, no underflow.
    const double a = std::sin(theta) / theta;
    const double half_sinc = std::sin(theta / 2) / (theta / 2);
    return a * W + (0.5 * half_sinc * half_sinc) * (W * W);
}

Vec3 dexpinv(const Vec3& u, const Vec3& v) {
    const double x = u.norm();
    const double c = x < 1e-3 ? 1.0 / 12 + x * x / 720 : (1 - (x / 2) / std::tan(x / 2)) / (x * x);
    const Vec3 uv = u.cross(v);
    return v - 0.5 * uv + c * u.cross(uv);
}

Increment combine(const Increment& first, const Increment& second) {
    return {first.dOmega + second.dOmega, first.E + second.E + first.E * second.E};
}

Increment rkmk4_step(const HeavyTop& top, const BodyState& s, double h) {
    const auto F = [&top](const Mat3& R, const Vec3& W) { return euler_poisson_rhs(top, {W, R}).Omega; };
    const auto R_at = [&s](const Vec3& theta) { return Mat3(s.R + s.R * expm1_so3(theta)); };
    const Vec3 K1 = s.Omega, L1 = F(s.R, s.Omega);
    Vec3 theta = 0.5 * h * K1;
    const Vec3 W2 = s.Omega + 0.5 * h * L1;
    const Vec3 K2 = dexpinv(-theta, W2), L2 = F(R_at(theta), W2);
    theta = 0.5 * h * K2;
    const Vec3 W3 = s.Omega + 0.5 * h * L2;
    const Vec3 K3 = dexpinv(-theta, W3), L3 = F(R_at(theta), W3);
    theta = h * K3;
    const Vec3 W4 = s.Omega + h * L3;
    const Vec3 K4 = dexpinv(-theta, W4), L4 = F(R_at(theta), W4);
    return {h / 6 * (L1 + 2 * L2 + 2 * L3 + L4), expm1_so3(h / 6 * (K1 + 2 * K2 + 2 * K3 + K4))};
}

Increment torque_kick(const HeavyTop& top, const BodyState& s, double h) {
    // With Omega = 0 the Euler equation (3.1) leaves only the torque: J Omega_dot = f [R^T k, z(0)].
    return {h * euler_poisson_rhs(top, {Vec3::Zero(), s.R}).Omega, Mat3::Zero()};
}

Increment free_rotation(const HeavyTop& top, const BodyState& s, int axis, double h) {
    if (axis < 0 || axis > 2)
        throw std::invalid_argument("free_rotation: axis must be 0, 1 or 2, got " + std::to_string(axis));
    const Mat3 E = expm1_so3(h * s.Omega(axis) * Vec3::Unit(axis));
    // exp(-x) = exp(x)^T for a skew x, so exp(-phi hat(e_i)) - 1 = E^T.
    const Vec3 dm = E.transpose() * (top.J.diagonal().asDiagonal() * s.Omega);
    return {dm.cwiseQuotient(top.J.diagonal()), E};
}

Increment strang_step(const HeavyTop& top, const BodyState& s, double h) {
    Increment d = torque_kick(top, s, h / 2);
    // The rotations read Omega only; R is needed again by the closing kick.
    BodyState now{s.Omega + d.dOmega, s.R};
    static constexpr std::array<std::pair<int, double>, 5> rotations{
        {{0, 0.5}, {1, 0.5}, {2, 1.0}, {1, 0.5}, {0, 0.5}}};
    for (const auto& [axis, fraction] : rotations) {
        d = combine(d, free_rotation(top, now, axis, fraction * h));
        now.Omega = s.Omega + d.dOmega;
    }
    now.R = s.R + s.R * d.E;
    return combine(d, torque_kick(top, now, h / 2));
}

Increment triple_jump(const IncrementStepper& step, const BodyState& s, double h) {
    const double g1 = 1 / (2 - std::cbrt(2.0)), g2 = 1 - 2 * g1;
    Increment d = step(s, g1 * h);
    d = combine(d, step(apply(s, d), g2 * h));
    return combine(d, step(apply(s, d), g1 * h));
}

// One RK4 step multiplies y = q' + i omega q... by R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24, z = i x,
// and E by |R(i x)|^2 = (1 - x^2/2 + x^4/24)^2 + (x - x^3/6)^2 = 1 - x^6/72 + x^8/576: the terms
// in x^2 and x^4 cancel exactly. The loss x^6 (8 - x^2) / 576 is written so, not as 1 - |R|^2.
double rk4_energy_loss(double x) {
    if (!std::isfinite(x) || !(x >= 0))
        throw std::invalid_argument("x = h omega must be finite and >= 0, got " + std::to_string(x));
    const double x2 = x * x;
    return x2 * x2 * x2 * (8 - x2) / 576;
}

}  // namespace rigid
