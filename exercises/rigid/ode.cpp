// GSL odeiv2 behind the workbook's interface (rigid/ode.hpp). Provided, not an exercise.
#include "rigid/ode.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
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
    {"rk2", &gsl_odeiv2_step_rk2, false},       {"rk4", &gsl_odeiv2_step_rk4, false},
    {"rkf45", &gsl_odeiv2_step_rkf45, false},   {"rkck", &gsl_odeiv2_step_rkck, false},
    {"rk8pd", &gsl_odeiv2_step_rk8pd, false},   {"msadams", &gsl_odeiv2_step_msadams, false},
    {"rk1imp", &gsl_odeiv2_step_rk1imp, true},  {"rk2imp", &gsl_odeiv2_step_rk2imp, true},
    {"rk4imp", &gsl_odeiv2_step_rk4imp, true},  {"bsimp", &gsl_odeiv2_step_bsimp, true},
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
    const OdeRhs& f;
    const OdeJacobian& jacobian;
    std::size_t n;
    OdeStats stats;
    std::exception_ptr error;
};

int rhs(double t, const double y[], double dydt[], void* params) {
    auto& c = *static_cast<Context*>(params);
    try {
        ++c.stats.rhs_calls;
        const VecX dy = c.f(t, Eigen::Map<const VecX>(y, c.n));
        if (static_cast<std::size_t>(dy.size()) != c.n)
            throw std::logic_error("the right-hand side returned " + std::to_string(dy.size()) + " numbers for a state of " +
                                   std::to_string(c.n));
        Eigen::Map<VecX>(dydt, c.n) = dy;
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

OdeStats integrate_gsl(const OdeRhs& f, const VecX& y0, const std::vector<double>& times, const OdeObserver& observe,
                       const OdeSettings& settings, const OdeJacobian& jacobian) {
    static const auto previous_handler = gsl_set_error_handler_off();  // report, never abort()
    (void)previous_handler;
    const Method& method = find_method(settings.method);
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
        if (i > 0 && !(times[i] > times[i - 1])) throw std::invalid_argument("output times must be strictly increasing");
    }
    if (y0.size() == 0 || !y0.allFinite()) throw std::invalid_argument("the initial state must be non-empty and finite");

    Context c{f, jacobian, static_cast<std::size_t>(y0.size()), {}, nullptr};
    gsl_odeiv2_system system{rhs, method.needs_jacobian ? jac : nullptr, c.n, &c};
    std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)> driver(
        gsl_odeiv2_driver_alloc_y_new(&system, *method.type, settings.first_step, settings.abs_tol, settings.rel_tol),
        gsl_odeiv2_driver_free);
    if (!driver) throw std::runtime_error("GSL could not allocate the '" + settings.method + "' driver");
    if (settings.max_steps > 0) gsl_odeiv2_driver_set_nmax(driver.get(), static_cast<unsigned long>(settings.max_steps));

    VecX y = y0;
    double t = times.front();
    observe(t, y);
    for (std::size_t i = 1; i < times.size(); ++i) {
        const int status = gsl_odeiv2_driver_apply(driver.get(), &t, times[i], y.data());
        if (c.error) std::rethrow_exception(c.error);
        if (status != GSL_SUCCESS)
            throw std::runtime_error("GSL " + settings.method + " failed at t = " + std::to_string(t) + ": " +
                                     gsl_strerror(status));
        observe(t, y);
    }
    return c.stats;
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
    if (y.size() != 12) throw std::invalid_argument("a rigid-body state has 12 numbers, got " + std::to_string(y.size()));
    BodyState s;
    s.Omega = y.head<3>();
    for (int i = 0; i < 3; ++i) s.R.row(i) = y.segment<3>(3 + 3 * i).transpose();
    return s;
}

}  // namespace rigid
