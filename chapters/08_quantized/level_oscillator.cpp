// Chapter 8 scene: the oscillator (6.1) with the friction k(E) = kappa |sin(pi E / E0)|^p, which
// vanishes on the levels E_n = n E0. Motions started between two levels settle onto the lower
// one; a motion started on a level stays there. Checked against the exact harmonic motion (on a
// level), the energy balance E + W = E(0) (W, the work of friction, integrated alongside) and
// the averaged energy equation dE/dt = -k(E) E / m.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "figure.hpp"
#include "level_oscillator.gp.hpp"
#include "quantized_scene.hpp"
#include "rigid/ode.hpp"
#include "rigid/quantized.hpp"
#include "scene.hpp"

using rigid::VecX;

namespace {

// A number as printf writes it, with %g unless told (the figures' titles and keys).
std::string gnum(double x, const char* format = "%g") {
    char s[32];
    std::snprintf(s, sizeof s, format, x);
    return s;
}

// The scene's own parameters, bound to its options (the oscillator's are scene8's).
struct Params {
    scene8::OscillatorParams osc;
    double T = 200;
    long outputs = 800, repeats = 3, periods = 50;
};

void declare(kit::Options& opts, Params& p) {
    scene8::oscillator_options(opts, p.osc);
    opts.real("T", &p.T, "time span", kit::between(1e-2, 1e6))
        .integer("outputs", &p.outputs, "output times", 10, 100000)
        .integer("repeats", &p.repeats, "timing repetitions (the minimum is kept)", 1, 50)
        .integer("periods", &p.periods, "periods on the level over which the period is measured (400 outputs each)", 3,
                 1000);
}

struct Setup {
    rigid::Oscillator osc;
    rigid::LevelFriction k;
    double T, w;  // w = omega / sqrt(m), the natural frequency
    int repeats, periods;
    std::vector<double> times;
};

Setup setup(const kit::Options& o, const Params& p) {
    Setup u{scene8::oscillator_from(p.osc),
            scene8::friction_from(p.osc),
            p.T,
            0,
            static_cast<int>(p.repeats),
            static_cast<int>(p.periods),
            rigid::linspace(0, p.T, static_cast<int>(p.outputs))};
    u.w = u.osc.omega / std::sqrt(u.osc.m);
    // The work: the motion on a level and six between levels (`repeats` timed runs each), six
    // averaged ones, over T; and `periods` periods for the period. The phase turned sets the steps.
    kit::require_budget(o, {(7.0 * u.repeats + 6) * u.T * u.w + u.periods * 2 * std::numbers::pi,
                            scene8::seconds_per_radian, "radians of phase", "--T, --omega, --m, --repeats, --periods"});
    kit::require_budget(
        o, {(7.0 * u.repeats + 6) * double(u.times.size()), 4e-6, "output times (all runs)", "--outputs, --repeats"});
    return u;
}

// 1. A motion on a level, against the exact harmonic motion; then its period.
void report_on_level(kit::Report& report, const Setup& u) {
    const rigid::Oscillator& osc = u.osc;
    const rigid::LevelFriction& k = u.k;
    const double E0 = u.k.E0, w = u.w;
    const int repeats = u.repeats;
    const auto& times = u.times;
    const rigid::OdeSettings tight{.method = "rk8pd", .rel_tol = 1e-12, .abs_tol = 1e-12};
    // On a level, (6.1) is m q'' + omega^2 q = 0: exact reference q0 cos(w t), w = omega / sqrt(m).
    const double E_on = 2 * E0;
    const VecX y_on = scene8::at_energy(osc, E_on);
    const rigid::OdeRhs f = rigid::oscillator_equations(osc, k);
    scene8::Run on;
    const double on_time = kit::min_time([&] { on = scene8::integrate(f, y_on, times, "rk8pd", 1e-12); }, repeats);
    double on_err = 0, on_drift = 0, naive_err = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
        const double t = times[i], q0 = y_on(0);
        on_err = std::max({on_err, std::abs(on.y[i](0) - q0 * std::cos(w * t)) / q0,
                           std::abs(on.y[i](1) + q0 * w * std::sin(w * t)) / (q0 * w)});
        naive_err = std::max(naive_err, std::abs(on.y[i](0) - q0 * std::cos(osc.omega * t)) / q0);
        on_drift = std::max(on_drift, std::abs(rigid::oscillator_energy(osc, on.y[i](0), on.y[i](1)) - E_on) / E_on);
    }
    report.headline(
        "a motion started on the level E = 2 E0, rk8pd at tol 1e-12, against the exact harmonic "
        "motion q0 cos(omega t / sqrt(m)): max relative error of q and q'",
        on_err, on_time);
    report.add("on_level_energy_drift", on_drift, "max |E(t) - 2 E0| / (2 E0) on the level");
    report.add("error_if_frequency_were_omega", naive_err, "the same motion against q0 cos(omega t)");

    // The period, from the zero crossings of q on a fine grid over u.periods periods, 400 points
    // each (linear interpolation).
    const auto fine = rigid::linspace(0, u.periods * 2 * std::numbers::pi / w, 400 * u.periods);
    std::vector<double> crossings;
    double tp = 0, qp = y_on(0);
    rigid::integrate_gsl(
        f, y_on, fine,
        [&](double t, const VecX& y) {
            if (t > 0 && (qp < 0) != (y(0) < 0)) crossings.push_back(tp + (t - tp) * qp / (qp - y(0)));
            tp = t, qp = y(0);
        },
        tight);
    if (crossings.size() < 3) throw kit::NumericalFailure("too few zero crossings to measure the period");
    const double period = 2 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
    report.add("period_measured", period, "from the zero crossings of q on the level");
    report.add("period_predicted", 2 * std::numbers::pi * std::sqrt(osc.m) / osc.omega, "2 pi sqrt(m) / omega");
    report.add("period_if_frequency_were_omega", 2 * std::numbers::pi / osc.omega);
    report.add("period_mismatch", std::abs(period * osc.omega / (2 * std::numbers::pi * std::sqrt(osc.m)) - 1),
               "relative, measured against 2 pi sqrt(m) / omega");
}

// 2. Motions started between the levels, with the work of friction alongside.
struct Settling {
    std::vector<double> starts{0.45, 1.3, 1.9, 2.5, 3.2, 3.9};
    std::vector<std::vector<double>> rows;  // E(0)/E0, level/E0, E(T)/E0, d(T), d_avg(T), ratio, min(E - level)
    std::vector<std::vector<std::vector<double>>> curves, averaged, approach, asymptote;
    double balance = 0, settle_time = 0;
};

Settling settle(const Setup& u) {
    const rigid::Oscillator& osc = u.osc;
    const rigid::LevelFriction& k = u.k;
    const double E0 = u.k.E0;
    const int repeats = u.repeats;
    const auto& times = u.times;
    Settling S;
    const auto& starts = S.starts;
    auto& rows = S.rows;
    auto &curves = S.curves, &averaged = S.averaged, &approach = S.approach, &asymptote = S.asymptote;
    auto &balance = S.balance, &settle_time = S.settle_time;
    for (double s : starts) {
        const double E_start = s * E0, level = rigid::level_below(k, E_start);
        const VecX y0{{scene8::at_energy(osc, E_start)(0), 0.0, 0.0}};
        scene8::Run run;
        settle_time += kit::min_time(
            [&] { run = scene8::integrate(scene8::with_work(osc, k), y0, times, "rk8pd", 1e-12); }, repeats);
        const scene8::Run avg =
            scene8::integrate(scene8::averaged_energy(osc, k), VecX{{E_start}}, times, "rk8pd", 1e-12);
        std::vector<std::vector<double>> c, a, d, as;
        double min_above = 1e300;
        const double rate = scene8::level_rate(osc, k, level);
        for (std::size_t i = 0; i < times.size(); ++i) {
            const double E = rigid::oscillator_energy(osc, run.y[i](0), run.y[i](1));
            if (!std::isfinite(E))
                throw kit::NumericalFailure("the energy is not finite at t = " + std::to_string(times[i]));
            balance = std::max(balance, std::abs(E + run.y[i](2) - E_start) / E_start);
            min_above = std::min(min_above, E - level);
            c.push_back({times[i], E / E0});
            a.push_back({times[i], avg.y[i](0) / E0});
            if (times[i] >= 1) {
                d.push_back({times[i], std::max(E - level, 1e-300) / E0});
                // The asymptote of the averaged equation: (p - 1) c t for p > 1 (E_n > 0), or,
                // on the ground level, E^-p = p kappa (pi/E0)^p t / m.
                const double x =
                    level > 0
                        ? std::pow((k.power - 1) * rate * times[i], -1 / (k.power - 1))
                        : std::pow(k.power * k.kappa * std::pow(std::numbers::pi / E0, k.power) * times[i] / osc.m,
                                   -1 / k.power);
                if (k.power > 1 || level == 0) as.push_back({times[i], x / E0});
            }
        }
        const double ET = rigid::oscillator_energy(osc, run.y.back()(0), run.y.back()(1));
        const double dT = ET - level, dA = avg.y.back()(0) - level;
        rows.push_back({s, level / E0, ET / E0, dT, dA, dT / dA, min_above});
        curves.push_back(c), averaged.push_back(a), approach.push_back(d), asymptote.push_back(as);
    }
    return S;
}

void report_settling(kit::Report& report, const Setup& u, const Settling& S) {
    report.add("energy_balance", S.balance, "max |E(t) + W(t) - E(0)| / E(0) over the six motions");
    report.add("settling_run_time_s", S.settle_time, "the six motions with W, rk8pd at 1e-12");
    const double T = u.T, w = u.w;
    const auto& rows = S.rows;
    report.add("T", T);
    report.add("natural_frequency", w, "omega / sqrt(m)");
    report.table("settling",
                 {"E_start_over_E0", "level_over_E0", "E_T_over_E0", "above_level_T", "averaged_above_level_T", "ratio",
                  "min_above_level"},
                 rows);
    double worst_ratio = 0, lowest = 1e300;
    for (const auto& r : rows) {
        if (r[1] > 0) worst_ratio = std::max(worst_ratio, std::abs(r[5] - 1));
        lowest = std::min(lowest, r[6]);
    }
    report.add("averaged_mismatch_at_T", worst_ratio,
               "max |(E(T) - E_n) / (averaged E(T) - E_n) - 1| over the motions that settle on E_n > 0");
    report.add("min_above_level", lowest, "min over t of E(t) - level: never below the level it settles onto");
    if (lowest < 0) report.note("a motion went below the level it should settle onto");
}

void draw_settling(kit::Scene& scene, const Setup& u, const Settling& S) {
    const rigid::LevelFriction& k = u.k;
    const double T = u.T;
    const auto& starts = S.starts;
    const int levels = static_cast<int>(std::ceil(starts.back()));
    const auto &curves = S.curves, &averaged = S.averaged;
    kit::Figure fig(scene, "level_settling.svg", 820, 520);
    if (fig.enabled()) {
        std::vector<kit::Fill> plot, averaged_curves(starts.size() - 1);  // the first averaged curve: in the script
        for (std::size_t j = 0; j < starts.size(); ++j)
            plot.push_back({{"ls", std::to_string(j + 1)}, {"start", gnum(starts[j], "%.2g")}});
        fig.script(kit::gp::settling, {{"kappa", gnum(k.kappa)},
                                       {"power", gnum(k.power)},
                                       {"tmax", std::to_string(std::min(T, 40.0))},
                                       {"Emax", std::to_string(levels + 0.2)},
                                       {"levels", std::to_string(levels)},
                                       {"curves", kit::joined(kit::gp::start, plot)},
                                       {"averaged", kit::joined(kit::gp::averaged, averaged_curves, "")}});
        for (const auto& c : curves) fig.data(c);
        for (const auto& a : averaged) fig.data(a);
        fig.finish();
    }
}

void draw_approach(kit::Scene& scene, const Setup& u, const Settling& S) {
    const double T = u.T;
    const auto& starts = S.starts;
    const auto& rows = S.rows;
    const auto &approach = S.approach, &asymptote = S.asymptote;
    kit::Figure fa(scene, "level_approach.svg", 820, 520);
    if (fa.enabled()) {
        std::vector<kit::Fill> curves, asymptotes;
        for (std::size_t j = 0; j < starts.size(); ++j) {
            curves.push_back(
                {{"ls", std::to_string(j + 1)}, {"start", gnum(starts[j], "%.2g")}, {"level", gnum(rows[j][1])}});
            if (!asymptote[j].empty()) asymptotes.push_back({{"ls", std::to_string(j + 1)}});
        }
        fa.script(kit::gp::approach, {{"T", std::to_string(T)},
                                      {"curves", kit::joined(kit::gp::approach_start, curves)},
                                      {"asymptotes", kit::joined(kit::gp::asymptote, asymptotes, "")}});
        for (const auto& d : approach) fa.data(d);
        for (const auto& as : asymptote)
            if (!as.empty()) fa.data(as);
        fa.finish();
    }
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("level_oscillator", "Chapter 8: the oscillator (6.1) settling onto discrete energy levels");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&p](const kit::Options& o, kit::Scene& scene) {
        const Setup u = setup(o, p);
        report_on_level(scene.report, u);
        const Settling settling = settle(u);
        report_settling(scene.report, u, settling);
        draw_settling(scene, u, settling);
        draw_approach(scene, u, settling);
    });
}
