// Chapter 5 scene: [P, Sect. 5, (4.1)-(4.15)] line by line. The series (4.2) and (4.3) against
// a numerical Fourier decomposition; the sign argument after (4.4); the pair (4.8); k_B = cos
// theta after (4.11); and case (2), (4.12)-(4.15), which [P] calls the clockwise precession,
// compared with case (1) half a period later.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "heavy_body.hpp"
#include "rigid/grioli.hpp"
#include "rigid/heavy_top.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

using rigid::Mat3;
using rigid::Vec3;
using std::numbers::pi;

namespace {

// Constant, cos/sin(alpha t), cos/sin(2 alpha t) coefficients of v over one period 2 pi/alpha.
template <class F>
std::vector<Vec3> fourier(F v, double alpha, int N = 32) {
    std::vector<Vec3> c(5, Vec3::Zero());
    for (int j = 0; j < N; ++j) {
        const double t = 2 * pi * j / N / alpha, x = alpha * t;
        const Vec3 y = v(t);
        c[0] += y / N;
        c[1] += 2 * y * std::cos(x) / N;
        c[2] += 2 * y * std::sin(x) / N;
        c[3] += 2 * y * std::cos(2 * x) / N;
        c[4] += 2 * y * std::sin(2 * x) / N;
    }
    return c;
}

double max_diff(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
    return d;
}

// snippet: ch05_printed_42
// [P, (4.2)] as printed, read as E / alpha^2, and (4.3), with I = (I1, I2, I3), a = (a1, 0, a3).
std::vector<Vec3> printed_E(const Vec3& I, const Vec3& a, double eb) {
    const double a1 = a.x(), a3 = a.z(), I31 = I(2) - I(0), I32 = I(2) - I(1), I21 = I(1) - I(0);
    return {Vec3(0, -0.5 * I31 * a1 * a3, 0), Vec3(a3, 0, -a1) * eb * (I(0) + I32), Vec3(0, -eb * (I(0) + I32), 0),
            Vec3(0, -0.5 * I31 * a1 * a3, 0), 0.5 * Vec3(-I32 * a1, 0, I21 * a3)};
}
std::vector<Vec3> printed_T(const Vec3& a, const Vec3& k, double eb) {
    const double a1 = a.x(), a3 = a.z(), ak = a.dot(k);
    return {0.5 * Vec3(eb * ak * a3, k.z() * a1 - k.x() * a3, -eb * ak * a1), Vec3(a3 * k.y(), 0, -a1 * k.y()),
            Vec3(0, -k.y(), 0), 0.5 * Vec3(-eb * ak * a3, k.z() * a1 - k.x() * a3, eb * ak * a1),
            0.5 * Vec3(ak * a1 - k.x(), eb * ak, ak * a3 - k.z())};
}
// end snippet

// What every check below reads: the body, f, and its counter-clockwise precession.
struct Setup {
    rigid::Moments m;
    double f;
    Vec3 I;
    Mat3 J;
    rigid::GrioliPrecession g;
    double alpha;
};

Setup setup(const kit::HeavyBody& body) {
    const rigid::Moments m = kit::grioli_moments(body.moments, 1e3);
    const Vec3 I(m.A, m.B, m.C);
    const rigid::GrioliPrecession g = rigid::grioli_precession(m, body.f, rigid::Sense::ccw);
    return {m, body.f, I, I.asDiagonal(), g, g.alpha};
}

// Each check adds its numbers to the report and returns the largest deviation of a statement
// the chapter makes.

// (4.2), (4.3) for a general a = (a1, 0, a3) and k (not a precession), both eps_b; then with a of (4.10).
double series_4_2_4_3(kit::Report& report, const Setup& u) {
    const Vec3& I = u.I;
    const Mat3& J = u.J;
    const double alpha = u.alpha;
    double corrected = 0;
    const Vec3 a_gen = Vec3(std::cos(0.7), 0, -std::sin(0.7)), k_gen = Vec3(0.3, 0.8, 0.5).normalized();
    std::vector<std::vector<double>> rows;
    for (double eb : {1.0, -1.0}) {
        const rigid::TrialPrecession p{a_gen, alpha, eb * Vec3::UnitY(), alpha};
        const auto E = fourier([&](double t) { return Vec3(rigid::euler_vector(J, p, t) / (alpha * alpha)); }, alpha);
        const auto T = fourier([&](double t) { return rigid::torque(k_gen, a_gen, p, t); }, alpha);
        auto pE = printed_E(I, a_gen, eb);
        const double dE_printed = max_diff(pE, E), dT = max_diff(printed_T(a_gen, k_gen, eb), T);
        // The sin(alpha t) term in general: -eps_b (I2 + I_(3-1) (a3^2 - a1^2)) e2.
        pE[2] = Vec3(0, -eb * (I(1) + (I(2) - I(0)) * (a_gen.z() * a_gen.z() - a_gen.x() * a_gen.x())), 0);
        const double dE_corrected = max_diff(pE, E);
        corrected = std::max({corrected, dE_corrected, dT});
        rows.push_back({eb, dE_printed, dE_corrected, dT});
    }
    report.table("series_4_2_4_3", {"eps_b", "E_printed", "E_sin_corrected", "T_printed"}, rows);
    // With a of (4.10), which obeys (4.8), the printed sin term is right.
    const rigid::TrialPrecession p{u.g.a, alpha, Vec3::UnitY(), alpha};
    const auto E = fourier([&](double t) { return Vec3(rigid::euler_vector(J, p, t) / (alpha * alpha)); }, alpha);
    const double d = max_diff(printed_E(I, u.g.a, 1.0), E);
    report.add("E_printed_with_a_of_4_10", d, "(4.2) holds once a obeys (4.8)");
    return std::max(corrected, d);
}

// After (4.4): "this implies eps_b = +1". The reversed motion, eps_a = eps_b = -1, solves too.
// (4.8), and after (4.11): cos theta is k_B, not k_A.
double signs_and_4_8(kit::Report& report, const Setup& u) {
    const rigid::Moments& m = u.m;
    const rigid::GrioliPrecession& g = u.g;
    const double r_pp = rigid::precession_residual(rigid::grioli_top(m, g), {g.a, u.alpha, g.b, u.alpha});
    const double r_mm = rigid::precession_residual(rigid::grioli_top(m, g), {-g.a, u.alpha, -g.b, u.alpha});
    const double r_pm = rigid::precession_residual(rigid::grioli_top(m, g), {g.a, u.alpha, -g.b, u.alpha});
    report.add("residual_eps_a_plus_eps_b_plus", r_pp);
    report.add("residual_eps_a_minus_eps_b_minus", r_mm, "z(0) = -a, b = -R_2(0): the clockwise precession");
    report.add("residual_eps_a_plus_eps_b_minus", r_pm, "not a precession: the condition is eps_a eps_b = +1");
    // (4.8): I_(3-1) a1^2 = I_(2-1) and, for the second, I_(3-1) a3^2 = I_(3-2).
    const double e48a = std::abs((m.C - m.A) * g.a.x() * g.a.x() - (m.B - m.A));
    const double e48b = std::abs((m.C - m.A) * g.a.z() * g.a.z() - (m.C - m.B));
    report.add("eq_4_8_first", e48a, "I_(3-1) a1^2 - I_(2-1)");
    report.add("eq_4_8_second_corrected", e48b, "I_(3-1) a3^2 - I_(3-2)");
    report.add("cos_theta", std::cos(g.theta));
    report.add("k_A", g.k.x());
    report.add("k_B", g.k.y());
    return std::max({r_pp, r_mm, e48a, e48b, std::abs(std::cos(g.theta) - g.k.y())});
}

// Case (2): the frame (R_C, R_B, R_A), I = (C, B, A), a (4.13), k (4.15).
double case_2(kit::Report& report, const Setup& u) {
    const rigid::Moments& m = u.m;
    const rigid::GrioliPrecession& g = u.g;
    const double alpha = u.alpha;
    const double S = rigid::grioli_root(m), pA = std::sqrt(m.B_minus_A / (m.C - m.A)),
                 qC = std::sqrt(m.C_minus_B / (m.C - m.A));
    const Vec3 I2(m.C, m.B, m.A), a2(-qC, 0, pA),
        k2(m.B_minus_A * qC / S, (m.A + m.C_minus_B) / S, m.C_minus_B * pA / S);
    const rigid::HeavyTop top2 = rigid::heavy_top(I2.asDiagonal(), u.f, k2, a2);
    const double r2_ccw = rigid::precession_residual(top2, {a2, alpha, Vec3::UnitY(), alpha});
    const double r2_cw = rigid::precession_residual(top2, {-a2, alpha, -Vec3::UnitY(), alpha});
    report.add("case2_residual_R_b(alpha t)R_a(alpha t)", r2_ccw,
               "counter-clockwise about b (k_2 > 0) in its own frame");
    report.add("case2_residual_R_b(-alpha t)R_a(-alpha t)", r2_cw);
    // Case (2) in the right-handed frame (R_A, R_B, R_C) (R_A = -R_3), then turned by pi
    // about R_C so that z(0) is the a of (4.10): compare with case (1) at t = T/2.
    auto to_abc = [](const Vec3& v) { return Vec3(-v.z(), v.y(), v.x()); };
    const Mat3 D = Vec3(-1, -1, 1).asDiagonal();
    const Vec3 z2 = D * to_abc(a2), kk2 = D * to_abc(k2), W2 = D * to_abc(alpha * (a2 + Vec3::UnitY()));
    const double half = pi / alpha;
    const Mat3 Rh = rigid::grioli_rotation(g, half);
    const double d_case2 = std::max({(z2 - g.z0).norm(), (kk2 - Rh.transpose() * g.k).norm(),
                                     (W2 - rigid::grioli_angular_velocity(g, half)).norm() / alpha});
    report.add("case2_minus_case1_at_half_period", d_case2,
               "max |difference| of z(0), k and Omega / alpha in the body frame");
    return std::max({r2_ccw, r2_cw, d_case2});
}

}  // namespace

int main(int argc, char** argv) {
    kit::HeavyBody body;
    kit::Options opts("lemma2_checks", "Chapter 5: (4.2)-(4.15) checked line by line, and case (2) against case (1)");
    kit::heavy_body_options(opts, body);
    return kit::run(argc, argv, opts, [&](const kit::Options&, kit::Scene& scene) {
        const Setup u = setup(body);
        const auto t0 = std::chrono::steady_clock::now();
        const double corrected =
            std::max({series_4_2_4_3(scene.report, u), signs_and_4_8(scene.report, u), case_2(scene.report, u)});
        const double run_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        scene.report.headline(
            "largest deviation of the corrected statements of (4.2)-(4.15) (residuals, coefficients, "
            "case (2) = case (1) at T/2)",
            corrected, run_time);
    });
}
