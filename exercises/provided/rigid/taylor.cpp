// The Taylor-series reference integrator (rigid/taylor.hpp). Provided.
#include "rigid/taylor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rigid/require.hpp"

namespace rigid {

namespace {

template <class Real>
using V3 = Eigen::Matrix<Real, 3, 1>;
template <class Real>
using M3 = Eigen::Matrix<Real, 3, 3>;

// a x b, written out (Eigen's cross() wants column vectors; here rows of R are crossed too).
template <class Real>
inline void add_cross(Real* out, const Real* a, const Real* b) {
    out[0] += a[1] * b[2] - a[2] * b[1];
    out[1] += a[2] * b[0] - a[0] * b[2];
    out[2] += a[0] * b[1] - a[1] * b[0];
}

template <class Real>
struct Series {
    // Coefficient n of Omega, of J Omega, and of R stored row by row (row i of R_n at R[n][3 i]).
    std::vector<V3<Real>> W, L;
    std::vector<std::array<Real, 9>> R;
    explicit Series(int order) : W(order + 1), L(order + 1), R(order + 1) {}
};

// The problem in Real: J, its inverse, f, k and z(0). When J is diagonal (the principal frame),
// J^-1 is applied by dividing by its diagonal: each quotient is then correctly rounded, while the
// rounded entries of J^-1 would perturb the equations by the same relative 1e-17 at every step,
// a field that no longer conserves the energy exactly; over a long run that bias makes the
// energy drift like t and the phase like t^2 (Chapter 7, Brouwer's law).
template <class Real>
struct Top {
    M3<Real> J, Jinv;
    Real f;
    V3<Real> k, z0;
    bool diagonal;

    V3<Real> solve(const V3<Real>& b) const {
        return diagonal ? V3<Real>(b.cwiseQuotient(J.diagonal())) : V3<Real>(Jinv * b);
    }
};

// The Taylor coefficients of degree 0 to order of the solution through s, by Cauchy products.
template <class Real>
void expand(const Top<Real>& top, const TaylorState<Real>& s, Series<Real>& c, int order) {
    c.W[0] = s.Omega;
    c.L[0] = top.J * s.Omega;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) c.R[0][3 * i + j] = s.R(i, j);
    for (int n = 0; n < order; ++n) {
        V3<Real> cross = V3<Real>::Zero();
        std::array<Real, 9> Rn{};
        for (int i = 0; i <= n; ++i) {
            add_cross(cross.data(), c.L[i].data(), c.W[n - i].data());
            // Row r of R_i hat(W): (row r) x W.
            for (int r = 0; r < 3; ++r) add_cross(&Rn[3 * r], &c.R[i][3 * r], c.W[n - i].data());
        }
        // R_n^T k, the coefficient n of gamma = R^T k.
        V3<Real> g;
        const V3<Real>& k = top.k;
        for (int j = 0; j < 3; ++j) g(j) = c.R[n][j] * k(0) + c.R[n][3 + j] * k(1) + c.R[n][6 + j] * k(2);
        const Real inv = Real(1) / Real(n + 1);
        c.W[n + 1] = top.solve(cross + top.f * g.cross(top.z0)) * inv;
        c.L[n + 1] = top.J * c.W[n + 1];
        for (int e = 0; e < 9; ++e) c.R[n + 1][e] = Rn[e] * inv;
    }
}

// x += d with Kahan's compensation carried in comp.
template <class Real>
inline void kahan_add(Real& x, Real& comp, Real d) {
    const Real y = d + comp;
    const Real t = x + y;
    comp = (x - t) + y;
    x = t;
}

// One step of length dt: the polynomial by Horner's rule, all of it (plain), or its terms of
// degree 1 and up added to the state with compensation.
template <class Real>
void advance(TaylorState<Real>& s, TaylorState<Real>& comp, const Series<Real>& c, Real dt, int order,
             Summation summation) {
    const bool plain = summation == Summation::plain;
    const int last = plain ? 0 : 1;
    V3<Real> W = c.W[order];
    std::array<Real, 9> R = c.R[order];
    for (int n = order - 1; n >= last; --n) {
        W = W * dt + c.W[n];
        for (int e = 0; e < 9; ++e) R[e] = R[e] * dt + c.R[n][e];
    }
    if (plain) {
        s.Omega = W;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) s.R(i, j) = R[3 * i + j];
        return;
    }
    for (int i = 0; i < 3; ++i) kahan_add(s.Omega(i), comp.Omega(i), W(i) * dt);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) kahan_add(s.R(i, j), comp.R(i, j), R[3 * i + j] * dt);
}

template <class Real>
void require_taylor_arguments(const BodyState& s0, const std::vector<double>& times, double h, int order) {
    require_positive(h, "step h");
    if (order < 1 || order > 60)
        throw std::invalid_argument("order must be between 1 and 60, got " + std::to_string(order));
    if (times.empty()) throw std::invalid_argument("no output times");
    for (std::size_t i = 0; i < times.size(); ++i) {
        require_finite(times[i], "output time");
        if (i > 0 && !(times[i] > times[i - 1]))
            throw std::invalid_argument("output times must be strictly increasing");
    }
    if (!s0.Omega.allFinite() || !s0.R.allFinite()) throw std::invalid_argument("the initial state must be finite");
}

}  // namespace

template <class Real>
long integrate_taylor(const HeavyTop& top, const BodyState& s0, const std::vector<double>& times,
                      const std::function<void(double, const TaylorState<Real>&)>& observe, double h, int order,
                      Summation summation) {
    require_taylor_arguments<Real>(s0, times, h, order);
    const M3<Real> J = top.J.template cast<Real>();
    const bool diagonal = J.isDiagonal(Real(0));
    const Top<Real> t{J, J.inverse(), Real(top.f), top.k.template cast<Real>(), top.z0.template cast<Real>(), diagonal};

    TaylorState<Real> s{s0.Omega.template cast<Real>(), s0.R.template cast<Real>()};
    TaylorState<Real> comp{V3<Real>::Zero(), M3<Real>::Zero()};
    Series<Real> c(order);
    long steps = 0;
    observe(times.front(), s);
    for (std::size_t kout = 1; kout < times.size(); ++kout) {
        const Real span = Real(times[kout]) - Real(times[kout - 1]);
        const long n_steps = std::max(1L, static_cast<long>(std::ceil(static_cast<double>(span) / h)));
        const Real dt = span / Real(n_steps);
        for (long step = 0; step < n_steps; ++step) {
            expand(t, s, c, order);
            advance(s, comp, c, dt, order, summation);
        }
        steps += n_steps;
        observe(times[kout], s);
    }
    return steps;
}

template long integrate_taylor<double>(const HeavyTop&, const BodyState&, const std::vector<double>&,
                                       const std::function<void(double, const TaylorState<double>&)>&, double, int,
                                       Summation);
template long integrate_taylor<long double>(const HeavyTop&, const BodyState&, const std::vector<double>&,
                                            const std::function<void(double, const TaylorState<long double>&)>&, double,
                                            int, Summation);

}  // namespace rigid
