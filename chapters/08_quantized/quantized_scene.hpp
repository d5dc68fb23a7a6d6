// What the Chapter 8 scenes share: one way to integrate with the student's RK4 or a GSL method,
// the oscillator's starting states, the averaged energy equation that predicts how levels are
// approached and left, and a seeded, portable source of disturbances.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "rigid/integrators.hpp"
#include "rigid/ode.hpp"
#include "rigid/quantized.hpp"
#include "scene.hpp"
#include "sweep.hpp"

namespace scene8 {

using rigid::VecX;

// The states of one integration at the output times, and its cost in right-hand side calls.
struct Run {
    std::vector<VecX> y;
    long work = 0;
};

// method: "rk4" = the student's integrate_rk4 with step h; anything else = that GSL method at tol.
inline Run integrate(const rigid::OdeRhs& f, const VecX& y0, const std::vector<double>& times,
                     const std::string& method, double h_or_tol) {
    Run run;
    run.y.reserve(times.size());
    const auto observe = [&](double, const VecX& y) { run.y.push_back(y); };
    run.work = kit::integrate_by_name(f, y0, times, observe, method, h_or_tol);
    return run;
}

// The oscillator at energy E, at a turning point: q = sqrt(2 E) / omega, q' = 0.
inline VecX at_energy(const rigid::Oscillator& osc, double E) { return VecX{{std::sqrt(2 * E) / osc.omega, 0.0}}; }

// (6.1) with the work done by friction, W' = -dE/dt = k(E) q'^2, as a third component: along
// every solution E(t) + W(t) = E(0), the balance the scenes check.
inline rigid::OdeRhs with_work(const rigid::Oscillator& osc, const rigid::LevelFriction& k) {
    const rigid::OdeRhs f = rigid::oscillator_equations(osc, k);
    return [f, osc, k](double t, const VecX& y) {
        const VecX d = f(t, y.head<2>());
        return VecX{{d(0), d(1), -rigid::energy_rate(osc, k, y(0), y(1))}};
    };
}

// snippet: averaged_energy
// The averaged energy equation. Over one period of the nearly harmonic motion the mean of q'^2
// is E / m, so when k changes little in a period, dE/dt = -k(E) q'^2 becomes
//   dE/dt = -k(E) E / m.
// Near a level E_n = n E0 > 0, with d = E - E_n and k ~ kappa (pi |d| / E0)^p, it is
//   dd/dt = -c |d|^p,   c = kappa (pi / E0)^p E_n / m,
// on both sides of the level (k >= 0, so E never rises): above it (d > 0) |d| shrinks, below it
// (d < 0) |d| grows at the same rate. A level is approached from above like
// d = ((p - 1) c t)^(-1/(p-1)) (p > 1; d = 1/(c t) for p = 2) or like exp(-c t) (p = 1), and
// left from below by the mirror law: |d| = 1/(1/|d(0)| - c t) for p = 2, |d(0)| exp(c t) for p = 1.
inline rigid::OdeRhs averaged_energy(const rigid::Oscillator& osc, const rigid::LevelFriction& k) {
    return [osc, k](double, const VecX& E) { return VecX{{-rigid::level_friction(k, E(0)) * E(0) / osc.m}}; };
}
inline double level_rate(const rigid::Oscillator& osc, const rigid::LevelFriction& k, double E_n) {
    return k.kappa * std::pow(std::numbers::pi / k.E0, k.power) * E_n / osc.m;
}
// end snippet

// The time the averaged equation takes from E_n - delta down to E_n - E0 / 2: the integral of
// m / (k(E) E) dE, by Simpson's rule in s = ln(E_n - E) (smooth there), 4000 panels.
inline double averaged_escape_time(const rigid::Oscillator& osc, const rigid::LevelFriction& k, double E_n,
                                   double delta) {
    const double s0 = std::log(delta), s1 = std::log(k.E0 / 2);
    const int n = 4000;
    const double h = (s1 - s0) / n;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
        const double d = std::exp(s0 + i * h), E = E_n - d;
        const double g = osc.m * d / (rigid::level_friction(k, E) * E);
        sum += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * g;
    }
    return sum * h / 3;
}

// A seeded stream of normal numbers that every platform reproduces: splitmix64 and Box-Muller
// (std::normal_distribution is not specified bit for bit).
class Normal {
public:
    explicit Normal(std::uint64_t seed) : state_(seed) {}
    double operator()() {
        const double u1 = uniform(), u2 = uniform();
        return std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
    }

private:
    double uniform() {  // in (0, 1]
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        z ^= z >> 31;
        return (double(z >> 11) + 1) * 0x1.0p-53;
    }
    std::uint64_t state_;
};

// The oscillator of (6.1) and its friction k(E), bound to the scenes' options --m --omega
// --kappa --E0 --power (each range checked by the kit: bad input, exit status 2, naming the option).
struct OscillatorParams {
    double m = 2.0, omega = 2.0, kappa = 0.5, E0 = 1.0, power = 2.0;
};
inline void oscillator_options(kit::Options& opts, OscillatorParams& p) {
    opts.real("m", &p.m, "the mass m in (6.1)", kit::between(1e-2, 1e2))
        .real("omega", &p.omega, "omega in (6.1): the restoring force is omega^2 q (frequency omega / sqrt(m))",
              kit::between(1e-2, 1e2))
        .real("kappa", &p.kappa, "the largest friction coefficient, k(E) = kappa |sin(pi E / E0)|^power",
              kit::between(1e-6, 1e2))
        .real("E0", &p.E0, "the spacing of the energy levels E_n = n E0", kit::between(1e-3, 1e3))
        .real("power", &p.power, "the order of the zeros of k(E) (2 smooth, 1 a kink)", kit::between(1, 8));
}
// About how long rk8pd at tolerance 1e-12 takes per radian of the oscillator's phase, for the
// scenes' work estimates (measured on one core, within a factor 3).
constexpr double seconds_per_radian = 4e-5;

inline rigid::Oscillator oscillator_from(const OscillatorParams& p) { return {p.m, p.omega}; }
inline rigid::LevelFriction friction_from(const OscillatorParams& p) { return {p.kappa, p.E0, p.power}; }

}  // namespace scene8
