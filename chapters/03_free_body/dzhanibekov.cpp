// Chapter 3 scene: the separatrix and the Dzhanibekov flip, the free body's extreme case.
//
// A spin about the middle axis, slightly perturbed, Omega0 = (delta, w, delta): the body flips
// over and over; on the separatrix itself it flips once and never comes back [P, Sect. 3]. The
// exact motion (Jacobi elliptic functions with m_c kept accurate) is the reference. The scene
// shows the flips, the error growth of the student's RK4 and of rk8pd at each flip, and a
// table of ever closer approaches to the separatrix (m_c down to ~1e-12): the reference's own
// consistency, what GSL's gsl_sf_elljac_e(u, m) loses by forming 1 - m, and rk8pd's error.
#include <gsl/gsl_sf_elljac.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "body.hpp"
#include "dzhanibekov.gp.hpp"
#include "figure.hpp"
#include "free_body_scene.hpp"
#include "motion.hpp"
#include "rigid/free_body_exact.hpp"
#include "rigid/require.hpp"
#include "scene.hpp"

using rigid::Vec3;

namespace {

// The exact Omega(t), but with GSL's elljac(u, m): what happens when 1 - m is formed from m.
Vec3 omega_with_gsl_elljac(const rigid::FreeBodyMotion& mo, double t) {
    double sn, cn, dn;
    gsl_sf_elljac_e(mo.u0 + mo.lambda * t, mo.m, &sn, &cn, &dn);
    Vec3 w;
    w(mo.p) = mo.amplitude(mo.p) * cn;
    w(mo.q) = mo.amplitude(mo.q) * sn;
    w(mo.s) = mo.amplitude(mo.s) * dn;
    return w;
}

std::string short_number(double x, int digits = 6) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    return buf;
}

// The scene's parameters, bound to its options.
struct Params {
    Vec3 I{3, 4, 6};
    double spin = 10, delta = 1e-3, T = 20, h = 2e-3, tol = 1e-12;
};

void declare(kit::Options& opts, Params& p) {
    opts.vector("I", &p.I, "principal moments (distinct; the middle one is the unstable axis)",
                kit::components_between(1e-3, 1e3))
        .real("spin", &p.spin, "Omega about the middle axis", kit::between(1e-3, 1e3))
        .real("delta", &p.delta, "perturbation of the other two components (at most spin / 10)",
              kit::between(1e-9, 1e3))
        .real("T", &p.T, "time span", kit::between(1e-3, 1e6))
        .real("h", &p.h, "step of the student's RK4 (at most T / 10)", kit::between(1e-9, 1e3))
        .real("tol", &p.tol, "rk8pd tolerance", kit::between(1e-14, 1e-3));
}

// The body's axes sorted by moment, and the starts near the middle axis.
struct Setup {
    Params p;
    int lo, mid, hi;
    // Omega(0): the spin about the middle axis, d about the smallest, ratio_hi d about the largest.
    Vec3 start(double d, double ratio_hi) const {
        Vec3 w = Vec3::Zero();
        w(mid) = p.spin;
        w(lo) = d;
        w(hi) = ratio_hi * d;
        return w;
    }
};

Setup setup(const kit::Options& o, const Params& p) {
    kit::require_moments(p.I, "I", {kit::Order::distinct});
    const auto [lo, mid, hi] = scene3::sorted_axes(p.I);
    const double spin = p.spin, delta = p.delta, T = p.T, h = p.h, tol = p.tol;
    if (h > 0.1 * T) throw kit::BadInput("--h must be at most T / 10");
    // A flip about the middle axis needs a small perturbation: with delta near the spin the
    // motion is no longer near the separatrix, and the figure's labels would not hold.
    if (!(delta <= 0.1 * spin))
        throw kit::BadInput("--delta: got " + short_number(delta) + "; it must be at most spin / 10 = " +
                            short_number(0.1 * spin) + " (--spin), to stay near the separatrix");
    // The work: the student's RK4 (3 timed runs of T / h steps), rk8pd (3 timed runs, about
    // steps_per_radian radians of the spin's phase each), and the approach table (six rk8pd
    // runs at tolerance 1e-14 over at most T).
    const double phase = spin * T, rk8pd_steps_per_radian = 0.25 * std::pow(1e-12 / tol, 1.0 / 8);
    kit::require_budget(o, {3 * T / h, 1e-6, "RK4 steps", "--T, --h"});
    kit::require_budget(
        o, {3 * phase * rk8pd_steps_per_radian + 6 * phase * 0.4, 4e-6, "rk8pd steps", "--T, --spin, --tol"});
    return {p, lo, mid, hi};
}

// The separatrix curve as computed: for most bodies its start, rounded to double, lies on the
// separatrix only to round-off (m_c of order eps^2, not 0), and it flips again after half its
// period. Its flips are counted on a grid that resolves that period and predicted from its u0,
// K and lambda (the zeros of its middle component sn(u0 + lambda t) are at u = 2 j K); the
// figure's label says which curve it is.
struct SeparatrixFlips {
    long counted = 0, predicted = 0;
    bool at_an_end = false;  // a predicted zero within round-off of t = T: counted may differ by one
    std::string label;
    bool ideal = true;  // the label is that of the exact separatrix
};

SeparatrixFlips separatrix_flips(const rigid::FreeBodyMotion& sep, int mid, double T) {
    SeparatrixFlips s;
    const double samples = std::max(400.0, std::ceil(16 * T / sep.period));  // 8 per flip at least
    const long n = static_cast<long>(std::min(samples, 1e8));
    bool was_positive = rigid::free_body_exact_omega(sep, 0)(mid) > 0;
    for (long k = 1; k <= n; ++k) {
        const bool positive = rigid::free_body_exact_omega(sep, T * static_cast<double>(k) / n)(mid) > 0;
        s.counted += positive != was_positive;
        was_positive = positive;
    }
    const double u_end = sep.u0 + sep.lambda * T;
    if (std::isfinite(sep.period)) {
        const double two_K = sep.lambda * sep.period / 2;
        s.predicted = std::lround(std::floor(u_end / two_K) - std::floor(sep.u0 / two_K));
        const double to_zero = std::abs(u_end / two_K - std::round(u_end / two_K));
        s.at_an_end = to_zero < 1e-9 * std::max(1.0, std::abs(u_end / two_K));
    } else {  // m_c = 0: sn = tanh, one zero, at u = 0
        s.predicted = sep.u0 < 0 && u_end >= 0;
        s.at_an_end = std::abs(u_end) < 1e-9 * std::max(1.0, std::abs(sep.u0));
    }
    s.ideal = s.counted <= 1;
    if (s.counted == 1)
        s.label = "separatrix: one flip only";
    else if (s.counted == 0)
        s.label = "separatrix: its one flip comes after T";
    else
        s.label = "separatrix start rounded to double: m_c = " + short_number(sep.m_c, 2) + ", " +
                  std::to_string(s.counted) + " flips, period " + short_number(sep.period, 3);
    return s;
}

// 1. The flips: exact, rk8pd, the student's RK4; and the separatrix motion.
struct Flip {
    rigid::FreeBodyMotion exact, sep;
    SeparatrixFlips flips;
    std::vector<std::vector<double>> comps, err_rows;
    double e8 = 0, e4 = 0, t8 = 0, t4 = 0;
};

Flip flip(const Setup& u) {
    const Vec3& I = u.p.I;
    const int lo = u.lo, mid = u.mid, hi = u.hi;
    const double T = u.p.T;
    const double delta = u.p.delta, h = u.p.h, tol = u.p.tol;
    const auto start = [&u](double d, double ratio_hi) { return u.start(d, ratio_hi); };
    Flip f;
    // On the separatrix, I_lo (I_mid - I_lo) W_lo^2 = I_hi (I_hi - I_mid) W_hi^2.
    const Vec3 w0 = start(delta, 1.0);
    const auto exact = f.exact = rigid::free_body_motion(I, w0);
    const double ratio = std::sqrt(I(lo) * (I(mid) - I(lo)) / (I(hi) * (I(hi) - I(mid))));
    // Of the two separatrix branches through this neighbourhood, take the one that flips forward in time.
    auto& sep = f.sep;
    sep = rigid::free_body_motion(I, start(delta, ratio));
    if (rigid::free_body_exact_omega(sep, T)(mid) > 0) sep = rigid::free_body_motion(I, start(delta, -ratio));
    const int n = 400;
    const auto times = rigid::linspace(0, T, n);
    scene3::Run r8, r4;
    f.t8 = kit::min_time([&] { r8 = scene3::integrate(I, w0, times, "rk8pd", tol); }, 3);
    f.t4 = kit::min_time([&] { r4 = scene3::integrate(I, w0, times, "rk4", h); }, 3);
    auto &comps = f.comps, &err_rows = f.err_rows;
    auto &e8 = f.e8, &e4 = f.e4;
    for (int k = 0; k <= n; ++k) {
        const Vec3 we = rigid::free_body_exact_omega(exact, times[k]);
        const Vec3 ws = rigid::free_body_exact_omega(sep, times[k]);
        const double a8 = (r8.Omega[k] - we).norm() / w0.norm(), a4 = (r4.Omega[k] - we).norm() / w0.norm();
        e8 = std::max(e8, a8);
        e4 = std::max(e4, a4);
        comps.push_back({times[k], we(lo), we(mid), we(hi), ws(mid), r4.Omega[k](mid)});
        err_rows.push_back({times[k], std::max(a8, 1e-18), std::max(a4, 1e-18)});
    }
    f.flips = separatrix_flips(sep, mid, T);
    return f;
}

// The headline, and the separatrix curve: its m_c, its flips, its label.
void report_flip(kit::Report& report, const Flip& f) {
    const auto &exact = f.exact, &sep = f.sep;
    const SeparatrixFlips& s = f.flips;
    report.headline("max |Omega_rk8pd - Omega_exact| / |Omega(0)| over [0, T] near the separatrix", f.e8, f.t8);
    report.add("m_c", exact.m_c, "complementary elliptic parameter of the default motion");
    report.add("period", exact.period, "of Omega(t): two flips");
    report.add("rk4_error", f.e4, "the student's RK4 at step h, same measure");
    report.add("rk4_run_time_s", f.t4);
    report.add("separatrix_m_c", sep.m_c, "its start rounded to double: 0 on the exact separatrix");
    report.add("separatrix_period", sep.period, "of its Omega(t), two flips (null: infinite, m_c = 0)");
    report.add("separatrix_flips", s.counted, "sign changes of its middle component in [0, T]");
    report.add("separatrix_flips_predicted", s.predicted, "zeros of sn(u0 + lambda t) in (0, T]");
    report.add("separatrix_label", s.label, "the curve's label in the figure");
    report.add("separatrix_label_ideal", s.ideal, "true: at most one flip in [0, T], as on the exact separatrix");
    // Started from rounded numbers, the separatrix motion has m_c of order eps^2 (a period of about
    // 4 ln(4 / sqrt(m_c)) / lambda): more is no longer the separatrix.
    if (!(sep.m_c <= 1e-12))
        throw kit::CheckFailed("the separatrix motion has m_c = " + short_number(sep.m_c) +
                               "; it must be 0 (to 1e-12)");
    if (!(s.counted == s.predicted || (s.at_an_end && std::abs(s.counted - s.predicted) == 1)))
        throw kit::CheckFailed("the separatrix curve flips " + std::to_string(s.counted) + " times in [0, T], but " +
                               "its exact period " + short_number(sep.period) + " predicts " +
                               std::to_string(s.predicted));
}

// 2. Ever closer to the separatrix.
void report_approach(kit::Report& report, const Setup& u) {
    const Vec3& I = u.p.I;
    const double spin = u.p.spin, T = u.p.T;
    const auto start = [&u](double d, double ratio_hi) { return u.start(d, ratio_hi); };
    std::vector<std::vector<double>> table;
    double worst_ref = 0, worst_ratio = 0;
    for (double d : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
        const auto mo = rigid::free_body_motion(I, start(d, 1.0));
        const double Tn = std::min(T, 0.75 * mo.period);  // past the first flip
        // (a) The reference against itself: restart from Omega(Tn / 2).
        const auto re = rigid::free_body_motion(I, rigid::free_body_exact_omega(mo, Tn / 2));
        const double self =
            (rigid::free_body_exact_omega(re, Tn / 2) - rigid::free_body_exact_omega(mo, Tn)).norm() / spin;
        worst_ref = std::max(worst_ref, self);
        // (b) With GSL's elljac(u, m): 1 - m formed inside.
        const double gsl_diff = (omega_with_gsl_elljac(mo, Tn) - rigid::free_body_exact_omega(mo, Tn)).norm() / spin;
        // (c) rk8pd against the reference at Tn.
        const scene3::Run run = scene3::integrate(I, mo.Omega0, {0.0, Tn}, "rk8pd", 1e-14);
        const double e = (run.Omega.back() - rigid::free_body_exact_omega(mo, Tn)).norm() / spin;
        const double limit = std::numeric_limits<double>::epsilon() / mo.m_c;
        worst_ratio = std::max(worst_ratio, e / limit);
        table.push_back({d, mo.m_c, mo.period, Tn, self, gsl_diff, e, limit});
    }
    report.add("reference_self_consistency", worst_ref, "max over the table of the restart difference / spin");
    report.add("rk8pd_over_limit", worst_ratio, "max over the table of rk8pd's error / (eps / m_c)");
    report.table("approach",
                 {"delta", "m_c", "period", "t", "ref_restart", "gsl_elljac_diff", "rk8pd_error", "eps_over_m_c"},
                 table);
}

void draw_flip(kit::Scene& scene, const Flip& f) {
    const auto& comps = f.comps;
    // The small components are drawn ten times larger, and the vertical range is taken from
    // everything drawn, so that no curve is cut off.
    std::vector<std::vector<double>> c1, c2, c3, c4, c5;
    double top = 0;
    for (std::size_t k = 0; k < comps.size(); ++k) {
        const auto& c = comps[k];
        c1.push_back({c[0], 10 * c[1]});
        c2.push_back({c[0], c[2]});
        c3.push_back({c[0], 10 * c[3]});
        c4.push_back({c[0], c[4]});
        if (k % 4 == 0) c5.push_back({c[0], c[5]});
        top = std::max({top, std::abs(10 * c[1]), std::abs(c[2]), std::abs(10 * c[3]), std::abs(c[4]), std::abs(c[5])});
    }
    kit::Figure fig(scene, "dzhanibekov_flip.svg", 900, 480);
    // A label that names a rounded start is long: the key goes below the plot.
    fig.script(kit::gp::flip, {{"key", f.flips.ideal ? "outside right" : "below height 1"},
                               {"ymin", std::to_string(-1.08 * top)},
                               {"ymax", std::to_string(1.08 * top)},
                               {"flips", kit::quoted(f.flips.label)}});
    fig.data(c1).data(c2).data(c3).data(c4).data(c5);
    fig.finish();
}

void draw_error(kit::Scene& scene, const Setup& u, const Flip& f) {
    const double tol = u.p.tol, h = u.p.h;
    const auto& err_rows = f.err_rows;
    kit::Figure fe(scene, "dzhanibekov_error.svg", 900, 480);
    fe.script(kit::gp::error, {{"rk8pd", kit::quoted("rk8pd, tol " + short_number(tol))},
                               {"rk4", kit::quoted("student RK4, h = " + short_number(h))}});
    std::vector<std::vector<double>> a, b;
    for (const auto& r : err_rows) {
        a.push_back({r[0], r[1]});
        b.push_back({r[0], r[2]});
    }
    fe.data(a).data(b);
    fe.finish();
}

// The book's motion viewer: the exact motion of the flip, R(t) over [0, T], the body drawn as
// the box with its moments.
void write_flip_motion(kit::Scene& scene, const std::string& file, const Setup& u, const Flip& f) {
    if (file.empty()) return;
    kit::Motion m;
    m.title = "the Dzhanibekov flip: a spin about the middle axis R_B, perturbed by δ (exact motion)";
    m.parameters = "I = (" + short_number(u.p.I(0)) + ", " + short_number(u.p.I(1)) + ", " + short_number(u.p.I(2)) +
                   "), spin " + short_number(u.p.spin) + ", δ = " + short_number(u.p.delta) + ", t from 0 to " +
                   short_number(u.p.T);
    m.error = f.e8;
    m.error_measure = "max |Ω_rk8pd − Ω_exact| / |Ω(0)|: an independent integration against the motion shown";
    m.moments = u.p.I;
    m.shape = "box";
    m.speed = 0.25;
    const auto times = rigid::linspace(0, u.p.T, 800);
    const auto R = rigid::free_body_exact_rotations(f.exact, times);
    for (std::size_t k = 0; k < times.size(); ++k) m.sample(times[k], R[k]);
    kit::write_motion(scene, file, m);
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    std::string motion_file;
    kit::Options opts("dzhanibekov",
                      "Chapter 3: the Dzhanibekov flip near the separatrix, and the exact reference there");
    declare(opts, p);
    opts.file("motion", &motion_file, kit::motion_help);
    return kit::run(argc, argv, opts, [&p, &motion_file](const kit::Options& o, kit::Scene& scene) {
        const Setup u = setup(o, p);
        const Flip f = flip(u);
        report_flip(scene.report, f);
        report_approach(scene.report, u);
        draw_flip(scene, f);
        draw_error(scene, u, f);
        write_flip_motion(scene, motion_file, u, f);
    });
}
