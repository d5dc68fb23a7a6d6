// GSL odeiv2 behind the workbook's interface (rigid/ode.hpp). Provided, not an exercise.
#include "rigid/ode.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <stdexcept>
#include <utility>

namespace rigid {

namespace {

struct Method {
    const char* name;
    const gsl_odeiv2_step_type* const* type;  // GSL exports these as pointer variables
    bool needs_jacobian;
};

const Method methods[] = {
    {"rk2", &gsl_odeiv2_step_rk2, false},      {"rk4", &gsl_odeiv2_step_rk4, false},
    {"rkf45", &gsl_odeiv2_step_rkf45, false},  {"rkck", &gsl_odeiv2_step_rkck, false},
    {"rk8pd", &gsl_odeiv2_step_rk8pd, false},  {"msadams", &gsl_odeiv2_step_msadams, false},
    {"rk1imp", &gsl_odeiv2_step_rk1imp, true}, {"rk2imp", &gsl_odeiv2_step_rk2imp, true},
    {"rk4imp", &gsl_odeiv2_step_rk4imp, true}, {"bsimp", &gsl_odeiv2_step_bsimp, true},
    {"msbdf", &gsl_odeiv2_step_msbdf, true},
};

const Method& find_method(const std::string& name) {
    for (const auto& m : methods)
        if (name == m.name) return m;
    std::string list;
    for (const auto& m : methods) list += std::string(list.empty() ? "" : ", ") + m.name;
    throw std::invalid_argument("unknown integration method '" + name + "' (known: " + list + ")");
}

// What GSL calls back: the user's functions, and the first exception they threw. C frames
// must not be unwound through, so callbacks catch, park the exception, and report failure.
struct Context {
    const OdeRhs* f;  // one of the two right-hand sides
    const OdeRhsInPlace* fast;
    const OdeJacobian& jacobian;
    std::size_t n;
    OdeStats stats;
    std::exception_ptr error;
};

int rhs(double t, const double y[], double dydt[], void* params) {
    auto& c = *static_cast<Context*>(params);
    try {
        ++c.stats.rhs_calls;
        if (c.fast) {
            (*c.fast)(t, y, dydt);
        } else {
            const VecX dy = (*c.f)(t, Eigen::Map<const VecX>(y, static_cast<Eigen::Index>(c.n)));
            if (static_cast<std::size_t>(dy.size()) != c.n)
                throw std::logic_error("the right-hand side returned " + std::to_string(dy.size()) +
                                       " numbers for a state of " + std::to_string(c.n));
            Eigen::Map<VecX>(dydt, static_cast<Eigen::Index>(c.n)) = dy;
        }
        return GSL_SUCCESS;
    } catch (...) {
        if (!c.error) c.error = std::current_exception();
        return GSL_EBADFUNC;
    }
}

int jac(double t, const double y[], double* dfdy, double dfdt[], void* params) {
    auto& c = *static_cast<Context*>(params);
    try {
        ++c.stats.jacobian_calls;
        const VecX yv = Eigen::Map<const VecX>(y, c.n);
        const MatX J = c.jacobian(t, yv);
        if (static_cast<std::size_t>(J.rows()) != c.n || static_cast<std::size_t>(J.cols()) != c.n)
            throw std::logic_error("the Jacobian has the wrong shape");
        // GSL wants dfdy[i * n + j] = df_i/dy_j: row-major.
        Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(dfdy, c.n, c.n) = J;
        // The workbook's systems are autonomous, so df/dt = 0.
        std::fill(dfdt, dfdt + c.n, 0.0);
        return GSL_SUCCESS;
    } catch (...) {
        if (!c.error) c.error = std::current_exception();
        return GSL_EBADFUNC;
    }
}

}  // namespace

const std::vector<std::string>& gsl_methods() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        for (const auto& m : methods) v.push_back(m.name);
        return v;
    }();
    return names;
}

bool gsl_method_needs_jacobian(const std::string& method) { return find_method(method).needs_jacobian; }

namespace {

double time_calls(Context& c, const VecX& y0, long calls, VecX* last) {
    // Through a function pointer the compiler cannot see through, as GSL calls it.
    int (*volatile fn)(double, const double[], double[], void*) = rhs;
    VecX y = y0, dydt(y0.size());
    const auto t0 = std::chrono::steady_clock::now();
    for (long i = 0; i < calls; ++i) {
        if (fn(0.0, y.data(), dydt.data(), &c) != GSL_SUCCESS) std::rethrow_exception(c.error);
        y(0) += 1e-300 * dydt(0);  // a dependence from call to call that the optimiser must keep
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (last) *last = dydt;
    return s;
}

}  // namespace

double time_gsl_calls(const OdeRhs& f, const VecX& y, long calls, VecX* last) {
    const OdeJacobian none;
    Context c{&f, nullptr, none, static_cast<std::size_t>(y.size()), {}, nullptr};
    return time_calls(c, y, calls, last);
}

double time_gsl_calls(const OdeRhsInPlace& f, const VecX& y, long calls, VecX* last) {
    const OdeJacobian none;
    Context c{nullptr, &f, none, static_cast<std::size_t>(y.size()), {}, nullptr};
    return time_calls(c, y, calls, last);
}

namespace {

void check_arguments(const Method& method, const VecX& y0, const std::vector<double>& times,
                     const OdeSettings& settings, const OdeJacobian& jacobian) {
    if (method.needs_jacobian && !jacobian)
        throw std::invalid_argument("method '" + settings.method + "' is implicit and needs the Jacobian df/dy");
    if (!(settings.rel_tol >= 0) || !(settings.abs_tol >= 0) || !std::isfinite(settings.rel_tol) ||
        !std::isfinite(settings.abs_tol) || settings.rel_tol + settings.abs_tol == 0)
        throw std::invalid_argument("tolerances must be finite, >= 0 and not both 0");
    if (!(settings.first_step > 0) || !std::isfinite(settings.first_step))
        throw std::invalid_argument("first_step must be a finite number > 0");
    if (times.empty()) throw std::invalid_argument("no output times");
    for (std::size_t i = 0; i < times.size(); ++i) {
        if (!std::isfinite(times[i])) throw std::invalid_argument("output times must be finite");
        if (i > 0 && !(times[i] > times[i - 1]))
            throw std::invalid_argument("output times must be strictly increasing");
    }
    if (y0.size() == 0 || !y0.allFinite())
        throw std::invalid_argument("the initial state must be non-empty and finite");
    if (settings.compensated_time && (method.needs_jacobian || settings.method == "msadams"))
        throw std::invalid_argument(
            "compensated_time needs an explicit Runge-Kutta method (rk2, rk4, rkf45, rkck, rk8pd), not '" +
            settings.method + "'");
}

[[noreturn]] void solver_failed(const OdeSettings& settings, double t, int status) {
    throw std::runtime_error("GSL " + settings.method + " failed at t = " + std::to_string(t) + ": " +
                             gsl_strerror(status));
}

// GSL's own driver: gsl_odeiv2_driver_apply to each output time.
void drive_with_gsl(Context& c, gsl_odeiv2_system& system, const Method& method, VecX& y,
                    const std::vector<double>& times, const OdeObserver& observe, const OdeSettings& settings) {
    std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)> driver(
        gsl_odeiv2_driver_alloc_y_new(&system, *method.type, settings.first_step, settings.abs_tol, settings.rel_tol),
        gsl_odeiv2_driver_free);
    if (!driver) throw std::runtime_error("GSL could not allocate the '" + settings.method + "' driver");
    if (settings.max_steps > 0)
        gsl_odeiv2_driver_set_nmax(driver.get(), static_cast<unsigned long>(settings.max_steps));
    double t = times.front();
    for (std::size_t i = 1; i < times.size(); ++i) {
        const int status = gsl_odeiv2_driver_apply(driver.get(), &t, times[i], y.data());
        if (c.error) std::rethrow_exception(c.error);
        if (status != GSL_SUCCESS) solver_failed(settings, t, status);
        observe(t, y);
    }
}

// snippet: compensated_time
// Our own driver: the loop of gsl_odeiv2_evolve_apply (try a step, let the control judge it,
// retry smaller or accept), with the time kept as t_hi + t_lo. After each accepted step of
// size h, (t_hi, t_lo) <- (t_hi + h, t_lo + the rounding error of t_hi + h) by Knuth's
// two-sum: no step is lost to the rounding of t += h, and the step that ends on an output
// time t1 is (t1 - t_hi) - t_lo, the time actually left.
void drive_compensated(Context& c, gsl_odeiv2_system& system, const Method& method, VecX& y,
                       const std::vector<double>& times, const OdeObserver& observe, const OdeSettings& settings) {
    const std::size_t n = c.n;
    std::unique_ptr<gsl_odeiv2_step, decltype(&gsl_odeiv2_step_free)> step(gsl_odeiv2_step_alloc(*method.type, n),
                                                                           gsl_odeiv2_step_free);
    std::unique_ptr<gsl_odeiv2_control, decltype(&gsl_odeiv2_control_free)> control(
        gsl_odeiv2_control_y_new(settings.abs_tol, settings.rel_tol), gsl_odeiv2_control_free);
    if (!step || !control) throw std::runtime_error("GSL could not allocate the '" + settings.method + "' stepper");
    const bool use_dydt_in = (*method.type)->can_use_dydt_in != 0;
    std::vector<double> y_before(n), yerr(n), dydt_in(n), dydt_out(n);
    double t_hi = times.front(), t_lo = 0, h = settings.first_step;
    long count = 0;  // accepted steps: after the first, dydt_in is the last step's dydt_out
    for (std::size_t i = 1; i < times.size(); ++i) {
        const double t1 = times[i];
        bool reached = false;
        for (long steps = 0; !reached; ++steps) {
            const double left = (t1 - t_hi) - t_lo;  // the time still to go, to one rounding
            if (!(left > 0)) break;
            if (settings.max_steps > 0 && steps >= settings.max_steps) solver_failed(settings, t_hi, GSL_EMAXITER);
            if (use_dydt_in) {
                if (count == 0 && rhs(t_hi, y.data(), dydt_in.data(), &c) != GSL_SUCCESS)
                    std::rethrow_exception(c.error);
                if (count > 0) dydt_in = dydt_out;
            }
            std::copy(y.data(), y.data() + n, y_before.begin());
            for (double h_try = h;;) {
                const bool final = h_try >= left;
                if (final) h_try = left;
                const int status =
                    gsl_odeiv2_step_apply(step.get(), t_hi, h_try, y.data(), yerr.data(),
                                          use_dydt_in ? dydt_in.data() : nullptr, dydt_out.data(), &system);
                if (c.error) std::rethrow_exception(c.error);
                if (status != GSL_SUCCESS) solver_failed(settings, t_hi, status);
                // As gsl_odeiv2_evolve_apply: the control may shrink the step and ask for a retry.
                double h_new = h_try;
                const double t_next = t_hi + h_try;
                if (gsl_odeiv2_control_hadjust(control.get(), step.get(), y.data(), yerr.data(), dydt_out.data(),
                                               &h_new) == GSL_ODEIV_HADJ_DEC) {
                    if (!(std::abs(h_new) < std::abs(h_try) && t_next + h_new != t_next))
                        solver_failed(settings, t_hi, GSL_FAILURE);
                    std::copy(y_before.begin(), y_before.end(), y.data());
                    h_try = h_new;
                    continue;
                }
                // Accepted: t += h_try exactly, as a two-part sum (Knuth's two-sum, renormalised).
                const double s = t_hi + h_try, b = s - t_hi, err = (t_hi - (s - b)) + (h_try - b);
                t_lo += err;
                t_hi = s + t_lo;
                t_lo -= t_hi - s;
                ++count;
                if (!final) h = h_new;  // GSL keeps the step size over the short step to an output
                reached = final;
                break;
            }
        }
        observe(t1, y);
    }
}
// end snippet

OdeStats integrate(Context& c, const VecX& y0, const std::vector<double>& times, const OdeObserver& observe,
                   const OdeSettings& settings) {
    static const auto previous_handler = gsl_set_error_handler_off();  // report, never abort()
    (void)previous_handler;
    const Method& method = find_method(settings.method);
    check_arguments(method, y0, times, settings, c.jacobian);
    gsl_odeiv2_system system{rhs, method.needs_jacobian ? jac : nullptr, c.n, &c};
    VecX y = y0;
    observe(times.front(), y);
    if (settings.compensated_time)
        drive_compensated(c, system, method, y, times, observe, settings);
    else
        drive_with_gsl(c, system, method, y, times, observe, settings);
    return c.stats;
}

}  // namespace

OdeStats integrate_gsl(const OdeRhs& f, const VecX& y0, const std::vector<double>& times, const OdeObserver& observe,
                       const OdeSettings& settings, const OdeJacobian& jacobian) {
    Context c{&f, nullptr, jacobian, static_cast<std::size_t>(y0.size()), {}, nullptr};
    return integrate(c, y0, times, observe, settings);
}

OdeStats integrate_gsl(const OdeRhsInPlace& f, const VecX& y0, const std::vector<double>& times,
                       const OdeObserver& observe, const OdeSettings& settings, const OdeJacobian& jacobian) {
    Context c{nullptr, &f, jacobian, static_cast<std::size_t>(y0.size()), {}, nullptr};
    return integrate(c, y0, times, observe, settings);
}

std::vector<double> linspace(double t0, double t1, int n) {
    if (n < 1) throw std::invalid_argument("linspace needs n >= 1");
    std::vector<double> t(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) t[static_cast<std::size_t>(i)] = t0 + (t1 - t0) * i / n;
    t.back() = t1;
    return t;
}

VecX pack(const BodyState& s) {
    VecX y(12);
    y.head<3>() = s.Omega;
    for (int i = 0; i < 3; ++i) y.segment<3>(3 + 3 * i) = s.R.row(i).transpose();
    return y;
}

BodyState unpack(const VecX& y) {
    if (y.size() != 12)
        throw std::invalid_argument("a rigid-body state has 12 numbers, got " + std::to_string(y.size()));
    BodyState s;
    s.Omega = y.head<3>();
    for (int i = 0; i < 3; ++i) s.R.row(i) = y.segment<3>(3 + 3 * i).transpose();
    return s;
}

}  // namespace rigid
