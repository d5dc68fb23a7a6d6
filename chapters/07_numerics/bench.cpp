// The Chapter 7 benchmark harness: see bench.hpp.
#include "bench.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>

#include "rigid/free_body_exact.hpp"
#include "rigid/grioli.hpp"
#include "rigid/integrators.hpp"
#include "rigid/numerics.hpp"
#include "rigid/rotation.hpp"
#include "rigid/stepping.hpp"
#include "rigid/taylor.hpp"
#include "scene.hpp"

namespace bench {

using rigid::VecX;

std::vector<double> Scenario::times() const { return rigid::linspace(0, T, outputs); }

namespace {

const double nan_ = std::numeric_limits<double>::quiet_NaN();

// The size of Omega for random states in the agreement check: that of the scenario.
double sc_scale(const BodyState& s) { return std::max(1.0, s.Omega.norm()); }

Mat3 diag(double a, double b, double c) { return Vec3(a, b, c).asDiagonal().toDenseMatrix(); }

// A Grioli precession (Chapter 5) as a scenario: `periods` periods, one output every tenth.
Scenario grioli(const std::string& name, const std::string& title, const rigid::Moments& m, double periods) {
    const rigid::GrioliPrecession g = rigid::grioli_precession(m, 1.0, rigid::Sense::ccw);
    const double P = 2 * std::numbers::pi / g.alpha;
    Scenario sc{name,
                title,
                rigid::grioli_top(m, g),
                rigid::grioli_initial_state(g),
                periods * P,
                10,
                g.alpha * std::sqrt(2.0),
                {},
                "Theorem 1 (Chapter 5)"};
    sc.exact = [g](const std::vector<double>& times) {
        std::vector<BodyState> out;
        for (double t : times) out.push_back({rigid::grioli_angular_velocity(g, t), rigid::grioli_rotation(g, t)});
        return out;
    };
    return sc;
}

// A free body (f = 0) with R(0) = 1, and its exact motion through elliptic functions (Chapter 3).
Scenario free_body(const std::string& name, const std::string& title, const Vec3& I, const Vec3& Omega0, double T) {
    Scenario sc{name,
                title,
                {I.asDiagonal().toDenseMatrix(), 0.0, Vec3::UnitZ(), Vec3::UnitX()},
                {Omega0, Mat3::Identity()},
                T,
                10,
                Omega0.norm(),
                {},
                "elliptic functions (Chapter 3)"};
    const rigid::FreeBodyMotion motion = rigid::free_body_motion(I, Omega0);
    sc.exact = [motion](const std::vector<double>& times) {
        const std::vector<Mat3> R = rigid::free_body_exact_rotations(motion, times);
        std::vector<BodyState> out;
        for (std::size_t i = 0; i < times.size(); ++i)
            out.push_back({rigid::free_body_exact_omega(motion, times[i]), R[i]});
        return out;
    };
    return sc;
}

}  // namespace

// snippet: scenarios
std::vector<Scenario> scenarios() {
    std::vector<Scenario> s;
    s.push_back(free_body("free_body", "free body I = (2, 3, 4), t <= 100", Vec3(2, 3, 4), Vec3(1.0, 0.6, -0.8), 100));
    s.push_back(grioli("grioli", "Grioli (1, 1.5, 2), 10 periods", rigid::moments(1, 1.5, 2), 10));
    s.push_back(grioli("grioli_100", "Grioli (1, 1.5, 2), 100 periods", rigid::moments(1, 1.5, 2), 100));
    s.push_back(grioli("grioli_near_symmetric", "Grioli, B - A = 1e-3 (1, 1.001, 2), 10 periods",
                       rigid::moments_from_gaps(1, 1e-3, 0.999), 10));
    s.push_back(
        grioli("grioli_flat", "Grioli, flat A + B = C (1, 1.5, 2.5), 10 periods", rigid::moments(1, 1.5, 2.5), 10));
    // A fast heavy top, spinning at 150 rad/s about its symmetry axis e2, held horizontal at
    // t = 0 (the gyroscope benchmark of Bruls and Cardona, inertia moved to the fixed point).
    s.push_back({"fast_top",
                 "fast top, spin 150 rad/s, t <= 2",
                 {diag(15.234375, 0.46875, 15.234375), 15 * 9.81, Vec3::UnitZ(), Vec3::UnitY()},
                 {Vec3(0, 150, -4.61538), Mat3::Identity()},
                 2.0,
                 10,
                 150.0,
                 {},
                 ""});
    // A free body started 1e-3 off its middle axis: it flips over twice in t <= 60.
    s.push_back(free_body("separatrix", "free body near the separatrix, I = (1, 2, 3), t <= 60", Vec3(1, 2, 3),
                          Vec3(1e-3, 1.0, 1e-3), 60));
    // A needle: one moment 1e-4, the centre of mass off its axis, so that the torque drives a
    // rotation about the needle at about sqrt(f / 1e-4) = 100 rad/s.
    s.push_back({"needle",
                 "needle I = (1e-4, 1, 1 + 1e-4), t <= 10",
                 {diag(1e-4, 1, 1 + 1e-4), 1.0, Vec3(std::sin(0.3), 0, std::cos(0.3)), Vec3::UnitY()},
                 {Vec3(0, 0.2, 0.5), Mat3::Identity()},
                 10.0,
                 10,
                 100.0,
                 {},
                 ""});
    return s;
}
// end snippet

namespace {

rigid::OdeRhs rhs_of(const HeavyTop& top) {
    return [&top](double, const VecX& y) { return rigid::pack(rigid::euler_poisson_rhs(top, rigid::unpack(y))); };
}

// A GSL method on the right-hand side in place (rigid::EulerPoissonInPlace, what GSL calls);
// with compensated_time, our own driver around GSL's stepper and control (rigid/ode.hpp).
Method gsl(const std::string& name, const std::string& label, const std::string& family, bool compensated_time = false,
           const std::string& id = "") {
    return {id.empty() ? name : id, label, family, Kind::tolerance,
            [name, compensated_time](const Scenario& sc, const std::vector<double>& times, double tol,
                                     std::vector<BodyState>& out) {
                const HeavyTop& top = sc.top;
                std::size_t i = 0;
                rigid::OdeJacobian jac;
                if (rigid::gsl_method_needs_jacobian(name))
                    jac = [&top](double, const VecX& y) {
                        return rigid::euler_poisson_jacobian(top, rigid::unpack(y));
                    };
                const rigid::OdeSettings set{.method = name,
                                             .rel_tol = tol,
                                             .abs_tol = tol,
                                             .first_step = std::min(1e-3, 0.01 / sc.omega),
                                             .compensated_time = compensated_time};
                const rigid::OdeRhsInPlace f = rigid::EulerPoissonInPlace(top);
                return rigid::integrate_gsl(
                           f, rigid::pack(sc.s0), times, [&](double, const VecX& y) { out[i++] = rigid::unpack(y); },
                           set, jac)
                    .rhs_calls;
            }};
}

// A method in increment form, driven by integrate_steps with compensated summation.
Method stepper(const std::string& name, const std::string& label, const std::string& family, int evaluations_per_step,
               std::function<rigid::IncrementStepper(const HeavyTop&)> make) {
    return {name, label, family, Kind::step,
            [=](const Scenario& sc, const std::vector<double>& times, double h, std::vector<BodyState>& out) {
                std::size_t i = 0;
                const long steps = rigid::integrate_steps(
                    make(sc.top), sc.s0, times, [&](double, const BodyState& s) { out[i++] = s; }, h);
                return evaluations_per_step * steps;
            }};
}

}  // namespace

// snippet: methods
const std::vector<Method>& methods() {
    static const std::vector<Method> list = [] {
        std::vector<Method> m;
        m.push_back({"rk4", "your RK4 (fixed h)", "explicit Runge-Kutta", Kind::step,
                     [](const Scenario& sc, const std::vector<double>& times, double h, std::vector<BodyState>& out) {
                         std::size_t i = 0;
                         return 4 * rigid::integrate_rk4(
                                        rhs_of(sc.top), rigid::pack(sc.s0), times,
                                        [&](double, const VecX& y) { out[i++] = rigid::unpack(y); }, h);
                     }});
        m.push_back(gsl("rkf45", "GSL rkf45", "explicit Runge-Kutta"));
        m.push_back(gsl("rk8pd", "GSL rk8pd", "explicit Runge-Kutta"));
        m.push_back(gsl("msadams", "GSL msadams", "multistep"));
        m.push_back(gsl("rk4imp", "GSL rk4imp (Gauss)", "implicit"));
        m.push_back(gsl("bsimp", "GSL bsimp", "implicit"));
        m.push_back(gsl("msbdf", "GSL msbdf (BDF)", "implicit"));
        m.push_back(stepper("rkmk4", "RKMK4 (fixed h)", "Lie group", 4, [](const HeavyTop& top) {
            return rigid::IncrementStepper(
                [&top](const BodyState& s, double h) { return rigid::rkmk4_step(top, s, h); });
        }));
        m.push_back(stepper("strang", "Strang splitting (fixed h)", "splitting", 2, [](const HeavyTop& top) {
            return rigid::IncrementStepper(
                [&top](const BodyState& s, double h) { return rigid::strang_step(top, s, h); });
        }));
        m.push_back(stepper("yoshida4", "Strang + triple jump (fixed h)", "splitting", 6, [](const HeavyTop& top) {
            const rigid::IncrementStepper strang = [&top](const BodyState& s, double h) {
                return rigid::strang_step(top, s, h);
            };
            return rigid::IncrementStepper(
                [strang](const BodyState& s, double h) { return rigid::triple_jump(strang, s, h); });
        }));
        m.push_back(
            {"taylor16", "Taylor, degree 16 (fixed h)", "Taylor series", Kind::step,
             [](const Scenario& sc, const std::vector<double>& times, double h, std::vector<BodyState>& out) {
                 std::size_t i = 0;
                 return 16 * rigid::integrate_taylor<double>(
                                 sc.top, sc.s0, times,
                                 [&](double, const rigid::TaylorState<double>& s) { out[i++] = rigid::to_double(s); },
                                 h, 16);
             }});
        // rk8pd again, driven by our own loop with the time kept as an exact two-part sum. Last in
        // the list: the book's keys by_method[key=100 * scenario + index] keep their methods.
        m.push_back(gsl("rk8pd", "GSL rk8pd, compensated time", "explicit Runge-Kutta", true, "rk8pd_ct"));
        return m;
    }();
    return list;
}
// end snippet

const Method& method(const std::string& name) {
    for (const Method& m : methods())
        if (m.name == name) return m;
    throw std::invalid_argument("unknown method " + name);
}

Metrics measure(const Scenario& sc, const std::vector<BodyState>& ref, const std::vector<BodyState>& run) {
    Metrics m;
    const HeavyTop& top = sc.top;
    double scale = 0;
    for (const BodyState& r : ref) scale = std::max(scale, r.Omega.norm());
    const double H0 = rigid::heavy_top_energy(top, sc.s0);
    const double E_scale = 0.5 * sc.s0.Omega.dot(top.J * sc.s0.Omega) + top.f;
    const Vec3 L0 = sc.s0.R * top.J * sc.s0.Omega;
    const double L_scale = (top.J * sc.s0.Omega).norm();
    bool finite = true;
    for (std::size_t i = 0; i < run.size(); ++i) {
        const BodyState& s = run[i];
        finite = finite && s.Omega.allFinite() && s.R.allFinite();
        m.err_R = std::max(m.err_R, rigid::geodesic_angle(ref[i].R, s.R));
        m.err_Omega = std::max(m.err_Omega, (s.Omega - ref[i].Omega).norm() / scale);
        m.dH = std::max(m.dH, std::abs(rigid::heavy_top_energy(top, s) - H0) / E_scale);
        const Vec3 L = s.R * top.J * s.Omega;
        m.dL = std::max(m.dL, (top.f > 0 ? std::abs(top.k.dot(L - L0)) : (L - L0).norm()) / L_scale);
        m.orth = std::max(m.orth, rigid::orthogonality_defect(s.R));
    }
    m.error = std::max(m.err_R, m.err_Omega);
    if (!finite) m.error = nan_;  // std::max would drop a NaN
    return m;
}

namespace {

using LongState = rigid::TaylorState<long double>;

// The same measure as measure().error, in long double.
double difference(const LongState& a, const LongState& b, long double scale) {
    const long double angle = (a.R - b.R).norm() / std::sqrt(2.0L);  // the angle, for nearly equal rotations
    return static_cast<double>(std::max(angle, (a.Omega - b.Omega).norm() / scale));
}

}  // namespace

Reference reference(const Scenario& sc, bool self_check, bool conditioning) {
    Reference r;
    r.h = 0.1 / sc.omega;
    const std::vector<double> times = sc.times();
    const auto run_long = [&](double h) {
        std::vector<LongState> out;
        out.reserve(times.size());
        rigid::integrate_taylor<long double>(
            sc.top, sc.s0, times, [&](double, const LongState& s) { out.push_back(s); }, h, r.order);
        return out;
    };
    std::vector<LongState> L;
    r.time_s = kit::min_time([&] { L = run_long(r.h); }, 1);
    long double scale = 0;
    for (const LongState& s : L) scale = std::max(scale, s.Omega.norm());
    for (const LongState& s : L) r.states.push_back(rigid::to_double(s));
    if (self_check) {
        const std::vector<LongState> half = run_long(r.h / 2);
        r.self_difference = 0;
        for (std::size_t i = 0; i < L.size(); ++i)
            r.self_difference = std::max(r.self_difference, difference(L[i], half[i], scale));
    }
    if (sc.exact) r.exact_difference = measure(sc, r.states, sc.exact(times)).error;
    std::vector<LongState> D;
    rigid::integrate_taylor<double>(
        sc.top, sc.s0, times,
        [&](double, const rigid::TaylorState<double>& s) {
            D.push_back({s.Omega.cast<long double>(), s.R.cast<long double>()});
        },
        r.h, r.order);
    for (std::size_t i = 0; i < L.size(); ++i) r.double_floor = std::max(r.double_floor, difference(L[i], D[i], scale));
    if (!conditioning) return r;
    // The conditioning: the same reference from an initial state changed by delta = 1e-9 (Omega by
    // delta |Omega| along a fixed direction, R by a turn of delta), in long double.
    const double delta = 1e-9;
    BodyState changed = sc.s0;
    changed.Omega += delta * sc.s0.Omega.norm() * Vec3(0.48, -0.6, 0.64);
    changed.R = changed.R * Eigen::AngleAxisd(delta, Vec3(0.6, 0.8, 0)).toRotationMatrix();
    std::vector<LongState> C;
    rigid::integrate_taylor<long double>(
        sc.top, changed, times, [&](double, const LongState& s) { C.push_back(s); }, r.h, r.order);
    for (std::size_t i = 0; i < L.size(); ++i) r.kappa = std::max(r.kappa, difference(L[i], C[i], scale) / delta);
    r.expected_floor = std::numeric_limits<double>::epsilon() * r.kappa * std::sqrt(sc.T / r.h);
    return r;
}

Budget budget(const std::string& name) {
    if (name == "smoke") return {name, 1, 0.03, 0.06, 20000, 4.0, 100.0, false};
    if (name == "quick") return {name, 3, 0.1, 0.5, 200000, 2.0, 10.0, true};
    if (name == "full") return {name, 5, 5.0, 60.0, 4000000, std::sqrt(2.0), std::sqrt(10.0), true};
    throw std::invalid_argument("unknown budget " + name);
}

double seconds_per_evaluation(const std::string& method) {
    static const std::map<std::string, double> ns = {
        {"rk4", 98},    {"rkf45", 46},  {"rk8pd", 47},   {"msadams", 187},  {"rk4imp", 781},  {"bsimp", 350},
        {"msbdf", 351}, {"rkmk4", 125}, {"strang", 290}, {"yoshida4", 296}, {"taylor16", 63}, {"rk8pd_ct", 47}};
    const auto it = ns.find(method);
    if (it == ns.end()) throw std::invalid_argument("no cost of an evaluation is known for the method " + method);
    return it->second * 1e-9;
}

// snippet: sweep
std::vector<Point> sweep(const Scenario& sc, const Method& meth, const Reference& ref, const Budget& b,
                         const std::function<void(const std::string&)>& progress) {
    std::vector<Point> points;
    const std::vector<double> times = sc.times();
    std::vector<BodyState> out(times.size());
    // Tolerances from 1e-3 to 1e-14; steps from h omega = 0.5 (1.5 for the degree-16 Taylor
    // method) down to the step budget. Each next one tighter by the budget's factors.
    double param = meth.kind == Kind::tolerance ? 1e-3 : (meth.name == "taylor16" ? 1.5 : 0.5) / sc.omega;
    // Stops on the floor: two points in a row below 1e-9 and no better than the best so far by 2x
    // (higher up, a flat stretch is not the floor: at loose tolerances rk8pd takes the same
    // steps whatever the tolerance, one or two per output interval).
    double best_error = std::numeric_limits<double>::infinity();
    int stalled = 0, failures = 0;
    double spent = 0;  // the costs of the runs so far (not their times: the load must not matter)
    const double cost = seconds_per_evaluation(meth.name);
    for (;; param /= meth.kind == Kind::tolerance ? b.tol_factor : b.step_factor) {
        if (meth.kind == Kind::tolerance && param < 0.99e-14) break;
        if (meth.kind == Kind::step && sc.T / param > static_cast<double>(b.max_steps)) break;
        std::ostringstream what;
        what << sc.name << "  " << meth.name << (meth.kind == Kind::tolerance ? "  tol " : "  h ") << param;
        progress(what.str());
        Point p;
        p.scenario = sc.name, p.method = meth.name, p.param = param;
        try {
            long evaluations = 0;
            p.time_s = kit::min_time([&] { evaluations = meth.run(sc, times, param, out); }, 1);
            const double first = cost * static_cast<double>(evaluations);  // its cost, not its time
            p.repeats = 1;
            // More repetitions for short runs, whose minimum is the most easily disturbed.
            const int repeats = first < 5e-3 && b.repeats > 1 ? std::max(b.repeats, 10) : b.repeats;
            if (first < b.max_run_s && repeats > 1) {
                p.time_s = std::min(p.time_s,
                                    kit::min_time([&] { evaluations = meth.run(sc, times, param, out); }, repeats - 1));
                p.repeats = repeats;
            }
            p.evaluations = evaluations;
            spent += first * p.repeats;
            p.m = measure(sc, ref.states, out);
            if (!std::isfinite(p.m.error)) throw std::runtime_error("the solution is not finite");
            points.push_back(p);
            failures = 0;
            if (p.m.error < best_error / 2 || p.m.error > 1e-9) {
                best_error = std::min(best_error, p.m.error);
                stalled = 0;
            } else if (++stalled >= 2) {
                break;
            }
            if (first > b.max_run_s || spent > b.max_sweep_s) break;
        } catch (const std::runtime_error& e) {
            p.failed = true;
            p.why = e.what();
            points.push_back(p);
            if (++failures >= 2) break;
        }
    }
    return points;
}
// end snippet

double time_to_reach(const std::vector<Point>& points, double target) {
    std::vector<const Point*> ok;
    for (const Point& p : points)
        if (!p.failed) ok.push_back(&p);
    std::sort(ok.begin(), ok.end(), [](const Point* a, const Point* b) { return a->time_s < b->time_s; });
    double env_err = std::numeric_limits<double>::infinity(), env_time = 0;
    for (const Point* p : ok) {
        if (p->m.error >= env_err) continue;  // not on the lower envelope
        if (p->m.error <= target) {
            if (!std::isfinite(env_err)) return p->time_s;  // the cheapest run is already good enough
            const double s = std::log(env_err / target) / std::log(env_err / p->m.error);
            return env_time * std::pow(p->time_s / env_time, s);
        }
        env_err = p->m.error;
        env_time = p->time_s;
    }
    return nan_;
}

namespace {

// snippet: plain_rhs
// The same equations as a hand-written loop on std::array: the yardstick of the fast form.
struct PlainTop {
    std::array<double, 9> J, J_inv;  // row by row
    std::array<double, 3> fk, z0;    // f k and z(0)
};

__attribute__((noinline)) void plain_rhs(const PlainTop& p, const std::array<double, 12>& y,
                                         std::array<double, 12>& d) {
    const double* W = &y[0];
    const double* R = &y[3];  // R_ij = R[3 i + j]
    double L[3], u[3], g[3];
    for (int i = 0; i < 3; ++i) L[i] = p.J[3 * i] * W[0] + p.J[3 * i + 1] * W[1] + p.J[3 * i + 2] * W[2];
    for (int j = 0; j < 3; ++j) u[j] = R[j] * p.fk[0] + R[3 + j] * p.fk[1] + R[6 + j] * p.fk[2];  // f R^T k
    g[0] = L[1] * W[2] - L[2] * W[1] + u[1] * p.z0[2] - u[2] * p.z0[1];
    g[1] = L[2] * W[0] - L[0] * W[2] + u[2] * p.z0[0] - u[0] * p.z0[2];
    g[2] = L[0] * W[1] - L[1] * W[0] + u[0] * p.z0[1] - u[1] * p.z0[0];
    for (int i = 0; i < 3; ++i) d[i] = p.J_inv[3 * i] * g[0] + p.J_inv[3 * i + 1] * g[1] + p.J_inv[3 * i + 2] * g[2];
    for (int i = 0; i < 3; ++i) {  // row i of R hat(Omega) = (row i of R) x Omega
        const double* r = R + 3 * i;
        d[3 + 3 * i] = r[1] * W[2] - r[2] * W[1];
        d[4 + 3 * i] = r[2] * W[0] - r[0] * W[2];
        d[5 + 3 * i] = r[0] * W[1] - r[1] * W[0];
    }
}
// end snippet

}  // namespace

RhsCost rhs_cost(const HeavyTop& top, const BodyState& s) {
    constexpr long n = 400000;
    const VecX y = rigid::pack(s);
    RhsCost c{};
    // The teaching form (your euler_poisson_rhs through OdeRhs) and the fast form, each through
    // the callback integrate_gsl hands GSL: the smallest of five batches.
    const rigid::OdeRhs teaching = rhs_of(top);
    const rigid::OdeRhsInPlace fast = rigid::EulerPoissonInPlace(top);
    VecX d_teaching, d_fast;
    c.teaching_ns = 1e9 * kit::min_time([&] { rigid::time_gsl_calls(teaching, y, n, &d_teaching); }) / n;
    c.fast_ns = 1e9 * kit::min_time([&] { rigid::time_gsl_calls(fast, y, n, &d_fast); }) / n;
    // The plain loop, called directly.
    PlainTop p{};
    const Mat3 J_inv = top.J.inverse();
    for (int i = 0; i < 9; ++i) p.J[i] = top.J(i / 3, i % 3), p.J_inv[i] = J_inv(i / 3, i % 3);
    for (int i = 0; i < 3; ++i) p.fk[i] = top.f * top.k(i), p.z0[i] = top.z0(i);
    std::array<double, 12> ya{}, da{};
    for (int i = 0; i < 12; ++i) ya[i] = y(i);
    c.plain_ns = 1e9 * kit::min_time([&] {
                     for (long i = 0; i < n; ++i) {
                         plain_rhs(p, ya, da);
                         ya[0] += 1e-300 * da[0];
                     }
                 }) /
                 n;
    // Agreement, on 1000 random states: the largest difference of the three results, relative
    // to the size of dy/dt.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> U(-1, 1);
    for (int k = 0; k < 1000; ++k) {
        const Vec3 W = sc_scale(s) * Vec3(U(rng), U(rng), U(rng));
        const Mat3 R = Eigen::AngleAxisd(3 * U(rng), Vec3(U(rng), U(rng), U(rng)).normalized()).toRotationMatrix();
        const VecX yk = rigid::pack({W, R});
        const VecX a = teaching(0, yk);
        VecX b(12);
        fast(0, yk.data(), b.data());
        for (int i = 0; i < 12; ++i) ya[i] = yk(i);
        plain_rhs(p, ya, da);
        const double scale = a.cwiseAbs().maxCoeff();
        c.fast_vs_teaching = std::max(c.fast_vs_teaching, (b - a).cwiseAbs().maxCoeff() / scale);
        for (int i = 0; i < 12; ++i) c.fast_vs_plain = std::max(c.fast_vs_plain, std::abs(b(i) - da[i]) / scale);
    }
    return c;
}

const Point* best(const std::vector<Point>& points) {
    const Point* b = nullptr;
    for (const Point& p : points)
        if (!p.failed && (!b || p.m.error < b->m.error)) b = &p;
    return b;
}

}  // namespace bench
