// Chapter 8 scene: leaving the levels of (6.1). [P, Sect. 7] says the oscillator stays on a level
// for ever when undisturbed and drops to a lower level "under the action of even infinitesimal
// disturbances". Shown two ways: (a) seeded random kicks to q' every tau, starting on a level
// (energy against time: a staircase down, in portions of E0); (b) a single disturbance delta
// below the level E_n and the time the motion takes to fall half-way to E_(n-1), for the
// smooth friction (p = 2) and the kinked one (p = 1), against the averaged energy equation.
// Checked by the energy balance E + W - (the energy the kicks put in) = E(0), with W the work
// of friction integrated alongside.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "figure.hpp"
#include "level_transitions.gp.hpp"
#include "quantized_scene.hpp"
#include "rigid/ode.hpp"
#include "rigid/quantized.hpp"
#include "scene.hpp"

using rigid::VecX;

namespace {

// A number as printf's %g writes it (the figures' titles and keys).
std::string gnum(double x) {
    char s[32];
    std::snprintf(s, sizeof s, "%g", x);
    return s;
}

// The time at which E(t) first falls below `below`, by linear interpolation on the output grid
// (NaN when it never does before times.back()), integrated by rk8pd at the tolerance `tol`.
double first_time_below(const rigid::Oscillator& osc, const rigid::LevelFriction& k, double E_start,
                        const std::vector<double>& times, double below, double tol = 1e-13) {
    const VecX y0{{scene8::at_energy(osc, E_start)(0), 0.0}};
    double found = NAN, tp = 0, Ep = E_start;
    rigid::integrate_gsl(rigid::oscillator_equations(osc, k), y0, times,
                         [&](double t, const VecX& y) {
                             const double E = rigid::oscillator_energy(osc, y(0), y(1));
                             if (std::isnan(found) && E < below) found = tp + (t - tp) * (Ep - below) / (Ep - E);
                             tp = t, Ep = E;
                         },
                         {.method = "rk8pd", .rel_tol = tol, .abs_tol = tol});
    return found;
}

// The scene's own parameters, bound to its options (the oscillator's are scene8's).
struct Params {
    scene8::OscillatorParams osc;
    long start_level = 4, seeds = 3, repeats = 1;
    double epsilon = 3e-3, tau = 1.0, T = 600;
};

void declare(kit::Options& opts, Params& p) {
    scene8::oscillator_options(opts, p.osc);
    opts.integer("start_level", &p.start_level, "the level n the kicked motions start on, E = n E0", 1, 50)
        .real("epsilon", &p.epsilon, "the size of a kick: q' += epsilon * (a normal random number)",
              kit::between(1e-9, 1))
        .real("tau", &p.tau, "the time between kicks", kit::between(1e-2, 1e3))
        .real("T", &p.T, "time span of the kicked motions", kit::between(1e-2, 1e6))
        .integer("seeds", &p.seeds, "kicked motions (seeds 1, 2, ...)", 1, 20)
        .integer("repeats", &p.repeats, "timing repetitions (the minimum is kept)", 1, 50);
}

struct Setup {
    rigid::Oscillator osc;
    rigid::LevelFriction k;
    double eps, tau, T;
    int n_start, seeds;
    double E_start, E_n;  // the start of the kicked motions; the level of part (b), n = 2
};

Setup setup(const kit::Options& o, const Params& prm) {
    const rigid::Oscillator osc = scene8::oscillator_from(prm.osc);
    const rigid::LevelFriction k = scene8::friction_from(prm.osc);
    const double E0 = k.E0, tau = prm.tau, T = prm.T;
    const int n_start = static_cast<int>(prm.start_level), seeds = static_cast<int>(prm.seeds);
    if (tau > T)
        throw kit::BadInput("--tau must be at most --T (got " + std::to_string(tau) + " > " + std::to_string(T) + ")");
    // The work: seeds + 1 motions over T (`repeats` timed runs), restarted at every kick.
    const double w = osc.omega / std::sqrt(osc.m);
    kit::require_budget(o, {double(prm.repeats) * (seeds + 1) * (T * w + 20 * T / tau), scene8::seconds_per_radian,
                            "radians of phase (and restarts)", "--T, --tau, --seeds, --omega, --m"});
    // Part (b) follows a motion from delta below a level until it has left it, for delta down
    // to 1e-5 E0 (1e-10 E0 for p = 1): the averaged equation predicts how long that takes,
    // about delta^(1 - p) / ((p - 1) c), which grows without bound with the power p.
    double escape_span = 0;
    for (double p : {k.power, 1.0}) {
        rigid::LevelFriction kp = k;
        kp.power = p;
        for (int e = 1; e <= (p == 1 ? 10 : 5); ++e)
            escape_span += 1.5 * scene8::averaged_escape_time(osc, kp, 2 * E0, std::pow(10.0, -e) * E0) + 30;
    }
    kit::require_budget(o, {escape_span * w + 400 * w, scene8::seconds_per_radian,
                            "radians of phase (the escapes of part (b))", "--power, --kappa, --E0, --omega, --m"});
    return {osc, k, prm.epsilon, tau, T, n_start, seeds, n_start * E0, 2 * E0};
}

// (a) Kicked motions, and one left alone.
struct Trace {
    std::vector<std::vector<double>> curve;  // t, E / E0
    double balance = 0;
    std::vector<double> leave;  // first time below (n - 1/2) E0, n = n_start, ..., 1
};
struct Kicked {
    std::vector<Trace> traces;  // seed 0: left alone
    double time_s;
};

Kicked kicked_motions(const Setup& u) {
    const rigid::Oscillator& osc = u.osc;
    const rigid::LevelFriction& k = u.k;
    const double E0 = u.k.E0;
    const double eps = u.eps, tau = u.tau, T = u.T, E_start = u.E_start;
    const int n_start = u.n_start, seeds = u.seeds;
    const rigid::OdeRhs g = scene8::with_work(osc, k);
    const int per_kick = std::max(2, static_cast<int>(std::ceil(tau / 0.5)));  // outputs between kicks
    std::vector<Trace> traces(seeds + 1);
    const double kicked_time = kit::min_time([&] {
        for (int s = 0; s <= seeds; ++s) {
            Trace tr;
            scene8::Normal normal(static_cast<std::uint64_t>(s));
            VecX y{{scene8::at_energy(osc, E_start)(0), 0.0, 0.0}};
            double t = 0, kicked_in = 0;
            tr.curve.push_back({0, E_start / E0});
            int next = n_start;
            while (t < T - 1e-12) {
                const double t1 = std::min(T, t + tau);
                rigid::integrate_gsl(g, y, rigid::linspace(t, t1, per_kick),
                                     [&](double tt, const VecX& z) {
                                         if (tt == t) return;
                                         const double E = rigid::oscillator_energy(osc, z(0), z(1));
                                         tr.curve.push_back({tt, E / E0});
                                         tr.balance =
                                             std::max(tr.balance, std::abs(E + z(2) - kicked_in - E_start) / E_start);
                                         while (next >= 1 && E < (next - 0.5) * E0) tr.leave.push_back(tt), --next;
                                         y = z;
                                     },
                                     {.method = "rk8pd", .rel_tol = 1e-12, .abs_tol = 1e-12});
                t = t1;
                if (s > 0 && t < T) {  // seed 0: left alone
                    const double before = rigid::oscillator_energy(osc, y(0), y(1));
                    y(1) += eps * normal();
                    kicked_in += rigid::oscillator_energy(osc, y(0), y(1)) - before;
                }
            }
            traces[s] = tr;
        }
    });
    return {traces, kicked_time};
}

void report_kicked(kit::Report& report, const Setup& u, const Kicked& kd) {
    const auto& traces = kd.traces;
    const int n_start = u.n_start, seeds = u.seeds;
    double balance = 0;
    for (const auto& tr : traces) balance = std::max(balance, tr.balance);
    report.headline(
        "max |E + W - (energy put in by the kicks) - E(0)| / E(0) over the kicked and the "
        "undisturbed motions, rk8pd at tol 1e-12",
        balance, kd.time_s);
    std::vector<std::vector<double>> leave_rows;
    for (int s = 0; s <= seeds; ++s)
        for (std::size_t j = 0; j < traces[s].leave.size(); ++j)
            leave_rows.push_back({double(s), double(n_start - int(j)), traces[s].leave[j]});
    report.table("drops", {"seed(0=undisturbed)", "level_left", "time_below_half_way"}, leave_rows);
    double undisturbed_change = 0;
    for (const auto& p : traces[0].curve) undisturbed_change = std::max(undisturbed_change, std::abs(p[1] - n_start));
    report.add("undisturbed_max_change", undisturbed_change, "max |E(t) / E0 - n| of the motion left alone");
    // The plateaus: how close to n E0 the energy sits half-way between two drops.
    double worst_plateau = 0;
    long plateaus = 0;
    for (int s = 1; s <= seeds; ++s) {
        const auto& tr = traces[s];
        for (std::size_t j = 0; j + 1 < tr.leave.size(); ++j) {
            const double mid = 0.5 * (tr.leave[j] + tr.leave[j + 1]);
            const auto it = std::lower_bound(tr.curve.begin(), tr.curve.end(), mid,
                                             [](const std::vector<double>& p, double x) { return p[0] < x; });
            if (it == tr.curve.end()) continue;
            const double n = n_start - 1 - double(j);
            worst_plateau = std::max(worst_plateau, std::abs((*it)[1] - n));
            ++plateaus;
        }
    }
    report.add("plateaus", plateaus, "plateaus between two drops, over the kicked motions");
    report.add("plateau_offset", worst_plateau, "max |E / E0 - n| half-way through a plateau");
}

// (b) One disturbance delta below E_n, n = 2: the time to fall below E_n - E0 / 2.
struct Escapes {
    std::vector<double> powers;
    std::vector<std::vector<double>> rows;  // power, delta / E0, measured, averaged prediction
};

Escapes escapes(const Setup& u) {
    const rigid::Oscillator& osc = u.osc;
    const rigid::LevelFriction& k = u.k;
    const double E0 = u.k.E0;
    const double E_n = u.E_n;
    std::vector<std::vector<double>> escape;  // power, delta / E0, measured, averaged prediction
    std::vector<double> powers{k.power};
    if (k.power != 1) powers.push_back(1.0);
    for (double p : powers) {
        rigid::LevelFriction kp = k;
        kp.power = p;
        for (int e = 1; e <= (p == 1 ? 10 : 5); ++e) {
            const double delta = std::pow(10.0, -e) * E0;
            const double predicted = scene8::averaged_escape_time(osc, kp, E_n, delta);
            const auto times =
                rigid::linspace(0, 1.5 * predicted + 30, static_cast<int>(std::ceil((1.5 * predicted + 30) / 0.05)));
            const double measured = first_time_below(osc, kp, E_n - delta, times, E_n - E0 / 2);
            if (std::isnan(measured))
                throw kit::NumericalFailure("the motion did not leave the level in the time allowed");
            escape.push_back({p, delta / E0, measured, predicted});
        }
    }
    return {powers, escape};
}

void report_escapes(kit::Report& report, const Setup& u, const Escapes& es) {
    const rigid::Oscillator& osc = u.osc;
    const rigid::LevelFriction& k = u.k;
    const double E0 = u.k.E0;
    const double E_n = u.E_n;
    const auto& escape = es.rows;
    const auto& powers = es.powers;
    double worst_escape = 0;
    for (const auto& r : escape) worst_escape = std::max(worst_escape, std::abs(r[2] / r[3] - 1));
    report.table("escape", {"power", "delta_over_E0", "time_measured", "time_averaged"}, escape);
    report.add("escape_mismatch", worst_escape, "max |measured / averaged - 1| of the escape times");
    // The laws near the level, from the averaged equation: t ~ delta^(1-p) / ((p - 1) c) for p > 1
    // (1 / (c delta) for p = 2), t ~ ln(1 / delta) / c for p = 1. Measured against them.
    for (double p : powers) {
        rigid::LevelFriction kp = k;
        kp.power = p;
        const double c = scene8::level_rate(osc, kp, E_n);
        std::vector<double> x, y;  // ln(1 / delta), t
        double last_delta = 0, last_t = 0;
        for (const auto& r : escape)
            if (r[0] == p)
                x.push_back(std::log(E0 / (r[1] * E0))), y.push_back(r[2]), last_delta = r[1] * E0, last_t = r[2];
        if (p > 1) {
            report.add("smooth_escape_law", last_t * (p - 1) * c * std::pow(last_delta, p - 1),
                       "p > 1: measured time x (p-1) c delta^(p-1) at the smallest delta (the law: 1)");
        } else {
            const double n = double(x.size());
            double sx = 0, sy = 0, sxx = 0, sxy = 0;
            for (std::size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
            report.add("kinked_escape_law", c * (n * sxy - sx * sy) / (n * sxx - sx * sx),
                       "p = 1: c x d(time)/d ln(1/delta), least squares (the law: 1)");
        }
    }
}

// (c) p = 1 with no disturbance but the computation's own errors: started on E = 2 E0 (to
// the rounding of q0), integrated at several tolerances. If the time to leave moves with
// the tolerance, the integration error, not the rounding of the start, ends the level.
void report_undisturbed_exit(kit::Report& report, const Setup& u) {
    const rigid::Oscillator& osc = u.osc;
    const rigid::LevelFriction& k = u.k;
    const double E0 = u.k.E0;
    const double E_n = u.E_n;
    rigid::LevelFriction k1 = k;
    k1.power = 1;
    std::vector<std::vector<double>> left_rows;
    double earliest = INFINITY, latest = -INFINITY;
    for (double tol : {1e-10, 1e-11, 1e-12, 1e-13, 1e-14}) {
        const double left = first_time_below(osc, k1, E_n, rigid::linspace(0, 400, 8000), E_n - E0 / 2, tol);
        left_rows.push_back({tol, left});
        if (std::isfinite(left)) earliest = std::min(earliest, left), latest = std::max(latest, left);
    }
    report.table("undisturbed_exit", {"tol", "time_below_1_5_E0"}, left_rows);
    report.add("kinked_left_undisturbed_at", left_rows[3][1],
               "p = 1, started on E = 2 E0, no disturbance, rk8pd at 1e-13: time below 1.5 E0 (null: never, t <= 400)");
    report.add("kinked_left_undisturbed_earliest", earliest, "the same, earliest over tolerances 1e-10 ... 1e-14");
    report.add("kinked_left_undisturbed_latest", latest, "the same, latest over tolerances 1e-10 ... 1e-14");
}

void draw_kicks(kit::Scene& scene, const Setup& u, const Kicked& kd) {
    const double eps = u.eps, tau = u.tau;
    const int n_start = u.n_start, seeds = u.seeds;
    const auto& traces = kd.traces;
    kit::Figure fig(scene, "level_transitions.svg", 820, 520);
    if (fig.enabled()) {
        std::vector<kit::Fill> seed_curves;
        for (int s = 1; s <= seeds; ++s) seed_curves.push_back({{"seed", std::to_string(s)}});
        fig.script(kit::gp::kicks, {{"eps", gnum(eps)},
                                    {"tau", gnum(tau)},
                                    {"n_start", std::to_string(n_start)},
                                    {"Emax", std::to_string(n_start + 0.4)},
                                    {"seeds", kit::joined(kit::gp::seed, seed_curves, "")}});
        for (int s = 0; s <= seeds; ++s) fig.data(traces[s].curve);
        fig.finish();
    }
}

void draw_escapes(kit::Scene& scene, const Escapes& es) {
    const auto& escape = es.rows;
    const auto& powers = es.powers;
    kit::Figure fe(scene, "level_escape.svg", 820, 520);
    if (fe.enabled()) {
        std::vector<kit::Fill> pairs;
        for (std::size_t j = 0; j < powers.size(); ++j)
            pairs.push_back({{"ls", std::to_string(j + 1)}, {"p", gnum(powers[j])}});
        fe.script(kit::gp::escape, {{"curves", kit::joined(kit::gp::power, pairs)}});
        for (double p : powers) {
            std::vector<std::vector<double>> pts, line;
            for (const auto& r : escape)
                if (r[0] == p) pts.push_back({r[1], r[2]}), line.push_back({r[1], r[3]});
            fe.data(pts).data(line);
        }
        fe.finish();
    }
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("level_transitions", "Chapter 8: the oscillator (6.1) dropping to lower levels when disturbed");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&p](const kit::Options& o, kit::Scene& scene) {
        const Setup u = setup(o, p);
        const Kicked kicked = kicked_motions(u);
        report_kicked(scene.report, u, kicked);
        const Escapes es = escapes(u);
        report_escapes(scene.report, u, es);
        report_undisturbed_exit(scene.report, u);
        draw_kicks(scene, u, kicked);
        draw_escapes(scene, es);
    });
}
