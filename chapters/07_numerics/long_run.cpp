// Chapter 7 scene: a long run. The Grioli precession (1, 1.5, 2) for a million fixed steps
// h = 1/16 (about 7900 periods) with your RK4, RKMK4, Strang's splitting and its triple jump,
// the last three with plain and with compensated summation of their increments, and GSL's
// rk8pd over the same time. Recorded at 60 instants spaced evenly in log t: the drift of the
// energy and of the vertical angular momentum, ||R^T R - 1||, and the angle from the exact R.
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "figure.hpp"
#include "long_run.gp.hpp"
#include "rigid/grioli.hpp"
#include "rigid/integrators.hpp"
#include "rigid/numerics.hpp"
#include "rigid/rotation.hpp"
#include "rigid/stepping.hpp"
#include "scene.hpp"

using rigid::BodyState;
using rigid::Mat3;
using rigid::Vec3;
using rigid::VecX;

namespace {

struct Track {
    Track(std::string n, std::string l, std::string s) : name(std::move(n)), label(std::move(l)), style(std::move(s)) {}
    std::string name, label, style;
    std::vector<std::vector<double>> rows;  // t / period, steps, dH, dL, orth, err_R
    double time_s = 0;
};

// Least-squares slope of log y against log x over the second half of the rows (column c).
double late_slope(const std::vector<std::vector<double>>& rows, int c) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t i = rows.size() / 2; i < rows.size(); ++i) {
        if (!(rows[i][c] > 0)) continue;
        const double x = std::log(rows[i][1]), y = std::log(rows[i][c]);
        sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
    }
    return n < 3 ? std::numeric_limits<double>::quiet_NaN() : (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// The scene's parameters, bound to its options.
struct Params {
    long steps = 1000000;
    double tol = 1e-12;
};

void declare(kit::Options& opts, Params& p) {
    opts.integer("steps", &p.steps,
                 "fixed steps of h = 1/16 (a power of two, so that every output time is a whole "
                 "number of steps)",
                 1000, 20000000)
        .real("tol", &p.tol, "tolerance of GSL rk8pd over the same time", kit::between(1e-14, 1e-3));
}

// The Grioli precession of (1, 1.5, 2) followed for N steps, the output instants and the scales
// of the invariants.
struct Problem {
    long N;
    double h, period;
    rigid::GrioliPrecession g;
    rigid::HeavyTop top;
    BodyState s0;
    std::vector<double> times;
    std::vector<long> at;  // the output instants, in steps
    double H0, E_scale, L0, L_scale;
};

Problem problem(long N) {
    Problem pb;
    pb.N = N;
    const double h = pb.h = 1.0 / 16;
    const rigid::Moments m = rigid::moments(1, 1.5, 2);
    const rigid::GrioliPrecession g = pb.g = rigid::grioli_precession(m, 1.0, rigid::Sense::ccw);
    const rigid::HeavyTop top = pb.top = rigid::grioli_top(m, g);
    const BodyState s0 = pb.s0 = rigid::grioli_initial_state(g);
    pb.period = 2 * std::numbers::pi / g.alpha;

    // Output instants: whole numbers of steps, about evenly spaced in log.
    auto& times = pb.times;
    auto& at = pb.at;
    times = {0.0};
    at = {0};
    for (int i = 0; i <= 59; ++i) {
        const long n = std::lround(std::pow(10.0, 1 + (std::log10(double(N)) - 1) * i / 59.0));
        if (n > at.back()) at.push_back(n), times.push_back(n * h);
    }
    pb.H0 = rigid::heavy_top_energy(top, s0);
    pb.E_scale = 0.5 * s0.Omega.dot(top.J * s0.Omega) + top.f;
    pb.L0 = top.k.dot(s0.R * top.J * s0.Omega), pb.L_scale = (top.J * s0.Omega).norm();

    return pb;
}

// The rows of one track from the states at the output instants: the drifts of the energy and
// of the vertical momentum, the orthogonality defect, and the angle from the exact R.
void record(std::vector<Track>& tracks, Track tr, const Problem& pb, const std::vector<BodyState>& out) {
    const auto& top = pb.top;
    for (std::size_t i = 1; i < pb.times.size(); ++i) {
        const BodyState& s = out[i];
        tr.rows.push_back(
            {pb.times[i] / pb.period, double(pb.at[i]), std::abs(rigid::heavy_top_energy(top, s) - pb.H0) / pb.E_scale,
             std::abs(top.k.dot(s.R * top.J * s.Omega) - pb.L0) / pb.L_scale, rigid::orthogonality_defect(s.R),
             rigid::geodesic_angle(rigid::grioli_rotation(pb.g, pb.times[i]), s.R)});
    }
    tracks.push_back(tr);
}

// Your RK4 and GSL rk8pd, on the packed state.
void run_library_tracks(std::vector<Track>& tracks, const Problem& pb, double tol) {
    const auto& top = pb.top;
    std::vector<BodyState> out(pb.times.size());
    const rigid::OdeRhs rhs = [&top](double, const VecX& y) {
        return rigid::pack(rigid::euler_poisson_rhs(top, rigid::unpack(y)));
    };
    std::size_t i = 0;
    const auto keep = [&](double, const VecX& y) { out[i++] = rigid::unpack(y); };
    Track rk4{"rk4", "your RK4", "lc rgb '#000000'"};
    rk4.time_s = kit::min_time(
        [&] {
            i = 0;
            rigid::integrate_rk4(rhs, rigid::pack(pb.s0), pb.times, keep, pb.h);
        },
        1);
    record(tracks, rk4, pb, out);
    std::ostringstream label;
    label << "GSL rk8pd, tol " << tol;
    Track rk8pd{"rk8pd", label.str(), "lc rgb '#0072B2' dt 2"};
    rk8pd.time_s = kit::min_time(
        [&] {
            i = 0;
            rigid::integrate_gsl(rhs, rigid::pack(pb.s0), pb.times, keep,
                                 {.method = "rk8pd", .rel_tol = tol, .abs_tol = tol});
        },
        1);
    record(tracks, rk8pd, pb, out);
}

// RKMK4, Strang and its triple jump, each with plain and compensated sums.
void run_geometric_tracks(std::vector<Track>& tracks, const Problem& pb) {
    const auto& top = pb.top;
    const rigid::IncrementStepper rkmk4 = [&top](const BodyState& s, double dt) {
        return rigid::rkmk4_step(top, s, dt);
    };
    const rigid::IncrementStepper strang = [&top](const BodyState& s, double dt) {
        return rigid::strang_step(top, s, dt);
    };
    const rigid::IncrementStepper yoshida = [&strang](const BodyState& s, double dt) {
        return rigid::triple_jump(strang, s, dt);
    };
    struct Geometric {
        std::string name, label, colour;
        const rigid::IncrementStepper* step;
    };
    std::vector<BodyState> out(pb.times.size());
    for (const Geometric& gm :
         {Geometric{"rkmk4", "RKMK4", "#009E73", &rkmk4}, Geometric{"strang", "Strang", "#D55E00", &strang},
          Geometric{"yoshida4", "Strang + triple jump", "#CC79A7", &yoshida}}) {
        for (const auto sum : {rigid::Summation::plain, rigid::Summation::compensated}) {
            const bool plain = sum == rigid::Summation::plain;
            Track tr{gm.name + (plain ? "_plain" : "_compensated"),
                     gm.label + (plain ? ", plain sum" : ", compensated"),
                     "lc rgb '" + gm.colour + "'" + (plain ? " dt 3" : "")};
            std::size_t i = 0;
            tr.time_s = kit::min_time(
                [&] {
                    i = 0;
                    rigid::integrate_steps(
                        *gm.step, pb.s0, pb.times, [&](double, const BodyState& s) { out[i++] = s; }, pb.h, sum);
                },
                1);
            record(tracks, tr, pb, out);
        }
    }
}

// Your RK4, GSL rk8pd, and RKMK4, Strang and its triple jump with plain and compensated sums.
std::vector<Track> run_tracks(const Problem& pb, double tol) {
    std::vector<Track> tracks;
    run_library_tracks(tracks, pb, tol);
    run_geometric_tracks(tracks, pb);
    return tracks;
}

// The report: the last row of every track, and the growth of the orthogonality defect.
void report(kit::Report& r, const Problem& pb, const std::vector<Track>& tracks) {
    const long N = pb.N;
    const double h = pb.h, period = pb.period;
    double worst_orth = 0;
    for (const Track& tr : tracks) {
        const auto& last = tr.rows.back();
        r.add(tr.name + "_time_s", tr.time_s);
        r.add(tr.name + "_energy_drift", last[2]);
        r.add(tr.name + "_momentum_drift", last[3]);
        r.add(tr.name + "_orthogonality", last[4]);
        r.add(tr.name + "_error_R", last[5]);
        r.add(tr.name + "_orthogonality_slope", late_slope(tr.rows, 4), "d log(defect) / d log(steps), late half");
        if (tr.name.find("_compensated") != std::string::npos) worst_orth = std::max(worst_orth, last[4]);
    }
    double geometric_time = 0;
    for (const Track& tr : tracks)
        if (tr.name.find("_compensated") != std::string::npos) geometric_time += tr.time_s;
    r.headline("largest ||R^T R - 1||_F after " + std::to_string(N) +
                   " steps of RKMK4, Strang and its triple jump (compensated sums; target < 1e-13)",
               worst_orth, geometric_time);
    r.add("steps", N);
    r.add("h", h);
    r.add("periods", N * h / period);
    r.add("brouwer", std::numeric_limits<double>::epsilon() * std::sqrt(double(N)), "eps sqrt(steps)");
}

void draw(kit::Scene& scene, const Problem& pb, const std::vector<Track>& tracks) {
    const long N = pb.N;
    const double h = pb.h, period = pb.period;
    kit::Figure fig(scene, "long_run.svg", 1450, 900);
    if (!fig.enabled()) return;
    fig.script(kit::gp::long_run,
               {{"title", kit::quoted("Grioli (1, 1.5, 2): " + std::to_string(N) + " steps of h = 1/16 (" +
                                      std::to_string(long(N * h / period)) + " periods)")}});
    const char* panels[4][2] = {{"energy: |H − H(0)| / (T(0) + f)", "energy drift"},
                                {"vertical angular momentum ({/:Bold k}, RJΩ)", "drift / |JΩ(0)|"},
                                {"orthogonality ‖R^T R − 1‖_F", "defect"},
                                {"angle between R and the exact R (rad)", "error"}};
    std::vector<kit::Fill> track_curves;
    for (const Track& tr : tracks) track_curves.push_back({{"style", tr.style}, {"title", kit::quoted(tr.label)}});
    const std::string curves = kit::joined(kit::gp::track, track_curves);
    for (int p = 0; p < 4; ++p) {
        fig.script(p == 2 ? kit::gp::key_panel : kit::gp::panel,
                   {{"title", kit::quoted(panels[p][0])}, {"ylabel", kit::quoted(panels[p][1])}, {"curves", curves}});
        for (const Track& tr : tracks) {
            std::vector<std::vector<double>> rows;
            for (const auto& r : tr.rows) rows.push_back({r[0], std::max(r[2 + p], 1e-17)});
            fig.data(rows);
        }
        if (p == 2) {
            std::vector<std::vector<double>> rows;
            for (const auto& r : tracks.front().rows)
                rows.push_back({r[0], std::numeric_limits<double>::epsilon() * std::sqrt(r[1])});
            fig.data(rows);
        }
    }
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("long_run", "Chapter 7: a million steps on the Grioli precession: what drifts and what does not");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&p](const kit::Options& o, kit::Scene& scene) {
        // The work: eight methods over N steps of h = 1/16 (rk8pd over the same time).
        kit::require_budget(o, {double(p.steps), 1.2e-5, "steps (of each of the eight methods)", "--steps"});
        const Problem pb = problem(p.steps);
        const std::vector<Track> tracks = run_tracks(pb, p.tol);
        report(scene.report, pb, tracks);
        draw(scene, pb, tracks);
    });
}
