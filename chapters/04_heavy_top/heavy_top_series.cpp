// Chapter 4 scene: the trigonometric series of [P, (3.5), (3.6)] for the Euler vector E and
// the torque T along a trial precession, checked coefficient by coefficient.
//
// E(t) and T(t) are evaluated directly (rigid::euler_vector, rigid::torque) at N instants of
// one common period and decomposed numerically on the eleven functions of the series (least
// squares; with alpha = 3, beta = 5 every frequency 0, 2, 3, 5, 6, 8 is resolved on [0, 2 pi)).
// --beta takes another whole beta, unless two frequencies of the series then coincide.
// Each coefficient vector is compared with [P]'s printed one and with the corrected one of
// rigid::euler_vector_series / rigid::torque_series.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "figure.hpp"
#include "heavy_top_series.gp.hpp"
#include "rigid/heavy_top.hpp"
#include "scene.hpp"

using rigid::Mat3;
using rigid::PrecessionSeries;
using rigid::Vec3;

namespace {

const char* names[11] = {"constant",       "cos(alpha t)",  "sin(alpha t)", "cos(2 alpha t)",
                         "sin(2 alpha t)", "cos(beta t)",   "sin(beta t)",  "cos(gamma+ t)",
                         "sin(gamma+ t)",  "cos(gamma- t)", "sin(gamma- t)"};

std::vector<Vec3> rows_of(const PrecessionSeries& s) {
    return {s.constant, s.cos_alpha, s.sin_alpha, s.cos_2alpha, s.sin_2alpha, s.cos_beta,
            s.sin_beta, s.cos_plus,  s.sin_plus,  s.cos_minus,  s.sin_minus};
}

// snippet: ch04_printed_series
// [P, (3.5)] as printed, with its constant's factor A = (beta b2)^2/2 - (alpha + beta b3)^2.
PrecessionSeries printed_E(const Mat3& J, double alpha, double beta, double b3) {
    const double b2 = std::sqrt(1 - b3 * b3), w = alpha + beta * b3, bb = beta * b2, half = bb * bb / 2;
    PrecessionSeries E;
    E.constant = (half - w * w) * Vec3(J(1, 2), -J(0, 2), 0);
    E.cos_alpha =
        bb * Vec3(w * (J(2, 2) - J(1, 1)) + alpha * J(0, 0), (2 * alpha + beta * b3) * J(0, 1), -beta * b3 * J(0, 2));
    E.sin_alpha =
        bb * Vec3(-(2 * alpha + beta * b3) * J(0, 1), w * (J(0, 0) - J(2, 2)) - alpha * J(1, 1), beta * b3 * J(1, 2));
    E.cos_2alpha = half * Vec3(J(1, 2), J(0, 2), -2 * J(0, 1));
    E.sin_2alpha = half * Vec3(J(0, 2), -J(1, 2), 2 * (J(1, 1) - J(0, 0)));
    return E;
}

// [P, (3.6)] as printed: its last two terms both multiply cos(gamma_- t).
PrecessionSeries printed_T(const Vec3& k, const Vec3& z, double b3) {
    const double b2 = std::sqrt(1 - b3 * b3), n = b2 * k.y() + b3 * k.z(), p = b3 * k.y() - b2 * k.z();
    PrecessionSeries T;
    T.constant = b3 * n * Vec3(-z.y(), z.x(), 0);
    T.cos_alpha = b2 * n * Vec3(z.z(), 0, -z.x());
    T.sin_alpha = b2 * n * Vec3(0, -z.z(), z.y());
    T.cos_beta = b2 * p * Vec3(z.y(), -z.x(), 0);
    T.cos_plus = (1 + b3) * p / 2 * Vec3(z.z(), 0, -z.x());
    T.sin_plus = (1 + b3) * p / 2 * Vec3(0, -z.z(), z.y());
    T.cos_minus = (1 + b3) * p / 2 * Vec3(-z.z(), 0, z.x()) + (1 - b3) * p / 2 * Vec3(0, z.z(), -z.y());
    return T;
}
// end snippet

// snippet: ch04_fourier_fit
// The numerical decomposition: least squares of v(t_j), t_j = 2 pi j / N, on the eleven
// functions of the series. Row i of the result is the coefficient vector of function i.
template <class F>
std::vector<Vec3> fourier_fit(F v, double alpha, double beta, int N) {
    Eigen::MatrixXd G(N, 11), Y(N, 3);
    for (int j = 0; j < N; ++j) {
        const double t = 2 * std::numbers::pi * j / N, gp = (alpha + beta) * t, gm = (alpha - beta) * t;
        G.row(j) << 1, std::cos(alpha * t), std::sin(alpha * t), std::cos(2 * alpha * t), std::sin(2 * alpha * t),
            std::cos(beta * t), std::sin(beta * t), std::cos(gp), std::sin(gp), std::cos(gm), std::sin(gm);
        Y.row(j) = v(t).transpose();
    }
    const Eigen::MatrixXd X = G.colPivHouseholderQr().solve(Y);
    std::vector<Vec3> rows;
    for (int i = 0; i < 11; ++i) rows.push_back(X.row(i).transpose());
    return rows;
}
// end snippet

struct Params {
    int beta = 5;  // alpha = 3: beta / alpha = 5/3
    double b3 = 0.37;
    double k_angle = 0.8;
    Vec3 z0 = Vec3(0.3, -0.5, 0.8);
    int samples = 64;
};

void declare(kit::Options& opts, Params& p) {
    opts.real("b3", &p.b3, "third component of the precession vector b = (0, b2, b3), [P, (3.3)]",
              kit::between(-0.99, 0.99))
        .real("k-angle", &p.k_angle, "direction of k = (0, cos, sin) in the plane of a and b (radians)",
              kit::between(-10, 10))
        .vector("z0", &p.z0, "centre-of-mass direction z(0) (normalised)", kit::nonzero_vector(-1e3, 1e3))
        .integer(
            "samples", &p.samples,
            "samples N over the period 2 pi (at least 11, one per function fitted; 2 (alpha + beta) + 1 resolve every "
            "frequency: 17 at beta = 5, 31 at beta = 12)",
            11, 4096)
        .integer("beta", &p.beta,
                 "the precession's frequency beta, a whole number (alpha = 3): beta / alpha = beta / 3", 1, 12);
}

// The eleven functions are independent only if the frequencies alpha, 2 alpha, beta,
// alpha + beta, |alpha - beta| differ (and none is 0): beta = alpha, 2 alpha, 3 alpha make two
// of them one, Lemma 1's Case 3, Case 2 and the ratio 3 (|gamma_-| = 2 alpha).
void check(const Params& p) {
    if (p.beta == 3 || p.beta == 6 || p.beta == 9)
        throw kit::BadInput("--beta: got " + std::to_string(p.beta) +
                            "; it must not be 3, 6 or 9 (alpha = 3): beta = alpha, 2 alpha or 3 alpha makes two "
                            "frequencies of the series one (Lemma 1's Case 3, Case 2, |gamma_-| = 2 alpha), and the "
                            "decomposition cannot tell their terms apart");
}

// The trial motion, and the 11 coefficient vectors of E and of T: numerical, from the series
// corrected, and as printed.
struct Series {
    double alpha = 3, beta = 5;  // whole numbers: one common period 2 pi
    Vec3 b, k, z0;
    std::vector<Vec3> numE, numT, corE, corT, prE, prT;
    double run_time;
};

Series compute(const Params& prm) {
    Series s;
    s.beta = prm.beta;
    const double b3 = prm.b3, b2 = std::sqrt(1 - b3 * b3), phi = prm.k_angle;
    const double alpha = s.alpha, beta = s.beta;
    Mat3 J;  // a general symmetric J: the lab axes are not inertia axes
    J << 2.1, 0.3, -0.2, 0.3, 1.7, 0.45, -0.2, 0.45, 2.6;
    const Vec3 a = Vec3::UnitZ();
    s.b = Vec3(0, b2, b3), s.k = Vec3(0, std::cos(phi), std::sin(phi)), s.z0 = prm.z0.normalized();
    const rigid::TrialPrecession p{a, alpha, s.b, beta};
    PrecessionSeries serE, serT;
    s.run_time = kit::min_time(
        [&] {
            s.numE = fourier_fit([&](double t) { return rigid::euler_vector(J, p, t); }, alpha, beta, prm.samples);
            s.numT = fourier_fit([&](double t) { return rigid::torque(s.k, s.z0, p, t); }, alpha, beta, prm.samples);
            serE = rigid::euler_vector_series(J, alpha, beta, b3);
            serT = rigid::torque_series(s.k, s.z0, alpha, beta, b3);
        },
        3);
    s.corE = rows_of(serE), s.corT = rows_of(serT);
    s.prE = rows_of(printed_E(J, alpha, beta, b3)), s.prT = rows_of(printed_T(s.k, s.z0, b3));
    return s;
}

std::string xyz(const Vec3& v) {
    std::string s(1, '(');
    s += std::to_string(v.x());
    s += ", ";
    s += std::to_string(v.y());
    s += ", ";
    s += std::to_string(v.z());
    return s += ')';
}

// Coefficient by coefficient, printed and corrected against numerical: the table (term,
// E_printed, E_corrected, T_printed, T_corrected) and a note for every printed one that is off.
std::vector<std::vector<double>> compare(kit::Report& report, const Series& s) {
    double scaleE = 0, scaleT = 0;
    for (int i = 0; i < 11; ++i)
        scaleE = std::max(scaleE, s.numE[i].norm()), scaleT = std::max(scaleT, s.numT[i].norm());
    std::vector<std::vector<double>> table;
    for (int i = 0; i < 11; ++i) {
        const double pe = (s.prE[i] - s.numE[i]).norm() / scaleE, ce = (s.corE[i] - s.numE[i]).norm() / scaleE;
        const double pt = (s.prT[i] - s.numT[i]).norm() / scaleT, ct = (s.corT[i] - s.numT[i]).norm() / scaleT;
        table.push_back({double(i), pe, ce, pt, ct});
        if (pe > 1e-10)
            report.note("(3.5) " + std::string(names[i]) + ": printed " + xyz(s.prE[i]) + ", numerical " +
                        xyz(s.numE[i]));
        if (pt > 1e-10)
            report.note("(3.6) " + std::string(names[i]) + ": printed " + xyz(s.prT[i]) + ", numerical " +
                        xyz(s.numT[i]));
    }
    return table;
}

void report(kit::Scene& scene, const Params& p, const Series& s, const std::vector<std::vector<double>>& table) {
    double worst_corrected = 0;
    for (const auto& row : table) worst_corrected = std::max({worst_corrected, row[2], row[4]});
    scene.report.headline("max over the 22 coefficient vectors of |corrected - numerical| / largest coefficient",
                          worst_corrected, s.run_time);
    scene.report.add("alpha", s.alpha);
    scene.report.add("beta", s.beta);
    scene.report.add("b", s.b);
    scene.report.add("k", s.k);
    scene.report.add("z0", s.z0);
    scene.report.add("samples", static_cast<long>(p.samples));
    scene.report.table("coefficients", {"term", "E_printed", "E_corrected", "T_printed", "T_corrected"}, table);
    scene.report.note(
        "terms: 0 constant, 1-2 cos/sin(alpha t), 3-4 cos/sin(2 alpha t), 5-6 cos/sin(beta t), "
        "7-8 cos/sin(gamma+ t), 9-10 cos/sin(gamma- t); errors relative to the largest coefficient");
}

void draw(kit::Scene& scene, const std::vector<std::vector<double>>& table) {
    std::vector<std::vector<double>> figE, figT;
    for (const auto& r : table) {
        figE.push_back({r[0], std::max(r[1], 1e-17), std::max(r[2], 1e-17)});
        figT.push_back({r[0], std::max(r[3], 1e-17), std::max(r[4], 1e-17)});
    }
    kit::Figure fig(scene, "series_check.svg", 860, 520);
    fig.script(kit::gp::heavy_top_series);
    fig.data(figE).data(figE).data(figT).data(figT);
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("heavy_top_series",
                      "Chapter 4: the series (3.5)-(3.6) for E and T against a numerical Fourier decomposition");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options&, kit::Scene& scene) {
        check(p);
        const Series s = compute(p);
        const auto table = compare(scene.report, s);
        report(scene, p, s, table);
        draw(scene, table);
    });
}
