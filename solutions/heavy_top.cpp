// Chapter 4 reference solutions: the heavy top. Contracts in rigid/heavy_top.hpp.
#include "rigid/heavy_top.hpp"

#include <gsl/gsl_multimin.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "rigid/require.hpp"
#include "rigid/rotation.hpp"

namespace rigid {

namespace {

// J must be symmetric (to 1e-12 relative to its largest entry) and have finite entries.
void require_symmetric(const Mat3& J, const std::string& name) {
    if (!J.allFinite()) throw std::invalid_argument(name + " must have finite entries");
    const double scale = J.cwiseAbs().maxCoeff();
    if (!((J - J.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale))
        throw std::invalid_argument(name + " must be symmetric (J_ij = J_ji)");
}

void require_b3(double b3) {
    require_finite(b3, "b3");
    if (!(b3 > -1 && b3 < 1)) {
        std::ostringstream s;
        s.precision(17);
        s << "b3 must satisfy -1 < b3 < 1 (b is a unit vector with b2 > 0, [P, (3.3)]), got " << b3;
        throw std::invalid_argument(s.str());
    }
}

// Principal moments: positive, finite, each at most the sum of the other two.
void require_moments(const Vec3& m) {
    for (int i = 0; i < 3; ++i) require_positive(m(i), "principal moment");
    const double sum = m.sum();
    for (int i = 0; i < 3; ++i)
        if (!(m(i) <= sum - m(i)))
            throw std::invalid_argument(
                "principal moments must satisfy the triangle inequality (each at most the sum of the other two)");
}

Vec3 unit_from_angles(double theta, double phi) {
    return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

Mat3 rotation_from_vector(const Vec3& v) {
    const double angle = v.norm();
    if (!(angle > 0)) return Mat3::Identity();
    return rotation_about(v, angle);
}

// What the simplex moves: the search's parameters, decoded into a body and a precession.
struct Decoded {
    HeavyTop top;
    TrialPrecession precession;
};

Decoded decode(const PrecessionSearch& S, const double* x) {
    const Mat3 Q = rotation_from_vector(Vec3(x[0], x[1], x[2]));
    Decoded d;
    const Mat3 J = Q * S.moments.asDiagonal() * Q.transpose();
    d.top.J = 0.5 * (J + J.transpose());  // into another matrix: J = 0.5 (J + J^T) in place aliases
    d.top.f = 1.0;
    d.top.z0 = unit_from_angles(x[3], x[4]);
    const double s = std::exp(std::clamp(x[5], -60.0, 60.0));
    const Vec3 b(0, std::sin(S.gamma), std::cos(S.gamma));
    d.top.k = S.k_along_b ? b : unit_from_angles(x[6], x[7]);
    d.precession = {Vec3::UnitZ(), std::sqrt(s), b, S.ratio * std::sqrt(s)};
    return d;
}

struct SearchContext {
    const PrecessionSearch& search;
    long evaluations = 0;
};

double search_objective(const gsl_vector* x, void* params) {
    auto& c = *static_cast<SearchContext*>(params);
    ++c.evaluations;
    const Decoded d = decode(c.search, x->data);
    const double r = precession_residual(d.top, d.precession);
    return std::isfinite(r) ? r : 1e300;
}

}  // namespace

HeavyTop heavy_top(const Mat3& J, double f, const Vec3& k, const Vec3& z0) {
    require_symmetric(J, "inertia tensor J");
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(J, Eigen::EigenvaluesOnly);
    if (!(eig.eigenvalues().minCoeff() > 0))
        throw std::invalid_argument("inertia tensor J must be positive definite (all principal moments > 0)");
    require_positive(f, "f = g L mu");
    return {J, f, require_axis(k, "heavy_top: its argument k (the upward vertical)"),
            require_axis(z0, "heavy_top: its argument z0 (the direction z(0) from O to the centre of mass)")};
}

BodyState euler_poisson_rhs(const HeavyTop& top, const BodyState& s) {
    const Vec3 L = top.J * s.Omega;
    const Vec3 rhs = L.cross(s.Omega) + top.f * (s.R.transpose() * top.k).cross(top.z0);
    return {top.J.llt().solve(rhs), s.R * hat(s.Omega)};
}

double heavy_top_energy(const HeavyTop& top, const BodyState& s) {
    return 0.5 * s.Omega.dot(top.J * s.Omega) + top.f * top.k.dot(s.R * top.z0);
}

MatX euler_poisson_jacobian(const HeavyTop& top, const BodyState& s) {
    MatX D = MatX::Zero(12, 12);
    const Mat3 Jinv = top.J.inverse();
    // d/dOmega of [J Omega, Omega] = hat(J Omega) - hat(Omega) J.
    D.block<3, 3>(0, 0) = Jinv * (hat(top.J * s.Omega) - hat(s.Omega) * top.J);
    // f [R^T k, z0] = -f hat(z0) R^T k, and d(R^T k)_c / dR_ac = k_a.
    const Mat3 G = -top.f * Jinv * hat(top.z0);
    for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c) D.block<3, 1>(0, 3 + 3 * a + c) = G.col(c) * top.k(a);
    // R_dot_ij = sum_l R_il hat(Omega)_lj: row i of R_dot depends on row i of R only.
    const Mat3 W = hat(s.Omega);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            for (int l = 0; l < 3; ++l) D(3 + 3 * i + j, 3 + 3 * i + l) = W(l, j);
            for (int m = 0; m < 3; ++m) D(3 + 3 * i + j, m) = (s.R * hat(Vec3::Unit(m)))(i, j);
        }
    return D;
}

Vec3 euler_vector(const Mat3& J, const TrialPrecession& p, double t) {
    const Vec3 a = require_axis(p.a, "rotation vector a"), b = require_axis(p.b, "precession vector b");
    require_finite(p.alpha, "alpha");
    require_finite(p.beta, "beta");
    require_finite(t, "time t");
    const Vec3 bt = rotation_about(a, p.alpha * t).transpose() * b;  // R^a(alpha t)^T b
    const Vec3 Omega = p.alpha * a + p.beta * bt;                    // [P, (1.5)]
    const Vec3 Omega_dot = -p.alpha * p.beta * a.cross(bt);
    return J * Omega_dot - (J * Omega).cross(Omega);
}

Vec3 torque(const Vec3& k, const Vec3& z0, const TrialPrecession& p, double t) {
    const Vec3 a = require_axis(p.a, "rotation vector a"), b = require_axis(p.b, "precession vector b");
    require_finite(p.alpha, "alpha");
    require_finite(p.beta, "beta");
    require_finite(t, "time t");
    const Mat3 R = rotation_about(b, p.beta * t) * rotation_about(a, p.alpha * t);
    return (R.transpose() * k).cross(z0);
}

Vec3 evaluate(const PrecessionSeries& s, double alpha, double beta, double t) {
    const double gp = (alpha + beta) * t, gm = (alpha - beta) * t;
    return s.constant + s.cos_alpha * std::cos(alpha * t) + s.sin_alpha * std::sin(alpha * t) +
           s.cos_2alpha * std::cos(2 * alpha * t) + s.sin_2alpha * std::sin(2 * alpha * t) +
           s.cos_beta * std::cos(beta * t) + s.sin_beta * std::sin(beta * t) + s.cos_plus * std::cos(gp) +
           s.sin_plus * std::sin(gp) + s.cos_minus * std::cos(gm) + s.sin_minus * std::sin(gm);
}

PrecessionSeries euler_vector_series(const Mat3& J, double alpha, double beta, double b3) {
    require_symmetric(J, "inertia tensor J");
    require_finite(alpha, "alpha");
    require_finite(beta, "beta");
    require_b3(b3);
    const double b2 = std::sqrt((1 - b3) * (1 + b3));
    const double w = alpha + beta * b3, bb = beta * b2, half = 0.5 * bb * bb;
    PrecessionSeries E;
    E.constant = (half - w * w) * Vec3(J(1, 2), -J(0, 2), 0);
    E.cos_alpha =
        bb * Vec3(w * (J(2, 2) - J(1, 1)) + alpha * J(0, 0), (2 * alpha + beta * b3) * J(0, 1), -beta * b3 * J(0, 2));
    E.sin_alpha =
        bb * Vec3(-(2 * alpha + beta * b3) * J(0, 1), w * (J(0, 0) - J(2, 2)) - alpha * J(1, 1), beta * b3 * J(1, 2));
    E.cos_2alpha = half * Vec3(J(1, 2), J(0, 2), -2 * J(0, 1));
    E.sin_2alpha = half * Vec3(J(0, 2), -J(1, 2), J(1, 1) - J(0, 0));  // [P] prints 2 (J22 - J11)
    return E;
}

PrecessionSeries torque_series(const Vec3& k, const Vec3& z0, double alpha, double beta, double b3) {
    if (!k.allFinite() || !z0.allFinite()) throw std::invalid_argument("k and z(0) must be finite vectors");
    if (!(std::abs(k.x()) <= 1e-12 * k.norm()))
        throw std::invalid_argument("k must lie in the plane of a and b, k = (0, k2, k3) [P, (3.3)], got " +
                                    describe(k));
    require_finite(alpha, "alpha");
    require_finite(beta, "beta");
    require_b3(b3);
    const double b2 = std::sqrt((1 - b3) * (1 + b3));
    const double n = b2 * k.y() + b3 * k.z(), p = b3 * k.y() - b2 * k.z();  // [P, (3.7)]
    const double z1 = z0.x(), z2 = z0.y(), z3 = z0.z();
    PrecessionSeries T;
    T.constant = b3 * n * Vec3(-z2, z1, 0);
    T.cos_alpha = b2 * n * Vec3(z3, 0, -z1);
    T.sin_alpha = b2 * n * Vec3(0, -z3, z2);
    T.cos_beta = b2 * p * Vec3(z2, -z1, 0);
    T.cos_plus = 0.5 * (1 + b3) * p * Vec3(z3, 0, -z1);
    T.sin_plus = 0.5 * (1 + b3) * p * Vec3(0, -z3, z2);
    T.cos_minus = 0.5 * (1 - b3) * p * Vec3(-z3, 0, z1);  // [P] prints (1 + b3)
    T.sin_minus = 0.5 * (1 - b3) * p * Vec3(0, z3, -z2);  // [P] prints cos(gamma_- t)
    return T;
}

double precession_residual(const HeavyTop& top, const TrialPrecession& p, int n) {
    if (n < 16) throw std::invalid_argument("precession_residual needs n >= 16 sample times, got " + std::to_string(n));
    require_positive(top.f, "f = g L mu");
    require_positive(p.alpha, "alpha");
    require_positive(p.beta, "beta");
    const Vec3 a = require_axis(p.a, "rotation vector a"), b = require_axis(p.b, "precession vector b");
    const double L = 4 * std::numbers::pi / std::min(p.alpha, p.beta);
    double sum = 0;
    for (int j = 0; j < n; ++j) {
        // euler_vector and torque in one pass, sharing R^a(alpha t): the search calls this a lot.
        const double t = (j + 0.5) * L / n;
        const Mat3 Ra = rotation_about(a, p.alpha * t);
        const Vec3 bt = Ra.transpose() * b;
        const Vec3 Omega = p.alpha * a + p.beta * bt, Omega_dot = -p.alpha * p.beta * a.cross(bt);
        const Vec3 E = top.J * Omega_dot - (top.J * Omega).cross(Omega);
        const Vec3 T = ((rotation_about(b, p.beta * t) * Ra).transpose() * top.k).cross(top.z0);
        sum += (E - top.f * T).squaredNorm();
    }
    return std::sqrt(sum / n) / top.f;
}

PrecessionFit min_precession_residual(const PrecessionSearch& search) {
    require_moments(search.moments);
    require_finite(search.gamma, "gamma");
    if (!(search.gamma > 0 && search.gamma < std::numbers::pi))
        throw std::invalid_argument("gamma, the angle between a and b, must satisfy 0 < gamma < pi");
    require_positive(search.ratio, "ratio beta/alpha");
    if (search.restarts < 1) throw std::invalid_argument("restarts must be >= 1");

    const std::size_t n = search.k_along_b ? 6 : 8;
    SearchContext context{search};
    gsl_multimin_function F{search_objective, n, &context};
    std::unique_ptr<gsl_multimin_fminimizer, decltype(&gsl_multimin_fminimizer_free)> m(
        gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, n), gsl_multimin_fminimizer_free);
    std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> x(gsl_vector_alloc(n), gsl_vector_free);
    std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> step(gsl_vector_alloc(n), gsl_vector_free);

    std::mt19937 rng(search.seed);
    std::uniform_real_distribution<double> start(-3, 3);
    double best = INFINITY;
    std::vector<double> best_x(n, 0.0);
    for (int r = 0; r < search.restarts && !(best < 1e-12); ++r) {
        for (std::size_t i = 0; i < n; ++i) gsl_vector_set(x.get(), i, start(rng));
        gsl_vector_set_all(step.get(), 0.5);
        double previous = INFINITY;
        // Restart the simplex at its own minimum (smaller steps) until it stops improving:
        // Nelder-Mead can stall on a collapsed simplex, a restart un-collapses it.
        for (int round = 0; round < 6; ++round) {
            gsl_multimin_fminimizer_set(m.get(), &F, x.get(), step.get());
            for (int it = 0; it < 4000; ++it) {
                if (gsl_multimin_fminimizer_iterate(m.get())) break;
                if (gsl_multimin_fminimizer_size(m.get()) < 1e-10 * (1 + m->fval)) break;
            }
            gsl_vector_memcpy(x.get(), m->x);
            gsl_vector_set_all(step.get(), 0.05);
            if (!(m->fval < 0.999 * previous)) break;
            previous = m->fval;
        }
        if (m->fval < best) {
            best = m->fval;
            best_x.assign(m->x->data, m->x->data + n);
        }
    }
    const Decoded d = decode(search, best_x.data());
    return {precession_residual(d.top, d.precession), d.top, d.precession, context.evaluations};
}

double sleeping_top_min_spin(double A, double C, double f) {
    require_positive(A, "moment A");
    require_positive(C, "moment C");
    require_positive(f, "f = g L mu");
    if (C > 2 * A)
        throw std::invalid_argument("sleeping_top_min_spin: C > 2A breaks the triangle inequality C <= A + A");
    return 2 * std::sqrt(A * f) / C;  // C^2 omega^2 > 4 A f
}

}  // namespace rigid
