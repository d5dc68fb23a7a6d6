// Chapter 5 scene: the extreme cases of Theorem 1. Nearly symmetric bodies (B - A or C - B
// down to 1e-9 of C - A), the flat limit A + B = C, and f from 1e-6 to 1e6.
//
// For each case: the closed form computed from the gaps (rigid::moments_from_gaps) against a
// long double evaluation, the same numbers computed the naive way (B and C rounded first, the
// differences formed afterwards, theta by acos) for contrast, and an integration over 100
// periods (rk8pd, tol 1e-12) against R^b(alpha t) R^a(alpha t).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "heavy_body.hpp"
#include "rigid/grioli.hpp"
#include "rigid/ode.hpp"
#include "scene.hpp"
#include "stability.hpp"

using rigid::Vec3;

namespace {

struct Case {
    double A, BA, CB, f;
};

// The closed form in long double, from the gaps.
struct Reference {
    long double alpha, theta, a[3], k[3];
};
Reference reference(const Case& c) {
    const long double A = c.A, BA = c.BA, CB = c.CB, CA = BA + CB;
    const long double S = std::sqrt(CB * BA + (A + CB) * (A + CB));
    return {std::sqrt(static_cast<long double>(c.f) / S),
            std::atan2(std::sqrt(CB * BA), A + CB),
            {std::sqrt(BA / CA), 0.0L, -std::sqrt(CB / CA)},
            {CB * std::sqrt(BA / CA) / S, (A + CB) / S, BA * std::sqrt(CB / CA) / S}};
}

// snippet: ch05_naive
// The naive way: B and C rounded to doubles first, every difference formed from them, and
// theta from acos. Nothing wrong on paper; in floating point the gaps lose their digits.
struct Numbers {
    double alpha, theta;
    Vec3 a, k;
};
Numbers naive(const Case& c) {
    const double A = c.A, B = A + c.BA, C = B + c.CB;
    const double S = std::sqrt((C - B) * (B - A) + (A + C - B) * (A + C - B));
    const Vec3 a(std::sqrt((B - A) / (C - A)), 0, -std::sqrt((C - B) / (C - A)));
    return {std::sqrt(c.f / S), std::acos((A + C - B) / S), a,
            Vec3((C - B) * a.x() / S, (A + C - B) / S, -(B - A) * a.z() / S)};
}
// end snippet

// The largest relative error of the numbers against the reference (components that are zero
// in the reference are compared absolutely).
double worst(const Numbers& n, const Reference& r) {
    auto rel = [](double x, long double ref) {
        return static_cast<double>(ref == 0 ? std::abs(x - ref) : std::abs((x - ref) / ref));
    };
    double w = std::max(rel(n.alpha, r.alpha), rel(n.theta, r.theta));
    for (int i = 0; i < 3; ++i) w = std::max({w, rel(n.a(i), r.a[i]), rel(n.k(i), r.k[i])});
    return w;
}

}  // namespace

// The cases: C - A = 0.8 throughout the nearly symmetric ones; the flat ones have C - B = A.
std::vector<Case> extreme_cases() {
    std::vector<Case> cases = {{1.0, 0.5, 0.7, 1.0}};
    for (double eps : {1e-3, 1e-6, 1e-9}) cases.push_back({1.0, eps * 0.8, (1 - eps) * 0.8, 1.0});
    for (double eps : {1e-3, 1e-6, 1e-9}) cases.push_back({1.0, (1 - eps) * 0.8, eps * 0.8, 1.0});
    cases.push_back({1.0, 0.5, 1.0, 1.0});   // flat: A + B = C
    cases.push_back({1.0, 1e-9, 1.0, 1.0});  // flat and nearly symmetric
    cases.push_back({1.0, 0.5, 0.7, 1e-6});
    cases.push_back({1.0, 0.5, 0.7, 1e6});
    return cases;
}

struct Results {
    std::vector<std::vector<double>> table;
    double worst_gap = 0, worst_integration = 0, closed_time = 0;
    long unstable = 0, dominated = 0;
};

// Every case: the closed form against long double, both ways, and the integration against it.
Results compute(double periods) {
    Results r;
    for (const Case& c : extreme_cases()) {
        const rigid::Moments m = rigid::moments_from_gaps(c.A, c.BA, c.CB);
        rigid::GrioliPrecession g{};
        r.closed_time += kit::min_time([&] { g = rigid::grioli_precession(m, c.f, rigid::Sense::ccw); });
        const Reference ref = reference(c);
        const double e_gap = worst({g.alpha, g.theta, g.a, g.k}, ref), e_naive = worst(naive(c), ref);
        const rigid::PrecessionCheck chk = rigid::integrate_grioli(
            m, g, periods, 4, {.method = "rk8pd", .rel_tol = 1e-12, .abs_tol = 1e-12 * std::min(1.0, g.alpha)});
        // Is the error physics? The Floquet multipliers of the case's precession (Chapter 7).
        const kit::RunStability st = kit::run_stability(
            m, rigid::Sense::ccw, {periods, chk.max_rotation_error, 1e-12, kit::rk8pd_steps(chk.stats.rhs_calls)});
        r.unstable += st.stability.unstable(), r.dominated += st.verdict.dominated;
        r.worst_gap = std::max(r.worst_gap, e_gap);
        r.worst_integration = std::max(r.worst_integration, chk.max_rotation_error);
        const double CA = c.BA + c.CB;
        r.table.push_back({c.BA / CA, c.CB / CA, (c.A - c.CB) / c.A, c.f, g.theta, e_gap, e_naive,
                           chk.max_rotation_error, chk.max_energy_drift, st.stability.multiplier(),
                           st.stability.floquet.growth, st.verdict.dominated ? 1.0 : 0.0});
    }
    return r;
}

void report(kit::Scene& scene, double periods, const Results& r) {
    scene.report.headline(
        "largest relative error of alpha, theta, a, k from the gaps, against long double, over all cases", r.worst_gap,
        r.closed_time);
    scene.report.add("worst_integration_error", r.worst_integration, "max geodesic angle over the periods, every case");
    scene.report.add("periods", static_cast<long>(periods));
    scene.report.add("unstable_cases", r.unstable, "linearly unstable by the Floquet multipliers");
    scene.report.add("dominated_cases", r.dominated, "cases whose rot_error the instability dominates");
    scene.report.table("cases",
                       {"(B-A)/(C-A)", "(C-B)/(C-A)", "(A+B-C)/A", "f", "theta", "err_gaps", "err_naive", "rot_error",
                        "energy_drift", "floquet_mu", "floquet_growth", "dominated"},
                       r.table);
    scene.report.note(
        "err_gaps: closed form from the gaps; err_naive: B, C rounded first and theta by acos; both "
        "against long double. rot_error: rk8pd, tol 1e-12, over the periods.");
}

struct Params {
    long periods = 100;
};

void declare(kit::Options& opts, Params& p) {
    opts.integer("periods", &p.periods, "periods to integrate per case", 1, 10000);
}

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("grioli_extremes", "Chapter 5: nearly symmetric and flat bodies, f from 1e-6 to 1e6");
    declare(opts, p);

    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        const double periods = double(p.periods);
        // Each case: --periods periods of rk8pd, and the monodromy matrix of its precession.
        const std::size_t cases = extreme_cases().size();
        kit::require_budget(
            o, {double(cases) * periods,
                kit::seconds_per_period("rk8pd", 1e-12) + kit::monodromy_seconds(kit::monodromy_tol) / periods,
                "periods (" + std::to_string(cases) + " cases)", "--periods"});
        report(scene, periods, compute(periods));
    });
}
