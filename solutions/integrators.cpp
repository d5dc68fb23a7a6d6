// Reference solutions: the fixed-step classical Runge-Kutta method. Contracts in
// rigid/integrators.hpp.
#include "rigid/integrators.hpp"

#include <cmath>
#include <stdexcept>

#include "rigid/require.hpp"

namespace rigid {

VecX rk4_step(const OdeRhs& f, double t, const VecX& y, double h) {
    const VecX k1 = f(t, y);
    const VecX k2 = f(t + h / 2, y + (h / 2) * k1);
    const VecX k3 = f(t + h / 2, y + (h / 2) * k2);
    const VecX k4 = f(t + h, y + h * k3);
    return y + (h / 6) * (k1 + 2 * k2 + 2 * k3 + k4);
}

long integrate_rk4(const OdeRhs& f, const VecX& y0, const std::vector<double>& times, const OdeObserver& observe,
                   double h) {
    require_positive(h, "step h");
    if (times.empty()) throw std::invalid_argument("integrate_rk4: no output times");
    for (std::size_t i = 0; i < times.size(); ++i) {
        require_finite(times[i], "output time");
        if (i > 0 && !(times[i] > times[i - 1]))
            throw std::invalid_argument("integrate_rk4: output times must be strictly increasing");
    }
    if (y0.size() == 0 || !y0.allFinite())
        throw std::invalid_argument("integrate_rk4: the initial state must be non-empty and finite");

    VecX y = y0;
    observe(times.front(), y);
    long steps = 0;
    for (std::size_t i = 1; i < times.size(); ++i) {
        const double t0 = times[i - 1], span = times[i] - t0;
        const long n = std::max(1L, static_cast<long>(std::ceil(span / h)));
        const double step = span / double(n);
        // t from t0 + j * step (no accumulated sum), and the last step ends exactly on times[i].
        for (long j = 0; j < n; ++j) y = rk4_step(f, t0 + double(j) * step, y, step);
        steps += n;
        observe(times[i], y);
    }
    return steps;
}

}  // namespace rigid
