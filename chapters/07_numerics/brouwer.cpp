// Chapter 7 scene: Brouwer's law for the workbook's best method. The Grioli precession
// (1, 1.5, 2), f = 1, followed for N periods with the provided Taylor method of degree 16 (about
// 32 steps a period, truncation far below round-off), once with plain summation (the state
// rounded at every step) and once with compensated summation of the increments
// (rigid::Summation::compensated). Round-off that does not correlate from step to step makes
// the invariants walk like sqrt(t) and the phase like t^(3/2) (Brouwer's law); a bias makes them
// drift like t and t^2. A single run is one random walk, so the scene runs an ensemble: the same
// start with K slightly different steps (K rounding patterns), and fits the exponent of the root
// mean square of the rotation error and of the energy error against time over the last two
// decades of the run.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "brouwer.gp.hpp"
#include "figure.hpp"
#include "rigid/grioli.hpp"
#include "rigid/heavy_top.hpp"
#include "rigid/rotation.hpp"
#include "rigid/taylor.hpp"
#include "scene.hpp"

using rigid::BodyState;

namespace {

struct Params {
    long periods = 10000;
    int ensemble = 4;
    int steps = 32;
    int degree = 16;
};

void declare(kit::Options& opts, Params& p) {
    opts.integer("periods", &p.periods, "periods 2 pi / alpha to follow (the fit covers the last two decades)", 100,
                 1000000)
        .integer("ensemble", &p.ensemble, "runs with slightly different steps, for the root mean square", 1, 16)
        .integer("steps", &p.steps, "Taylor steps a period (the runs of the ensemble take up to 1% more)", 16, 256)
        .integer("degree", &p.degree, "degree of the Taylor method", 8, 30);
}

// The precession, its period and energy scale, and the output instants (ten a decade, in whole
// periods).
struct Problem {
    rigid::GrioliPrecession g;
    rigid::HeavyTop top;
    BodyState s0;
    double period, H0;
    std::vector<double> at;  // output instants, in periods
};

Problem problem(long periods) {
    const rigid::Moments m = rigid::moments(1, 1.5, 2);
    Problem pb{rigid::grioli_precession(m, 1.0, rigid::Sense::ccw), {}, {}, 0, 0, {0.0}};
    pb.top = rigid::grioli_top(m, pb.g);
    pb.s0 = rigid::grioli_initial_state(pb.g);
    pb.period = 2 * std::numbers::pi / pb.g.alpha;
    pb.H0 = rigid::heavy_top_energy(pb.top, pb.s0);
    for (int i = 0;; ++i) {
        const double p = std::round(std::pow(10.0, i / 10.0));
        if (p > double(periods)) break;
        if (p > pb.at.back()) pb.at.push_back(p);
    }
    if (pb.at.back() < double(periods)) pb.at.push_back(double(periods));
    return pb;
}

// One summation: the root mean square over the ensemble of the rotation error (rad) and of the
// energy error |H - H(0)| / f at each output instant, and the run time of one run.
struct Track {
    std::vector<double> rms_angle, rms_energy;
    double time_s = 0;
};

Track run(const Params& p, const Problem& pb, rigid::Summation sum) {
    std::vector<double> times;
    for (double a : pb.at) times.push_back(a * pb.period);
    Track tr{std::vector<double>(times.size()), std::vector<double>(times.size()), 0};
    for (int k = 0; k < p.ensemble; ++k) {
        const double h = pb.period / (p.steps * (1 + 0.01 * k / p.ensemble));
        std::size_t i = 0;
        tr.time_s += kit::min_time(
            [&] {
                i = 0;
                rigid::integrate_taylor<double>(
                    pb.top, pb.s0, times,
                    [&](double t, const rigid::TaylorState<double>& x) {
                        const BodyState s = rigid::to_double(x);
                        const double e = rigid::geodesic_angle(s.R, rigid::grioli_rotation(pb.g, t));
                        const double dH = (rigid::heavy_top_energy(pb.top, s) - pb.H0) / pb.top.f;
                        tr.rms_angle[i] += e * e / p.ensemble, tr.rms_energy[i] += dH * dH / p.ensemble;
                        ++i;
                    },
                    h, p.degree, sum);
            },
            1);
    }
    for (std::size_t i = 0; i < times.size(); ++i)
        tr.rms_angle[i] = std::sqrt(tr.rms_angle[i]), tr.rms_energy[i] = std::sqrt(tr.rms_energy[i]);
    tr.time_s /= p.ensemble;
    return tr;
}

// Least-squares slope of log y against log t over the instants t in [from, to] periods.
double exponent(const std::vector<double>& at, const std::vector<double>& y, double from, double to) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t i = 0; i < at.size(); ++i) {
        if (at[i] < from || at[i] > to || !(y[i] > 0)) continue;
        const double x = std::log(at[i]), v = std::log(y[i]);
        sx += x, sy += v, sxx += x * x, sxy += x * v, ++n;
    }
    return n < 3 ? std::nan("") : (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

void report(kit::Report& r, const Params& p, const Problem& pb, const Track& plain, const Track& comp) {
    const double to = double(p.periods), from = to / 100;
    if (!std::isfinite(comp.rms_angle.back()) || !std::isfinite(plain.rms_angle.back()))
        throw kit::NumericalFailure("the integration produced a non-finite rotation");
    r.headline(fmt::format("root mean square over {} runs of the angle between R and the exact R after {} periods "
                           "(Taylor-{}, compensated summation)",
                           p.ensemble, p.periods, p.degree),
               comp.rms_angle.back(), comp.time_s);
    r.add("periods", p.periods);
    r.add("ensemble", static_cast<long>(p.ensemble), "runs: the same start, steps up to 1% apart");
    r.add("steps_per_period", static_cast<long>(p.steps));
    r.add("degree", static_cast<long>(p.degree));
    r.add("fit_from_periods", from, "the exponents are fitted over [fit_from_periods, periods]");
    r.add("phase_exponent_compensated", exponent(pb.at, comp.rms_angle, from, to),
          "d log(rms angle) / d log t; Brouwer's law: 1.5");
    r.add("phase_exponent_plain", exponent(pb.at, plain.rms_angle, from, to), "the same, plain summation");
    r.add("energy_exponent_compensated", exponent(pb.at, comp.rms_energy, from, to),
          "d log(rms energy error) / d log t; Brouwer's law: 0.5");
    r.add("energy_exponent_plain", exponent(pb.at, plain.rms_energy, from, to), "the same, plain summation");
    r.add("angle_compensated", comp.rms_angle.back(), "rad, rms at the end");
    r.add("angle_plain", plain.rms_angle.back(), "rad, rms at the end");
    r.add("energy_compensated", comp.rms_energy.back(), "|H - H(0)| / f, rms at the end");
    r.add("energy_plain", plain.rms_energy.back(), "|H - H(0)| / f, rms at the end");
    r.add("time_plain_s", plain.time_s, "one run");
    // The same exponents decade by decade: where the growth changes. A row for every decade up to
    // the longest run the scene allows (1e6 periods); past this run's end, NaN.
    std::vector<std::vector<double>> rows;
    for (double lo = 1; lo < 1e6; lo *= 10)
        rows.push_back({std::log10(lo * 10), lo, lo * 10, exponent(pb.at, comp.rms_angle, lo, lo * 10),
                        exponent(pb.at, plain.rms_angle, lo, lo * 10), exponent(pb.at, comp.rms_energy, lo, lo * 10),
                        exponent(pb.at, plain.rms_energy, lo, lo * 10)});
    r.table("by_decade",
            {"decade", "from_periods", "to_periods", "phase_compensated", "phase_plain", "energy_compensated",
             "energy_plain"},
            rows);
}

void draw(kit::Scene& scene, const Params& p, const Problem& pb, const Track& plain, const Track& comp) {
    kit::Figure fig(scene, "brouwer.svg", 900, 520);
    if (!fig.enabled()) return;
    fig.script(kit::gp::brouwer, {{"degree", fmt::format("{}", p.degree)},
                                  {"steps", fmt::format("{}", p.steps)},
                                  {"ensemble", fmt::format("{}", p.ensemble)}});
    for (const auto* y : {&comp.rms_angle, &plain.rms_angle, &comp.rms_energy, &plain.rms_energy}) {
        std::vector<std::vector<double>> rows;
        for (std::size_t i = 1; i < pb.at.size(); ++i) rows.push_back({pb.at[i], std::max((*y)[i], 1e-18)});
        fig.data(rows);
    }
    // Brouwer's slopes, through the compensated curves at the end.
    std::vector<std::vector<double>> guide;
    const double T = pb.at.back(), from = T / 100;
    for (double t : {from, T}) guide.push_back({t, comp.rms_angle.back() * std::pow(t / T, 1.5)});
    guide.push_back({});
    for (double t : {from, T}) guide.push_back({t, comp.rms_energy.back() * std::pow(t / T, 0.5)});
    fig.data(guide);
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("brouwer", "Chapter 7: Brouwer's law for the Taylor method, plain and compensated summation");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&p](const kit::Options& o, kit::Scene& scene) {
        // The work: two summations, `ensemble` runs each, `steps` Taylor steps a period of about
        // 12 degree^2 multiply-adds (3.5 us at degree 16 on one core), doubled.
        const double per_step = 7e-6 * (p.degree * p.degree) / 256.0;
        kit::require_budget(o, {2.0 * p.ensemble * double(p.periods) * p.steps, per_step, "Taylor steps",
                                "--periods, --ensemble, --steps, --degree"});
        const Problem pb = problem(p.periods);
        const Track plain = run(p, pb, rigid::Summation::plain);
        const Track comp = run(p, pb, rigid::Summation::compensated);
        report(scene.report, p, pb, plain, comp);
        draw(scene, p, pb, plain, comp);
    });
}
