// The exact free-body motion (rigid/free_body_exact.hpp). Provided, not an exercise.
#include "rigid/free_body_exact.hpp"

#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_ellint.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "rigid/require.hpp"

namespace rigid {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

Mat3 skew(const Vec3& w) {
    Mat3 W;
    W << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return W;
}

// The smallest rotation taking the unit vector l to the unit vector n (needs l.n > -1).
Mat3 swing(const Vec3& l, const Vec3& n) {
    const Vec3 v = l.cross(n);
    const Mat3 V = skew(v);
    return Mat3::Identity() + V + V * V / (1 + l.dot(n));
}

// Carlson's R_F through GSL, the one elliptic integral the constants need.
double carlson_rf(double x, double y, double z) { return gsl_sf_ellint_RF(x, y, z, GSL_PREC_DOUBLE); }

// 20-point Gauss-Legendre nodes and weights on [-1, 1], from GSL once.
struct GaussLegendre {
    static constexpr int n = 20;
    std::array<double, n> x, w;
    GaussLegendre() {
        std::unique_ptr<gsl_integration_glfixed_table, decltype(&gsl_integration_glfixed_table_free)> table(
            gsl_integration_glfixed_table_alloc(n), gsl_integration_glfixed_table_free);
        for (int i = 0; i < n; ++i) gsl_integration_glfixed_point(-1, 1, std::size_t(i), &x[i], &w[i], table.get());
    }
};
const GaussLegendre& gauss_legendre() {
    static const GaussLegendre gl;
    return gl;
}

}  // namespace

JacobiElliptic jacobi_elliptic(double u, double m, double m_c) {
    if (!(m >= 0) || !(m_c >= 0) || !(std::abs(m + m_c - 1) <= 4 * eps))
        throw std::invalid_argument("jacobi_elliptic needs 0 <= m <= 1 and m_c = 1 - m");
    if (!std::isfinite(u)) throw std::invalid_argument("jacobi_elliptic needs a finite argument u");
    if (m_c == 0) {
        const double c = 1 / std::cosh(u);  // cosh overflows to inf far out: sech -> 0, as it should
        return {std::tanh(u), c, c};
    }
    if (m == 0) return {std::sin(u), std::cos(u), 1.0};
    // Arithmetic-geometric mean: a_0 = 1, b_0 = sqrt(m_c), c_0 = sqrt(m); c_{n+1} = c_n^2 / (4 a_{n+1})
    // is (a_n - b_n) / 2 written without the cancellation.
    constexpr int N = 64;
    double a[N], c[N];
    double b = std::sqrt(m_c);
    a[0] = 1;
    c[0] = std::sqrt(m);
    int n = 0;
    while (c[n] > eps * a[n] && n < N - 1) {
        a[n + 1] = 0.5 * (a[n] + b);
        c[n + 1] = c[n] * c[n] / (4 * a[n + 1]);
        b = std::sqrt(a[n] * b);
        ++n;
    }
    double phi = std::ldexp(a[n] * u, n);
    for (int k = n; k > 0; --k) phi = 0.5 * (phi + std::asin(c[k] / a[k] * std::sin(phi)));
    const double sn = std::sin(phi), cn = std::cos(phi);
    return {sn, cn, std::sqrt(cn * cn + m_c * sn * sn)};
}

namespace {

using LD = long double;

LD squared(const Vec3& v, int j) { return LD(v(j)) * LD(v(j)); }

// E and M^2, summed in long double.
void set_invariants(FreeBodyMotion& mo) {
    LD two_e = 0, m2 = 0;
    for (int j = 0; j < 3; ++j) {
        const LD I = mo.I(j), Omega = mo.Omega0(j);
        two_e += I * Omega * Omega;
        m2 += I * I * Omega * Omega;
    }
    mo.energy = double(two_e / 2);
    mo.momentum_squared = double(m2);
}

// The axes p (the one Omega circulates about), q (the middle one) and s, and delta =
// M^2 - 2E I_q, the distance from the separatrix. False when the motion is a steady rotation (at
// rest, a spherical body, or about the middle axis).
bool choose_axes(FreeBodyMotion& mo, LD& delta) {
    const Vec3& I = mo.I;
    std::array<int, 3> order{0, 1, 2};
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return I(x) < I(y); });
    const int lo = order[0], mid = order[1], hi = order[2];
    if (mo.Omega0.isZero(0) || I(lo) == I(hi)) return false;

    const auto Il = [&](int j) { return LD(I(j)); };
    const auto w = [&](int j) { return squared(mo.Omega0, j); };
    // M^2 - 2 E I_mid: the distance from the separatrix, the one difference that cannot be avoided.
    delta = Il(lo) * (Il(lo) - Il(mid)) * w(lo) + Il(hi) * (Il(hi) - Il(mid)) * w(hi);
    int p, s;
    if (I(mid) == I(hi))
        p = hi, s = lo;  // prolate symmetric: circulation about the odd axis
    else if (I(mid) == I(lo))
        p = lo, s = hi;  // oblate symmetric
    else if (delta >= 0)
        p = lo, s = hi;  // about the largest axis (and the separatrix)
    else
        p = hi, s = lo;  // about the smallest axis
    mo.p = p, mo.q = mid, mo.s = s;
    return !(mo.Omega0(p) == 0 && mo.Omega0(s) == 0);  // along the middle axis
}

// The amplitudes (with their signs), lambda, m and m_c; P1 = |2E I_s - M^2| for the phase. False
// when the motion is a steady rotation (along the p axis, or in the plane of two equal moments).
bool set_elliptic_constants(FreeBodyMotion& mo, LD delta, LD& P1) {
    const int p = mo.p, q = mo.q, s = mo.s;
    const auto Il = [&](int j) { return LD(mo.I(j)); };
    const auto w = [&](int j) { return squared(mo.Omega0, j); };
    const LD dsp = std::fabs(Il(s) - Il(p)), dsq = std::fabs(Il(s) - Il(q)), dqp = std::fabs(Il(q) - Il(p));
    P1 = std::fabs(Il(p) * (Il(s) - Il(p)) * w(p)) + std::fabs(Il(q) * (Il(s) - Il(q)) * w(q));  // |2E I_s - M^2|
    const LD P2 =
        std::fabs(Il(q) * (Il(q) - Il(p)) * w(q)) + std::fabs(Il(s) * (Il(s) - Il(p)) * w(s));  // |M^2 - 2E I_p|
    const LD P3 = std::fabs(delta);                                                             // |M^2 - 2E I_q|
    if (P2 == 0) return false;

    const LD Ap = std::sqrt(P1 / (Il(p) * dsp)), Aq = std::sqrt(P1 / (Il(q) * dsq)), As = std::sqrt(P2 / (Il(s) * dsp));
    mo.lambda = double(std::sqrt(dsq * P2 / (Il(p) * Il(q) * Il(s))));
    mo.m = double(dqp * P1 / (dsq * P2));
    mo.m_c = double(dsp * P3 / (dsq * P2));

    // Signs: sigma_p sigma_q sigma_s = parity(p, q, s) * sign(I_s - I_q), from Euler's equations.
    const double sp = mo.Omega0(p) < 0 ? -1 : 1, ss = mo.Omega0(s) < 0 ? -1 : 1;
    const double parity = (q == (p + 1) % 3) ? 1 : -1;
    const double sq = parity * (mo.I(s) > mo.I(q) ? 1 : -1) * sp * ss;
    mo.amplitude(p) = sp * double(Ap);
    mo.amplitude(q) = sq * double(Aq);
    mo.amplitude(s) = ss * double(As);
    return true;
}

// The phase u0 and the period.
void set_phase_and_period(FreeBodyMotion& mo, LD P1) {
    // u0 = F(phi0 | m) with sin(phi0) = sn(u0), cos(phi0) = cn(u0) >= 0:
    // F = sin(phi) R_F(cos^2 phi, cos^2 phi + m_c sin^2 phi, 1), free of 1 - m.
    if (P1 > 0) {
        const double sn0 = mo.Omega0(mo.q) / mo.amplitude(mo.q), cn0 = mo.Omega0(mo.p) / mo.amplitude(mo.p);
        const double r = std::hypot(sn0, cn0), sphi = sn0 / r, cphi = cn0 / r;
        mo.u0 = sphi * carlson_rf(cphi * cphi, cphi * cphi + mo.m_c * sphi * sphi, 1.0);
    }
    mo.period = mo.m_c > 0 ? 4 * carlson_rf(0.0, mo.m_c, 1.0) / mo.lambda : std::numeric_limits<double>::infinity();
}

}  // namespace

FreeBodyMotion free_body_motion(const Vec3& I, const Vec3& Omega0) {
    require_principal_moments(I);
    if (!Omega0.allFinite())
        throw std::invalid_argument("initial angular velocity Omega0 must be finite, got " + describe(Omega0));
    FreeBodyMotion mo;
    mo.I = I;
    mo.Omega0 = Omega0;
    set_invariants(mo);
    LD delta = 0, P1 = 0;
    if (!choose_axes(mo, delta) || !set_elliptic_constants(mo, delta, P1)) {
        mo.steady = true;
        mo.period = 0;
        return mo;
    }
    set_phase_and_period(mo, P1);
    return mo;
}

Vec3 free_body_exact_omega(const FreeBodyMotion& mo, double t) {
    require_finite(t, "time t");
    if (mo.steady) return mo.Omega0;
    const JacobiElliptic e = jacobi_elliptic(mo.u0 + mo.lambda * t, mo.m, mo.m_c);
    Vec3 Omega;
    Omega(mo.p) = mo.amplitude(mo.p) * e.cn;
    Omega(mo.q) = mo.amplitude(mo.q) * e.sn;
    Omega(mo.s) = mo.amplitude(mo.s) * e.dn;
    return Omega;
}

std::vector<Mat3> free_body_exact_rotations(const FreeBodyMotion& mo, const std::vector<double>& times) {
    for (std::size_t i = 0; i < times.size(); ++i) {
        require_finite(times[i], "output time");
        if (i > 0 && !(times[i] > times[i - 1]))
            throw std::invalid_argument("free_body_exact_rotations: times must be strictly increasing");
    }
    std::vector<Mat3> out;
    out.reserve(times.size());
    if (mo.steady) {
        const double w = mo.Omega0.norm();
        for (double t : times)
            out.push_back(w > 0 ? Mat3(Eigen::AngleAxisd(w * t, mo.Omega0 / w).toRotationMatrix()) : Mat3::Identity());
        return out;
    }
    const double M = std::sqrt(mo.momentum_squared), twoE_over_M = 2 * mo.energy / M;
    const Vec3 n = (mo.amplitude(mo.s) < 0 ? -1.0 : 1.0) * Vec3::Unit(mo.s);
    const auto l_of = [&](const Vec3& Omega) { return Vec3(mo.I.cwiseProduct(Omega).normalized()); };
    // phi' = 2E/M - n.(l x l') / (1 + n.l), with l' = l x Omega (the body sees m turn backwards).
    const auto phi_dot = [&](double t) {
        const Vec3 Omega = free_body_exact_omega(mo, t), l = l_of(Omega);
        const Vec3 l_dot = l.cross(Omega);
        return twoE_over_M - n.dot(l.cross(l_dot)) / (1 + n.dot(l));
    };
    // Panels short against the fastest time scale: |Omega| <= sqrt(2E / I_min), and lambda.
    const double rate = std::max(mo.lambda, std::sqrt(2 * mo.energy / mo.I.minCoeff()));
    const double panel = 0.25 / rate;
    const GaussLegendre& gl = gauss_legendre();
    const auto integral = [&](double a, double b) {
        const long panels = std::max(1L, long(std::ceil(std::abs(b - a) / panel)));
        const double h = (b - a) / double(panels);
        double sum = 0;
        for (long k = 0; k < panels; ++k) {
            const double mid = a + (double(k) + 0.5) * h;
            double part = 0;
            for (int i = 0; i < GaussLegendre::n; ++i) part += gl.w[i] * phi_dot(mid + 0.5 * h * gl.x[i]);
            sum += 0.5 * h * part;
        }
        return sum;
    };
    const Mat3 W0T = swing(l_of(mo.Omega0), n).transpose();
    double t_prev = 0, phi = 0;
    for (double t : times) {
        if (t != t_prev) phi += integral(t_prev, t);
        t_prev = t;
        const Vec3 l = l_of(free_body_exact_omega(mo, t));
        out.push_back(W0T * Eigen::AngleAxisd(phi, n).toRotationMatrix() * swing(l, n));
    }
    return out;
}

}  // namespace rigid
