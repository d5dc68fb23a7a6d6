// Chapter 6 scene: the angle phi between the smallest axis at O and the centre-of-mass line,
// against Theorem 1's condition cos^2 phi = (B - A)/(C - A) [P, (int.2), (5.12)-(5.14)], on a
// Grioli line, below it and above it, for L from 1e-6 to 1e6 body sizes.
//
// On the line the two sides agree at every L; off it they never do. Checked against a binary128
// evaluation on the exact line (tests/include/reference/quad_inertia.hpp), and against Eigen's eigenvectors.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "common.hpp"
#include "figure.hpp"
#include "reference/quad_inertia.hpp"
#include "tilt_on_grioli_lines.gp.hpp"

using namespace ch6;

struct Params {
    rigid::BodyAtG body = ch6::default_body;
    int sign = 1;
    double off = 0.1;
    int points = 121;
};

void declare(kit::Options& opts, Params& p) {
    ch6::body_options(opts, p.body);
    opts.integer("sign", &p.sign, "which Grioli line, x_C = sign sqrt((C_g - B_g)/(B_g - A_g)) x_A", -1, 1)
        .real("off", &p.off, "the angle (rad) by which the two other lines leave the Grioli line",
              kit::between(1e-12, 0.5))
        .integer("points", &p.points, "distances, log-spaced over 12 decades", 13, 10001);
}

namespace {

// The Grioli line of the options and the two lines `off` radians on either side of it.
struct Lines {
    Vec3 zg, z_below, z_above;
};

Lines lines_of(const BodyAtG& b, const Params& p) {
    if (p.sign == 0) throw kit::BadInput("--sign: got 0; it must be +1 or -1");
    const Vec3 zg = rigid::grioli_direction(b, p.sign);
    const double phi_line = std::atan2(zg.z(), zg.x());
    return {zg, rigid::shift_direction(phi_line + p.sign * p.off),  // towards x_C: cos^2 phi_g smaller
            rigid::shift_direction(phi_line - p.sign * p.off)};
}

// The sweep over L: rows L/size, cos^2 and (B-A)/(C-A) on the line, below it (cos^2, ratio,
// gap), above it (the same), the relative gap on the line, the eigen-solver's gap on the line.
struct Sweep {
    std::vector<std::vector<double>> rows;
    double err_ref = 0, gap_closed = 0, gap_eigen = 0, self_ref = 0, min_gap_off = 1e300;
};

Sweep compute(const BodyAtG& b, const Params& p, const Lines& lines) {
    const double ell = size_of(b);
    const int n = p.points;
    quadref::quad qA, qC;
    quadref::grioli_line(b.A_g, b.B_g, b.C_g, p.sign, qA, qC);
    Sweep sw;
    for (int i = 0; i < n; ++i) {
        const double t = -6 + 12.0 * i / (n - 1), L = ell * std::pow(10.0, t);
        const rigid::GrioliSuspension g = rigid::grioli_suspension(b, L, p.sign);
        const auto r = quadref::moments(b.A_g, b.B_g, b.C_g, b.mu, L, qA, qC);
        sw.err_ref = std::max({sw.err_ref, quadref::rel_err(g.tilt.cos2, r.cos2), quadref::rel_err(g.tilt.sin2, r.sin2),
                               quadref::rel_err(g.expected.cos2, r.BmA / r.CmA),
                               quadref::rel_err(g.expected.sin2, r.CmB / r.CmA)});
        sw.self_ref = std::max({sw.self_ref, static_cast<double>(quadref::abs_q(r.cos2 - r.BmA / r.CmA) / r.cos2),
                                static_cast<double>(quadref::abs_q(r.sin2 - r.CmB / r.CmA) / r.sin2)});
        // The gap, relative to the smaller of sin^2 and (C - B)/(C - A): the digits that matter.
        const double gap = std::abs(g.tilt.sin2 - g.expected.sin2) / g.expected.sin2;
        sw.gap_closed = std::max(sw.gap_closed, gap);
        // The eigen-solver on the same line: only where it can resolve the angle (L <= 100 sizes).
        double gap_e = NAN;
        if (t <= 2) {
            const EigenMoments e = eigen_moments(tensor_at(b, L, lines.zg));
            gap_e = std::abs(e.vA.dot(lines.zg) * e.vA.dot(lines.zg) - (e.B - e.A) / (e.C - e.A));
            sw.gap_eigen = std::max(sw.gap_eigen, gap_e);
        }
        std::vector<double> row{L / ell, g.tilt.cos2, g.expected.cos2};
        for (const Vec3& z : {lines.z_below, lines.z_above}) {
            const rigid::Cos2Sin2 tilt = rigid::smallest_axis_tilt(b, L, z);
            const rigid::Cos2Sin2 ratio = rigid::grioli_ratio(rigid::shifted_moments(b, L, z));
            row.push_back(tilt.cos2);
            row.push_back(ratio.cos2);
            row.push_back(std::abs(tilt.cos2 - ratio.cos2));
            sw.min_gap_off = std::min(sw.min_gap_off, std::abs(tilt.cos2 - ratio.cos2));
        }
        row.push_back(std::max(gap, 1e-18));
        row.push_back(gap_e);
        sw.rows.push_back(row);
    }
    return sw;
}

void report(kit::Scene& scene, const BodyAtG& b, const Params& p, const Lines& lines, const Sweep& sw) {
    const double ell = size_of(b);
    const double t_closed =
        kit::time_per_call([&](int i) { return rigid::grioli_suspension(b, ell * (1 + 1e-3 * i), p.sign).tilt.sin2; });
    scene.report.headline(
        "max relative error of cos^2, sin^2 phi and (B-A)/(C-A), (C-B)/(C-A) on the line, against binary128",
        sw.err_ref, t_closed);
    scene.report.add("grioli_cos2_phi_g", lines.zg.x() * lines.zg.x(), "(5.14)");
    scene.report.add("on_line_gap_closed_forms", sw.gap_closed,
                     "max |sin^2 phi - (C-B)/(C-A)| / ((C-B)/(C-A)), L = 1e-6..1e6 sizes");
    scene.report.add("on_line_gap_eigen", sw.gap_eigen,
                     "max |cos^2 phi - (B-A)/(C-A)| from Eigen's eigenvectors, L <= 100 sizes");
    scene.report.add("on_line_gap_binary128", sw.self_ref, "the same identity in binary128");
    scene.report.add("off_line_min_gap", sw.min_gap_off, "smallest |cos^2 phi - (B-A)/(C-A)| off the line, over all L");
    scene.report.table("sweep",
                       {"L/size", "cos2_line", "ratio_line", "cos2_below", "ratio_below", "gap_below", "cos2_above",
                        "ratio_above", "gap_above", "rel_gap_line", "gap_line_eigen"},
                       sw.rows, false);
    if (!(sw.err_ref <= 1e-13)) throw kit::NumericalFailure("the closed forms on the Grioli line lost digits");
}

void draw(kit::Scene& scene, const Params& p, const std::vector<std::vector<double>>& rows) {
    kit::Figure fig(scene, "tilt_on_grioli_lines.svg", 980, 460);
    if (!fig.enabled()) return;
    const std::string off_text = std::to_string(p.off).substr(0, 6);
    fig.script(kit::gp::tilt_on_grioli_lines, {{"off", off_text}});
    for (int rep = 0; rep < 6; ++rep) fig.data(rows);
    fig.script(kit::gp::gap);
    for (int rep = 0; rep < 4; ++rep) fig.data(rows);
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts(
        "tilt_on_grioli_lines",
        "Chapter 6: cos^2 phi against (B - A)/(C - A) along a Grioli line and off it, L from 1e-6 to 1e6 body sizes");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options&, kit::Scene& scene) {
        const BodyAtG b = body(p.body);
        const Lines lines = lines_of(b, p);
        const Sweep sw = compute(b, p, lines);
        report(scene, b, p, lines, sw);
        draw(scene, p, sw.rows);
    });
}
