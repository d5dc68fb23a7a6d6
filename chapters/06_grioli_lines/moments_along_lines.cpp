// Chapter 6 scene, Figures 6 and 7 of [P]: the three moments at O against the distance L,
// along four lines through G: phi_g = pi/2 and a line below the critical angle (Figure 6,
// where B and C change places at h_crit), phi_g = 0 and a line above it (Figure 7, where
// they never do).
//
// Checked against Eigen's SelfAdjointEigenSolver at every plotted point, and h_crit against
// a bisection on the eigen-solver's C - B.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "common.hpp"
#include "figure.hpp"
#include "moments_along_lines.gp.hpp"

using namespace ch6;

namespace {

struct Line {
    std::string title;
    Vec3 z;
};

// Where the eigen-solver's C - B changes sign along z (bisection), or -1 if not below h_max.
double bisect_crossing(const BodyAtG& b, const Vec3& z, double h_max) {
    auto g = [&](double h) {
        const EigenMoments e = eigen_moments(tensor_at(b, std::sqrt(h / b.mu), z));
        return e.C - e.B;
    };
    if (g(h_max) > 0) return -1;
    double lo = 0, hi = h_max;
    for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) (g(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
}

struct Params {
    rigid::BodyAtG body = ch6::default_body;
    double below = 0.5;
    double above = 0.5;
    int points = 241;
};

void declare(kit::Options& opts, Params& p) {
    ch6::body_options(opts, p.body);
    opts.real("below", &p.below, "the line of Figure 6(b): cos^2 phi_g as a fraction of the critical value (5.6)",
              kit::between(0.0, 1.0))
        .real("above", &p.above, "the line of Figure 7(b): (cos^2 phi_g - critical)/(1 - critical)",
              kit::between(0.0, 1.0))
        .integer("points", &p.points, "distances per line", 11, 20001);
}

// The four lines of Figures 6 and 7: (a) and (b) below the critical angle, then above it.
std::vector<Line> lines_of(const BodyAtG& b, const Params& p) {
    const double crit = rigid::critical_cos2(b);
    if (!(p.below > 0 && p.below < 1))
        throw kit::BadInput("--below: got " + std::to_string(p.below) + "; it must lie strictly between 0 and 1");
    if (!(p.above > 0 && p.above < 1))
        throw kit::BadInput("--above: got " + std::to_string(p.above) + "; it must lie strictly between 0 and 1");
    const double c_below = p.below * crit, c_above = crit + p.above * (1 - crit);
    return {
        {"(a) φ_g = π/2", Vec3::UnitZ()},
        {"(b) cos^2 φ_g = " + std::to_string(c_below).substr(0, 5) + " < critical " + std::to_string(crit).substr(0, 5),
         Vec3(std::sqrt(c_below), 0, std::sqrt(1 - c_below))},
        {"(a) φ_g = 0", Vec3::UnitX()},
        {"(b) cos^2 φ_g = " + std::to_string(c_above).substr(0, 5) + " > critical " + std::to_string(crit).substr(0, 5),
         Vec3(std::sqrt(c_above), 0, std::sqrt(1 - c_above))},
    };
}

// Closed forms and the eigen-solver at every distance of every line: a curve per line, rows
// L, A, B, C (closed form), A, B, C (eigen-solver).
struct Curves {
    double L_max;
    std::vector<std::vector<std::vector<double>>> curves;
    double err = 0, min_slope_A = 1e300, min_slope_C = 1e300;
};

Curves compute(const BodyAtG& b, const std::vector<Line>& lines, int n) {
    const double h_b = rigid::critical_h(b, lines[1].z);
    Curves c{1.6 * std::sqrt(std::max(h_b, b.C_g - b.A_g) / b.mu),
             std::vector<std::vector<std::vector<double>>>(lines.size())};
    for (std::size_t l = 0; l < lines.size(); ++l) {
        rigid::ShiftedMoments prev{};
        for (int i = 0; i < n; ++i) {
            const double L = c.L_max * std::max(i, 1) / (n - 1);
            const rigid::ShiftedMoments m = rigid::shifted_moments(b, L, lines[l].z);
            const Mat3 I = tensor_at(b, L, lines[l].z);
            const EigenMoments e = eigen_moments(I);
            c.err = std::max({c.err, std::abs(m.A - e.A) / I.norm(), std::abs(m.B - e.B) / I.norm(),
                              std::abs(m.C - e.C) / I.norm()});
            c.curves[l].push_back({L, m.A, m.B, m.C, e.A, e.B, e.C});
            if (i > 1) {
                c.min_slope_A = std::min(c.min_slope_A, m.A - prev.A);
                c.min_slope_C = std::min(c.min_slope_C, m.C - prev.C);
            }
            prev = m;
        }
    }
    return c;
}

// The run time of one closed-form evaluation and of one eigen-solver call, on the line z_b.
std::pair<double, double> run_times(const BodyAtG& b, const Vec3& z_b, double L_probe) {
    const double t_closed =
        kit::time_per_call([&](int i) { return rigid::shifted_moments(b, L_probe * (1 + 1e-4 * i), z_b).C_minus_B; });
    const double t_eigen =
        kit::time_per_call([&](int i) { return eigen_moments(tensor_at(b, L_probe * (1 + 1e-4 * i), z_b)).C; });
    return {t_closed, t_eigen};
}

void report(kit::Scene& scene, const BodyAtG& b, const std::vector<Line>& lines, const Curves& c) {
    const double dCA = b.C_g - b.A_g, h_b = rigid::critical_h(b, lines[1].z);
    const auto [t_closed, t_eigen] = run_times(b, lines[1].z, 0.5 * c.L_max);
    // h_crit (5.8) against the bisection, on both lines of Figure 6.
    const double h_max = 100 * std::max(h_b, dCA);
    double err_hcrit = 0;
    for (int l : {0, 1}) {
        const double h_bis = bisect_crossing(b, lines[l].z, h_max);
        err_hcrit = std::max(err_hcrit, std::abs(rigid::critical_h(b, lines[l].z) - h_bis) / h_bis);
    }
    // On the hyperbola the body is dynamically symmetric about R_A; where is its centre of mass?
    const double cos2_at_crossing = rigid::smallest_axis_tilt(b, std::sqrt(h_b / b.mu), lines[1].z).cos2;
    scene.report.headline("max |closed form - eigen-solver| / |I'| for A, B, C over the four lines", c.err, t_closed);
    scene.report.add("run_time_eigen_s", t_eigen, "per SelfAdjointEigenSolver call, for comparison");
    scene.report.add("critical_cos2", rigid::critical_cos2(b), "(5.6)");
    scene.report.add("h_crit_below", h_b, "(5.8) on the line of Figure 6(b)");
    scene.report.add("h_crit_phi_pi2", rigid::critical_h(b, Vec3::UnitZ()), "(5.8) along x_C: C_g - B_g");
    scene.report.add("h_crit_rel_error", err_hcrit, "(5.8) against a bisection on the eigen-solver");
    scene.report.add("h_A_meets_C_phi_pi2", dCA,
                     "along x_C, A = C at h = C_g - A_g: the smallest axis jumps from x_A to x_C");
    scene.report.add("min_step_A", c.min_slope_A,
                     "smallest change of A between neighbouring points (>= 0: non-decreasing)");
    scene.report.add("min_step_C", c.min_slope_C,
                     "smallest change of C between neighbouring points (>= 0: non-decreasing)");
    scene.report.add("cos2_phi_on_hyperbola", cos2_at_crossing,
                     "cos^2 of the angle between the symmetry axis R_A and z where B = C (Fig. 6(b)): not 1");
    if (!(c.min_slope_A >= -1e-12 * b.C_g && c.min_slope_C >= -1e-12 * b.C_g))
        throw kit::NumericalFailure("a moment decreased along a line");
}

// Figure 6 (lines 0, 1, with the crossings B = C) or Figure 7 (lines 2, 3).
void draw(kit::Scene& scene, const BodyAtG& b, const std::vector<Line>& lines, const Curves& c, const std::string& file,
          int first, bool crossing) {
    kit::Figure fig(scene, file, 960, 480);
    if (!fig.enabled()) return;
    fig.script(kit::gp::moments_along_lines, {{"L_max", std::to_string(c.L_max)}});
    for (int l = first; l < first + 2; ++l) {
        fig.script(kit::gp::panel, {{"title", kit::quoted(lines[l].title)}});
        if (crossing) {
            const double Lc = std::sqrt(rigid::critical_h(b, lines[l].z) / b.mu);
            fig.script(kit::gp::marker,
                       {{"L", std::to_string(Lc)}, {"ls", "9"}, {"text", "B = C"}, {"height", "0.75"}});
        }
        if (l == 0) {
            const double La = std::sqrt((b.C_g - b.A_g) / b.mu);
            fig.script(kit::gp::marker,
                       {{"L", std::to_string(La)}, {"ls", "10"}, {"text", "A = C"}, {"height", "0.62"}});
        }
        fig.script(kit::gp::curves);
        for (int rep = 0; rep < 6; ++rep) fig.data(c.curves[l]);
    }
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("moments_along_lines",
                      "Chapter 6, Figures 6 and 7: the moments A, B, C at O against the distance L");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options&, kit::Scene& scene) {
        const BodyAtG b = body(p.body);
        const std::vector<Line> lines = lines_of(b, p);
        const Curves c = compute(b, lines, p.points);
        report(scene, b, lines, c);
        draw(scene, b, lines, c, "moments_below_critical.svg", 0, true);
        draw(scene, b, lines, c, "moments_above_critical.svg", 2, false);
    });
}
