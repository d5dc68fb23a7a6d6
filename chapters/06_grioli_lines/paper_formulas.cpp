// Chapter 6 scene: every printed formula of [P, Sect. 6], (5.2)-(5.15), evaluated exactly as
// printed (common.hpp) on random bodies, directions and distances, against an independent
// computation: a direct mass-point sum, Eigen's SelfAdjointEigenSolver, a central difference,
// a bisection, and the circular sections of the inertia ellipsoid. Then the claims of the prose
// of Sect. 6, measured. Fails (exit 1) when a formula that the chapter says holds does not.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "common.hpp"

using namespace ch6;

namespace {

std::string sci(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0e", x);
    return buf;
}

struct Check {
    std::string key, what;
    double error, tolerance;  // tolerance 0: a bound of its own in each case
    double over;              // error / tolerance, or the largest error / bound over the cases
};

struct Params {
    int cases = 2000;
    long seed = 6;
};

void declare(kit::Options& opts, Params& p) {
    opts.integer("cases", &p.cases, "random bodies, directions and distances (L from 0.01 to 100 body sizes)", 10,
                 1000000)
        .integer("seed", &p.seed, "seed of the random cases", 0, 1000000000);
}

// The random cases: numbers uniform in [lo, hi], and bodies with sorted moments at G.
struct Random {
    std::mt19937_64 rng;
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
    BodyAtG body() {
        double s[3] = {uniform(0.05, 2), uniform(0.05, 2), uniform(0.05, 2)};
        std::sort(s, s + 3);
        return BodyAtG{s[1] + s[0], s[2] + s[0], s[2] + s[1], uniform(0.3, 3)};
    }
};

// The case of (5.13) with the largest error, and what makes it so.
struct Worst513 {
    long index = -1;          // the case, counted from 0
    double bound = 0;         // its round-off bound
    double h = 0, zA = 0;     // where: h = mu L^2, z = (zA, 0, zC)
    double D_rel = 0;         // D / (h + C_g - A_g)^2: near 0 where C -> A
    double ratio = 0;         // Eigen's (B - A)/(C - A)
    double in_binary128 = 0;  // the same printed form in binary128, same measure
};

// The largest error of each printed formula over the cases.
struct Errors {
    double e52 = 0, e53 = 0, e54[3] = {0, 0, 0}, e510 = 0, e59[2] = {0, 0}, e511 = 0, e512 = 0, e512d = 0, e513 = 0,
           e58 = 0, e515 = 0;
    double e53_over = 0, e513_over = 0;  // the largest error / bound of (5.3) and of (5.13)
    Worst513 w513;
};

// (5.2) against the direct sum over a cloud of point masses with these moments at G.
double point_cloud_error(Random& random, double L, const Vec3& z) {
    std::vector<rigid::PointMass> pts;
    Vec3 com = Vec3::Zero();
    double mass = 0;
    for (int k = 0; k < 8; ++k) {
        pts.push_back(
            {random.uniform(0.1, 2), Vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1))});
        com += pts.back().m * pts.back().x;
        mass += pts.back().m;
    }
    Mat3 IG = Mat3::Zero(), IO = Mat3::Zero();
    const Vec3 r = L * z;
    for (auto& q : pts) {
        q.x -= com / mass;
        IG += q.m * (q.x.squaredNorm() * Mat3::Identity() - q.x * q.x.transpose());
        const Vec3 x = q.x - r;
        IO += q.m * (x.squaredNorm() * Mat3::Identity() - x * x.transpose());
    }
    const Mat3 printed52 = IG + mass * L * L * (Mat3::Identity() - z * z.transpose());
    return (printed52 - IO).cwiseAbs().maxCoeff() / IO.norm();
}

// (5.9), (5.11), (5.12) evaluated in binary128 (so that their own round-off cannot hide a
// misprint) against the eigen-solver's smallest axis, where the eigen-solver resolves it (gap
// to the other moments at least 1% of |I'|): absolute errors.
void binary128_forms(Errors& err, const BodyAtG& b, double L, const Vec3& z, const EigenMoments& e, double scale) {
    const auto pq = printed_q(b, L, z);
    const bool resolved = std::min(e.C - e.A, e.B - e.A) >= 1e-2 * scale;
    const double cos2_ref = e.vA.dot(z) * e.vA.dot(z);
    if (resolved && std::abs(z.x() * z.z()) > 1e-3) {
        const double ang_ref = std::atan(e.vA.z() / e.vA.x());
        err.e59[0] = std::max(err.e59[0], std::abs(std::atan(static_cast<double>(pq.vC_over_vA_first())) - ang_ref));
        err.e59[1] = std::max(err.e59[1], std::abs(std::atan(static_cast<double>(pq.vC_over_vA())) - ang_ref));
        err.e511 = std::max(err.e511, std::abs(static_cast<double>(pq.cos2_511()) - cos2_ref));
    }
    if (!resolved) return;
    err.e512 = std::max(err.e512, std::abs(static_cast<double>(pq.cos2_512()) - cos2_ref));
    // The first form of (5.12), 1/2 + 1/2 d sqrt(D)/dh, by a fourth-order central difference in binary128.
    using q = quadref::quad;
    const q d = q(1e-6) * (pq.h + b.C_g);
    auto sqrtD = [&](q hh) {
        auto pp = pq;
        pp.h = hh;
        return root(pp.D3());
    };
    const q dsqrtD =
        (-sqrtD(pq.h + 2 * d) + 8 * sqrtD(pq.h + d) - 8 * sqrtD(pq.h - d) + sqrtD(pq.h - 2 * d)) / (12 * d);
    err.e512d = std::max(err.e512d, static_cast<double>(quadref::abs_q(q(0.5) + dsqrtD / 2 - pq.cos2_512())));
}

// snippet: round_off_bounds
// The round-off of a printed form in double, bounded in each case (u = eps / 2, the unit
// round-off). D is off by 12 u (h + C_g - A_g)^2, the size of its terms before they cancel, and
// sqrt(D) by dD / sqrt(D) + u sqrt(D): where C -> A (D -> 0, along x_C at h = C_g - A_g) that
// grows like 1 / sqrt(D). Each of Eigen's moments is within 8 eps |I'| of the exact one
// (regions_plane measures it against binary128).
struct RoundOff {
    double u, s, ds, eigen;  // u; sqrt(D) and its error; the error of one of Eigen's moments
};

RoundOff round_off(const BodyAtG& b, const Printed<double>& p, double scale) {
    const double u = std::numeric_limits<double>::epsilon() / 2, c = b.C_g - b.A_g, s = std::sqrt(p.D3());
    return {u, s, 12 * u * (p.h + c) * (p.h + c) / s + u * s, 16 * u * scale};
}

// (5.3), A, C = (A_g + C_g + h -+ sqrt(D)) / 2 and B = B_g + h, against Eigen's, / |I'|.
double bound_53(const BodyAtG& b, const Printed<double>& p, const RoundOff& r, double scale) {
    const double sum = b.A_g + b.C_g + p.h;
    return (std::max(r.u * (2 * sum + r.s) + r.ds / 2, 2 * r.u * (b.B_g + p.h)) + r.eigen) / scale;
}

// (5.13), 1/2 + N / (2 sqrt(D)) with N = 2 B_g - A_g - C_g + h, against Eigen's ratio
// r = (B - A)/(C - A), the difference times (C - A)/|I'|. N is off by 3 u (2 B_g + A_g + C_g + h),
// the ratio by dN / (2 sqrt(D)) + |N| d(sqrt D) / (2 D): near C = A that grows like 1 / D. Eigen's
// r is off by (dB + dA + r (dC + dA)) / (C - A).
double bound_513(const BodyAtG& b, const Printed<double>& p, const RoundOff& r, const EigenMoments& e, double scale) {
    const double N = 2 * b.B_g - b.A_g - b.C_g + p.h, q = N / (2 * r.s), ratio = (e.B - e.A) / (e.C - e.A);
    const double dN = 3 * r.u * (2 * b.B_g + b.A_g + b.C_g + p.h);
    const double printed =
        dN / (2 * r.s) + std::abs(N) * r.ds / (2 * r.s * r.s) + r.u * (std::abs(q) + std::abs(0.5 + q));
    const double eigen = 2 * r.eigen * (1 + std::abs(ratio)) / (e.C - e.A) + 2 * r.u * (1 + std::abs(ratio));
    return (printed + eigen) * (e.C - e.A) / scale;
}
// end snippet

// The largest error / bound so far, with a NaN kept as infinity (so that it fails).
void keep_over(double& over, double error, double bound) {
    const double x = error / bound;
    if (!(x <= over)) over = std::isnan(x) ? std::numeric_limits<double>::infinity() : x;
}

// (5.3) and (5.13) in one case, each against its bound; the worst case of (5.13) kept with what
// makes it so.
void check_53_513(Errors& err, long index, const BodyAtG& b, double L, const Vec3& z, const EigenMoments& e,
                  double scale) {
    const Printed p = printed(b, L, z);
    const RoundOff r = round_off(b, p, scale);
    const double e53 = std::max({std::abs(p.A() - e.A), std::abs(p.B() - e.B), std::abs(p.C() - e.C)}) / scale;
    err.e53 = std::max(err.e53, e53);
    keep_over(err.e53_over, e53, bound_53(b, p, r, scale));
    const double ratio = (e.B - e.A) / (e.C - e.A), error = std::abs(p.ratio_513() - ratio) * (e.C - e.A) / scale;
    const double bound = bound_513(b, p, r, e, scale);
    keep_over(err.e513_over, error, bound);
    if (!(error > err.e513) && index != 0) return;
    err.e513 = std::max(err.e513, error);
    const double c = b.C_g - b.A_g;
    const double q = static_cast<double>(quadref::abs_q(printed_q(b, L, z).ratio_513() - ratio));
    err.w513 = {index, bound, p.h, z.x(), p.D3() / ((p.h + c) * (p.h + c)), ratio, q * (e.C - e.A) / scale};
}

// One random body, direction and distance: every printed formula of (5.2)-(5.13).
void check_case(Errors& err, Random& random, long index, bool with_cloud) {
    const BodyAtG b = random.body();
    const Vec3 z = rigid::shift_direction(random.uniform(-std::numbers::pi, std::numbers::pi));
    const double L = size_of(b) * std::pow(10.0, random.uniform(-2, 2)), h = b.mu * L * L;
    const Printed p = printed(b, L, z);
    const Mat3 I = tensor_at(b, L, z);
    const double scale = I.norm();
    const EigenMoments e = eigen_moments(I);
    if (with_cloud) err.e52 = std::max(err.e52, point_cloud_error(random, L, z));
    // (5.4): the three forms of D against (C - A)^2; (5.10) against the last form.
    const double D_ref = (e.C - e.A) * (e.C - e.A), D_scale = (h + b.C_g + b.A_g) * (h + b.C_g + b.A_g);
    err.e54[0] = std::max(err.e54[0], std::abs(p.D1() - D_ref) / D_scale);
    err.e54[1] = std::max(err.e54[1], std::abs(p.D2() - D_ref) / D_scale);
    err.e54[2] = std::max(err.e54[2], std::abs(p.D3() - D_ref) / D_scale);
    err.e510 = std::max(err.e510, std::abs(p.D510() - p.D3()) / D_scale);
    binary128_forms(err, b, L, z, e, scale);
    check_53_513(err, index, b, L, z, e, scale);
}

// (5.8) against a bisection on the eigen-solver, on lines below the critical angle; (5.14)/(5.15)
// against Grioli: the plane orthogonal to the line cuts x^T I_G x = 1 in a circle.
void check_lines(Errors& err, Random& random) {
    for (int c = 0; c < 100; ++c) {
        const BodyAtG b = random.body();
        const double c2 = rigid::critical_cos2(b) * random.uniform(0.01, 0.99);
        const Vec3 z(std::sqrt(c2), 0, std::sqrt(1 - c2));
        const Crossing x = crossing_by_bisection(b, z);
        err.e58 = std::max(err.e58, std::abs(printed(b, 1.0, z).h_crit_58() - x.h()) / x.hi);
        for (int s : {1, -1}) {
            const double zA = std::sqrt((b.B_g - b.A_g) / (b.C_g - b.A_g));           // (5.14)
            const double zC = s * std::sqrt((b.C_g - b.B_g) / (b.B_g - b.A_g)) * zA;  // (5.15): x_C = +-k x_A
            const Vec3 n = Vec3(zA, 0, zC).normalized(), p = n.unitOrthogonal(), q = n.cross(p);
            const Mat3 IG = Vec3(b.A_g, b.B_g, b.C_g).asDiagonal();
            err.e515 =
                std::max({err.e515, std::abs(p.dot(IG * p) - q.dot(IG * q)) / b.C_g, std::abs(p.dot(IG * q)) / b.C_g});
        }
    }
}

Errors compute(const Params& prm) {
    Random random{std::mt19937_64(static_cast<unsigned long>(prm.seed))};
    Errors err;
    for (int c = 0; c < prm.cases; ++c) check_case(err, random, c, c < 200);
    check_lines(err, random);
    return err;
}

// The claims of the prose, measured on the default body (1, 2, 2.5), mu = 1.
void report_claims(kit::Report& report) {
    const BodyAtG b{1.0, 2.0, 2.5, 1.0};
    const double dBA = 1.0, dCB = 0.5;
    // "C(h) and A(h) are increasing": along x_A, A stays A_g.
    const double A_far_on_xA = rigid::shifted_moments(b, 1e3, Vec3::UnitX()).A - b.A_g;
    // "the smallest axis always remains smallest": along x_C it turns from x_A to x_C at h = C_g - A_g.
    const double axis_before = rigid::principal_frame(b, std::sqrt(1.4), Vec3::UnitZ()).R(0, 0);
    const double axis_after = rigid::principal_frame(b, std::sqrt(1.6), Vec3::UnitZ()).R(2, 0);
    // "C(h) -> B(h) along an asymptote": h (C - B) -> (B_g - A_g)(C_g - B_g).
    const double h_big = 1e8;
    const double rate = rigid::grioli_suspension(b, std::sqrt(h_big), 1).frame.moments.C_minus_B * h_big / (dBA * dCB);
    // "in the limit L -> infinity [the smallest axis] coincides with the centre-of-mass axis":
    // sin^2 phi h^2 -> (C_g - A_g)^2 sin^2(2 phi_g) / 4.
    const Vec3 z45 = rigid::shift_direction(std::numbers::pi / 4);
    const double sin2_rate = rigid::smallest_axis_tilt(b, 1e4, z45).sin2 * 1e16 / (1.5 * 1.5 / 4);
    // "on the hyperbola ... can experience a regular precession": where is G there?
    const Vec3 zb(std::sqrt(1.0 / 3), 0, std::sqrt(2.0 / 3));
    const double cos2_hyperbola = rigid::smallest_axis_tilt(b, std::sqrt(rigid::critical_h(b, zb)), zb).cos2;
    report.add("claim_A_increasing", A_far_on_xA, "A(L = 1000) - A_g along x_A: 0, so A is only non-decreasing");
    report.add("claim_smallest_axis_before", axis_before, "R_A . x_A along x_C at h = 1.4 < C_g - A_g");
    report.add("claim_smallest_axis_after", axis_after, "R_A . x_C along x_C at h = 1.6 > C_g - A_g: the axis jumped");
    report.add("claim_asymptote_rate", rate, "h (C - B) / ((B_g - A_g)(C_g - B_g)) at h = 1e8 on a Grioli line: -> 1");
    report.add("claim_axis_limit_rate", sin2_rate, "h^2 sin^2 phi / ((C_g - A_g)^2 sin^2 2phi_g / 4) at h = 1e8: -> 1");
    report.add("claim_hyperbola_cos2_phi", cos2_hyperbola,
               "cos^2 (R_A, z) where B = C on cos^2 phi_g = 1/3: G is off the symmetry axis");
}

Check fixed(std::string key, std::string what, double error, double tolerance) {
    return {std::move(key), std::move(what), error, tolerance, error / tolerance};
}

std::vector<Check> checks(const Errors& err) {
    const double eps = std::numeric_limits<double>::epsilon();
    return {
        fixed("eq_5_2", "(5.2) against the direct sum over point masses, / |I'|", err.e52, 64 * eps),
        {"eq_5_3", "(5.3) A, B, C against the eigen-solver, / |I'|", err.e53, 0, err.e53_over},
        fixed("eq_5_4_first", "(5.4) first form of D against (C - A)^2, / (A_g + C_g + h)^2", err.e54[0], 64 * eps),
        fixed("eq_5_4_second", "(5.4) second form", err.e54[1], 64 * eps),
        fixed("eq_5_4_third", "(5.4) third form", err.e54[2], 64 * eps),
        fixed("eq_5_10", "(5.10) D = alpha^2 + 4 h^2 z_A^2 z_C^2 against (5.4), same scale", err.e510, 64 * eps),
        fixed("eq_5_9_first", "(5.9) first form, in binary128: the angle of v against Eigen's smallest axis (rad)",
              err.e59[0], 1e-12),
        fixed("eq_5_9_second", "(5.9) second form, same", err.e59[1], 1e-12),
        fixed("eq_5_11", "(5.11) solved for cos^2 phi, in binary128, against Eigen's axis", err.e511, 1e-12),
        fixed("eq_5_12", "(5.12) in binary128 against Eigen's axis", err.e512, 1e-12),
        fixed("eq_5_12_derivative",
              "(5.12) first equality, 1/2 + 1/2 d sqrt(D)/dh, 4th-order central difference in binary128", err.e512d,
              1e-15),
        {"eq_5_13", "(5.13) against Eigen's (B - A)/(C - A), times (C - A)/|I'|", err.e513, 0, err.e513_over},
        fixed("eq_5_8", "(5.8) as printed against a bisection on Eigen's C - B, / h", err.e58, 1e-9),
        fixed("eq_5_15_circular", "(5.14), (5.15): the section orthogonal to the line is a circle, / C_g", err.e515,
              16 * eps),
    };
}

// (5.3) and (5.13): the largest error / bound; the case of (5.13)'s largest error.
void report_worst_513(kit::Report& report, const Errors& err) {
    const Worst513& w = err.w513;
    report.add("eq_5_3_over_bound", err.e53_over, "the largest error / bound of (5.3) over the cases: at most 1");
    report.add("eq_5_13_over_bound", err.e513_over, "the largest error / bound of (5.13) over the cases: at most 1");
    report.add("eq_5_13_worst_case", w.index, "the case of the largest error, counted from 0");
    report.add("eq_5_13_worst_bound", w.bound, "its round-off bound");
    report.add("eq_5_13_worst_h", w.h, "its h = mu L^2");
    report.add("eq_5_13_worst_zA", w.zA, "its z_A: near 0 and h near C_g - A_g is where C -> A");
    report.add("eq_5_13_worst_D_rel", w.D_rel, "its D / (h + C_g - A_g)^2: the cancellation in D");
    report.add("eq_5_13_worst_ratio", w.ratio, "its (B - A)/(C - A), from Eigen");
    report.add("eq_5_13_worst_binary128", w.in_binary128, "the same printed form in binary128, same measure");
}

void report(kit::Scene& scene, const Params& prm, const Errors& err, double run_time) {
    double worst = 0;
    std::string failed;
    for (const auto& c : checks(err)) {
        const std::string tolerance = c.tolerance > 0 ? sci(c.tolerance) : "its round-off bound in each case";
        scene.report.add(c.key, c.error, c.what + " (tolerance " + tolerance + ")");
        worst = std::max(worst, c.over);
        if (!(c.over <= 1)) failed += " " + c.key;
    }
    report_worst_513(scene.report, err);
    scene.report.headline("max error / tolerance over the printed formulas (5.2)-(5.15)", worst, run_time);
    scene.report.add("cases", static_cast<long>(prm.cases));
    report_claims(scene.report);
    if (!failed.empty()) throw kit::NumericalFailure("printed formulas out of tolerance:" + failed);
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("paper_formulas",
                      "Chapter 6: every printed formula of [P, Sect. 6] against an independent computation");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options& o, kit::Scene& scene) {
        kit::require_budget(
            o, {double(p.cases), 2e-5, "cases (each every printed formula, in double and binary128)", "--cases"});
        const auto t0 = std::chrono::steady_clock::now();
        const Errors err = compute(p);
        const double run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        report(scene, p, err, run_time);
    });
}
