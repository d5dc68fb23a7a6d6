// Chapter 8 reference solutions: the level oscillator (6.1) and the aligning spin (6.2).
// Contracts in rigid/quantized.hpp.
#include "rigid/quantized.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "rigid/require.hpp"
#include "rigid/rotation.hpp"

namespace rigid {

double oscillator_energy(const Oscillator& osc, double q, double q_dot) {
    require_oscillator(osc);
    return 0.5 * osc.m * q_dot * q_dot + 0.5 * osc.omega * osc.omega * q * q;
}

double level_friction(const LevelFriction& k, double E) {
    require_friction(k);
    return k.kappa * std::pow(std::abs(std::sin(std::numbers::pi * E / k.E0)), k.power);
}

double level_below(const LevelFriction& k, double E) {
    require_friction(k);
    require_finite(E, "the energy E");
    if (!(E >= 0)) {
        std::ostringstream s;
        s.precision(17);
        s << "the energy E must be >= 0, got " << E;
        throw std::invalid_argument(s.str());
    }
    return std::floor(E / k.E0) * k.E0;
}

OdeRhs oscillator_equations(const Oscillator& osc, const LevelFriction& k) {
    require_oscillator(osc);
    require_friction(k);
    return [osc, k](double, const VecX& y) {
        const double q = y(0), v = y(1);
        const double E = 0.5 * osc.m * v * v + 0.5 * osc.omega * osc.omega * q * q;
        const double friction = k.kappa * std::pow(std::abs(std::sin(std::numbers::pi * E / k.E0)), k.power);
        return VecX{{v, -(osc.omega * osc.omega * q + friction * v) / osc.m}};
    };
}

double energy_rate(const Oscillator& osc, const LevelFriction& k, double q, double q_dot) {
    return -level_friction(k, oscillator_energy(osc, q, q_dot)) * q_dot * q_dot;
}

Vec3 spin_rhs(const SpinField& field, const Vec3& S) {
    require_spin_field(field);
    const Vec3& B = field.B;
    const Vec3 precession = -field.e_over_mc * B.cross(S);
    // Sizes by stableNorm and directions from them: |S|^2 of a spin below 1e-154 would underflow
    // to 0 (and above 1e154 overflow), and (6.2) is homogeneous, of degree 1 in S and in B.
    const double size = S.stableNorm();
    if (size == 0) return precession;  // zero as well
    const double field_size = B.stableNorm();
    const Vec3 s = S / size, b = B / field_size;
    // beta (B.S) s x (b x s) = beta |B| |S| (s.b) (b - s (s.b)): the part of b across s.
    const double c = s.dot(b);
    return precession + (field.beta * field_size * size * c) * (b - c * s);
}

OdeRhs spin_equations(const SpinField& field) {
    require_spin_field(field);
    return [field](double, const VecX& y) {
        const Vec3 dS = spin_rhs(field, Vec3(y(0), y(1), y(2)));
        return VecX{{dS(0), dS(1), dS(2)}};
    };
}

double spin_projection_rate(const SpinField& field, const Vec3& S) {
    require_spin_field(field);
    const double size = S.stableNorm();  // not |S|^2, which underflows below 1e-154
    if (size == 0) return 0;
    const double B = field.B.stableNorm();
    const Vec3 s = S / size, b = field.B / B;
    return field.beta * B * size * s.dot(b) * s.cross(b).squaredNorm();
}

double spin_angle(const Vec3& B, const Vec3& S) {
    // From the unit vectors: |S x B| of two vectors below ~1e-77 each would underflow to 0.
    const Vec3 b = require_axis(B, "the field B"), s = require_axis(S, "the spin S");
    return std::atan2(s.cross(b).norm(), s.dot(b));
}

// |S| is constant and d(S . B^)/dt = beta |B| (S . B^) sin^2 theta; with S . B^ = |S| cos theta,
// -|S| sin(theta) theta' = beta |B| |S| cos(theta) sin^2(theta), so theta' = -beta |B| sin(theta)
// cos(theta) = -(beta |B| / 2) sin 2 theta. The precession term turns S about B: no change of theta.
// sin and cos from the unit vectors (a cross and a dot product), accurate at every angle.
double spin_angle_rate(const SpinField& field, const Vec3& S) {
    require_spin_field(field);
    const double B = field.B.stableNorm();  // not norm(), whose square underflows below 1e-154
    const Vec3 s = require_axis(S, "the spin S"), b = field.B / B;
    return -field.beta * B * s.cross(b).norm() * s.dot(b);
}

Vec3 spin_exact(const SpinField& field, const Vec3& S0, double t) {
    const Vec3 b = require_axis(field.B, "the field B");
    require_spin_field(field);
    require_finite(t, "the time t");
    if (!S0.allFinite())
        throw std::invalid_argument("the initial spin S0 must be a finite vector, got " + describe(S0));
    const double size = S0.stableNorm();  // not norm(), whose square underflows below 1e-154
    if (size == 0) return S0;
    const double B = field.B.stableNorm();
    const Vec3 u = S0 / size, par = u.dot(b) * b, perp = u - par;
    // In the frame turning with the precession, S moves in the plane of B and S0 only, with
    // tan(theta) = tan(theta0) exp(-x). Scaled so that exp never overflows.
    const double x = field.beta * B * t;
    Vec3 d = x >= 0 ? Vec3(par + std::exp(-x) * perp) : Vec3(std::exp(x) * par + perp);
    if (u.dot(b) == 0) d = perp;                   // exactly 90 degrees: an equilibrium of the angle
    if (perp.cwiseAbs().maxCoeff() == 0) d = par;  // exactly 0 or 180 degrees: one as well
    return rotation_about(b, -field.e_over_mc * B * t) * (size * (d / d.stableNorm()));
}

}  // namespace rigid
