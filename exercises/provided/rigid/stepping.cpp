// The fixed-step driver for steppers in increment form (rigid/stepping.hpp). Provided.
#include "rigid/stepping.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rigid/require.hpp"

namespace rigid {

namespace {

// Kahan's compensated summation, one entry at a time: sum += x, with the part of x that the
// rounding of sum lost kept in c (to be subtracted from the next term).
template <class M>
void kahan_add(M& sum, M& c, const M& x) {
    const M y = x - c;
    const M t = sum + y;
    c = (t - sum) - y;
    sum = t;
}

}  // namespace

long integrate_steps(const IncrementStepper& step, const BodyState& s0, const std::vector<double>& times,
                     const BodyObserver& observe, double h, Summation summation) {
    require_positive(h, "step h");
    if (times.empty()) throw std::invalid_argument("no output times");
    for (std::size_t i = 0; i < times.size(); ++i) {
        require_finite(times[i], "output time");
        if (i > 0 && !(times[i] > times[i - 1]))
            throw std::invalid_argument("output times must be strictly increasing");
    }
    if (!s0.Omega.allFinite() || !s0.R.allFinite()) throw std::invalid_argument("the initial state must be finite");

    BodyState s = s0;
    Vec3 c_Omega = Vec3::Zero();  // compensations: what the rounding of s has lost so far
    Mat3 c_R = Mat3::Zero();
    long steps = 0;
    observe(times.front(), s);
    for (std::size_t k = 1; k < times.size(); ++k) {
        const double span = times[k] - times[k - 1];
        const long n = std::max(1L, static_cast<long>(std::ceil(span / h)));
        const double dt = span / static_cast<double>(n);
        for (long i = 0; i < n; ++i) {
            const Increment d = step(s, dt);
            if (summation == Summation::plain) {
                s = apply(s, d);
            } else {
                const Mat3 dR = s.R * d.E;
                kahan_add(s.Omega, c_Omega, d.dOmega);
                kahan_add(s.R, c_R, dR);
            }
        }
        steps += n;
        observe(times[k], s);
    }
    return steps;
}

}  // namespace rigid
