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
    double error, tolerance;
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

// The largest error of each printed formula over the cases.
struct Errors {
    double e52 = 0, e53 = 0, e54[3] = {0, 0, 0}, e510 = 0, e59[2] = {0, 0}, e511 = 0, e512 = 0, e512d = 0, e513 = 0,
           e58 = 0, e515 = 0;
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

// One random body, direction and distance: every printed formula of (5.2)-(5.13).
void check_case(Errors& err, Random& random, bool with_cloud) {
    const BodyAtG b = random.body();
    const Vec3 z = rigid::shift_direction(random.uniform(-std::numbers::pi, std::numbers::pi));
    const double L = size_of(b) * std::pow(10.0, random.uniform(-2, 2)), h = b.mu * L * L;
    const Printed p = printed(b, L, z);
    const Mat3 I = tensor_at(b, L, z);
    const double scale = I.norm();
    const EigenMoments e = eigen_moments(I);
    if (with_cloud) err.e52 = std::max(err.e52, point_cloud_error(random, L, z));
    // (5.3) against the eigen-solver.
    err.e53 = std::max(
        {err.e53, std::abs(p.A() - e.A) / scale, std::abs(p.B() - e.B) / scale, std::abs(p.C() - e.C) / scale});
    // (5.4): the three forms of D against (C - A)^2; (5.10) against the last form.
    const double D_ref = (e.C - e.A) * (e.C - e.A), D_scale = (h + b.C_g + b.A_g) * (h + b.C_g + b.A_g);
    err.e54[0] = std::max(err.e54[0], std::abs(p.D1() - D_ref) / D_scale);
    err.e54[1] = std::max(err.e54[1], std::abs(p.D2() - D_ref) / D_scale);
    err.e54[2] = std::max(err.e54[2], std::abs(p.D3() - D_ref) / D_scale);
    err.e510 = std::max(err.e510, std::abs(p.D510() - p.D3()) / D_scale);
    binary128_forms(err, b, L, z, e, scale);
    // (5.13) against the eigen-solver's (B - A)/(C - A).
    err.e513 = std::max(err.e513, std::abs(p.ratio_513() - (e.B - e.A) / (e.C - e.A)) * (e.C - e.A) / scale);
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
    for (int c = 0; c < prm.cases; ++c) check_case(err, random, c < 200);
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

std::vector<Check> checks(const Errors& err) {
    const double eps = std::numeric_limits<double>::epsilon();
    return {
        {"eq_5_2", "(5.2) against the direct sum over point masses, / |I'|", err.e52, 64 * eps},
        {"eq_5_3", "(5.3) A, B, C against the eigen-solver, / |I'|", err.e53, 64 * eps},
        {"eq_5_4_first", "(5.4) first form of D against (C - A)^2, / (A_g + C_g + h)^2", err.e54[0], 64 * eps},
        {"eq_5_4_second", "(5.4) second form", err.e54[1], 64 * eps},
        {"eq_5_4_third", "(5.4) third form", err.e54[2], 64 * eps},
        {"eq_5_10", "(5.10) D = alpha^2 + 4 h^2 z_A^2 z_C^2 against (5.4), same scale", err.e510, 64 * eps},
        {"eq_5_9_first", "(5.9) first form, in binary128: the angle of v against Eigen's smallest axis (rad)",
         err.e59[0], 1e-12},
        {"eq_5_9_second", "(5.9) second form, same", err.e59[1], 1e-12},
        {"eq_5_11", "(5.11) solved for cos^2 phi, in binary128, against Eigen's axis", err.e511, 1e-12},
        {"eq_5_12", "(5.12) in binary128 against Eigen's axis", err.e512, 1e-12},
        {"eq_5_12_derivative",
         "(5.12) first equality, 1/2 + 1/2 d sqrt(D)/dh, 4th-order central difference in binary128", err.e512d, 1e-15},
        {"eq_5_13", "(5.13) against Eigen's (B - A)/(C - A), times (C - A)/|I'|", err.e513, 64 * eps},
        {"eq_5_8", "(5.8) as printed against a bisection on Eigen's C - B, / h", err.e58, 1e-9},
        {"eq_5_15_circular", "(5.14), (5.15): the section orthogonal to the line is a circle, / C_g", err.e515,
         16 * eps},
    };
}

void report(kit::Scene& scene, const Params& prm, const Errors& err, double run_time) {
    double worst = 0;
    std::string failed;
    for (const auto& c : checks(err)) {
        scene.report.add(c.key, c.error, c.what + " (tolerance " + sci(c.tolerance) + ")");
        worst = std::max(worst, c.error / c.tolerance);
        if (!(c.error <= c.tolerance)) failed += " " + c.key;
    }
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
