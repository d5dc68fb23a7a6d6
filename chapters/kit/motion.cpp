// The --motion FILE writer (motion.hpp): nlohmann-json does the writing; what is computed here
// is only what the viewer must not compute itself (the body's shape from its moments, the
// trails, each from the scene's own R(t)).
#include "motion.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "figure.hpp"
#include "kit.gp.hpp"  // kit::gp::motion_gif, motion_gif_frame

namespace kit {

namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

// Five decimals: a picture needs no more, and the page stays light.
double light(double x) { return std::round(x * 1e5) / 1e5; }

Json vec(const rigid::Vec3& v) { return Json::array({light(v.x()), light(v.y()), light(v.z())}); }

// The uniform ellipsoid (or box) with principal moments A, B, C about its centre has half-axes
// with a^2 proportional to B + C - A (ellipsoid: I_x = m (b^2 + c^2) / 5; box: / 3), and so
// on: scaled so that the largest half-axis is 1. Needs the triangle inequality.
rigid::Vec3 half_axes(const rigid::Vec3& I) {
    const rigid::Vec3 sq(I.y() + I.z() - I.x(), I.z() + I.x() - I.y(), I.x() + I.y() - I.z());
    if (!(sq.minCoeff() >= 0))
        throw BadInput("--motion: the moments (" + std::to_string(I.x()) + ", " + std::to_string(I.y()) + ", " +
                       std::to_string(I.z()) + ") break the triangle inequality: no body has them");
    const rigid::Vec3 axes = sq.cwiseSqrt().cwiseMax(0.02 * std::sqrt(sq.maxCoeff()));  // a flat body: a thin plate
    return axes / axes.maxCoeff();
}

Json cones(const std::vector<MotionCone>& list) {
    Json out = Json::array();
    for (const auto& c : list)
        out.push_back({{"name", c.name},
                       {"axis", vec(c.axis.normalized())},
                       {"half_angle", light(c.half_angle)},
                       {"frame", c.body_fixed ? "body" : "lab"},
                       {"length", light(c.length)}});
    return out;
}

// One body's part of the file: its shape, placement, samples of R(t), trails and cones.
Json body_json(const Motion& m) {
    const rigid::Vec3 axes = half_axes(m.moments) * m.size;
    Json R = Json::array(), cm = Json::array(), tip = Json::array();
    const bool heavy = m.centre_of_mass.norm() > 0;
    for (std::size_t i = 0; i < m.R.size(); ++i) {
        const rigid::Mat3& r = m.R[i];
        const double drift = (r.transpose() * r - rigid::Mat3::Identity()).norm();
        if (!std::isfinite(drift) || drift > 1e-6 || !(std::abs(r.determinant() - 1) < 1e-6))
            throw NumericalFailure("--motion: R(t) at t = " + std::to_string(m.t[i]) +
                                   " is not a rotation (|R^T R - 1| = " + std::to_string(drift) + ")");
        Json row = Json::array();
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) row.push_back(light(r(a, b)));
        R.push_back(std::move(row));
        if (heavy) cm.push_back(vec(m.fixed_point + r * m.centre_of_mass));
        tip.push_back(vec(m.fixed_point + r.col(1) * (1.25 * axes.maxCoeff())));
    }
    return {{"label", m.label},
            {"body", {{"shape", m.shape}, {"moments", vec(m.moments)}, {"half_axes", vec(axes)}}},
            {"fixed_point", vec(m.fixed_point)},
            {"centre_of_mass", vec(m.centre_of_mass)},
            {"R", R},
            {"trails", {{"centre_of_mass", cm}, {"tip_R_B", tip}}},
            {"cones", cones(m.cones)}};
}

// ------------------------------------------------------------------- the still-frame fallback
// The same motion as an animated GIF (gnuplot's `gif animate` terminal), for readers without the
// viewer (GitHub, print): 48 frames, the lines of the viewer seen from one direction.
using Points = std::vector<rigid::Vec3>;

// The body's outline in its own frame: the box's 12 edges, or the ellipsoid's 3 principal
// ellipses, as polylines.
std::vector<Points> outline(const Motion& m, const rigid::Vec3& h) {
    std::vector<Points> lines;
    if (m.shape == "box") {
        for (int axis = 0; axis < 3; ++axis)
            for (int s1 : {-1, 1})
                for (int s2 : {-1, 1}) {
                    rigid::Vec3 p = rigid::Vec3::Zero(), q;
                    p((axis + 1) % 3) = s1 * h((axis + 1) % 3);
                    p((axis + 2) % 3) = s2 * h((axis + 2) % 3);
                    q = p;
                    p(axis) = -h(axis);
                    q(axis) = h(axis);
                    lines.push_back({p, q});
                }
    } else {
        for (int axis = 0; axis < 3; ++axis) {
            Points ring;
            for (int j = 0; j <= 48; ++j) {
                const double phi = 2 * std::numbers::pi * j / 48;
                rigid::Vec3 p = rigid::Vec3::Zero();
                p((axis + 1) % 3) = h((axis + 1) % 3) * std::cos(phi);
                p((axis + 2) % 3) = h((axis + 2) % 3) * std::sin(phi);
                ring.push_back(p);
            }
            lines.push_back(ring);
        }
    }
    for (auto& l : lines)
        for (auto& p : l) p += m.centre_of_mass;
    return lines;
}

// A cone's rim and eight of its generators, in its own frame (lab or body).
std::vector<Points> cone_lines(const MotionCone& c) {
    const rigid::Vec3 a = c.axis.normalized(), u = a.unitOrthogonal(), v = a.cross(u);
    std::vector<Points> lines;
    Points rim;
    for (int j = 0; j <= 48; ++j) {
        const double phi = 2 * std::numbers::pi * j / 48;
        const rigid::Vec3 g =
            c.length * (std::cos(c.half_angle) * a + std::sin(c.half_angle) * (std::cos(phi) * u + std::sin(phi) * v));
        rim.push_back(g);
        if (j % 6 == 0) lines.push_back({rigid::Vec3::Zero(), g});
    }
    lines.push_back(rim);
    return lines;
}

void block(std::ostream& os, const std::vector<Points>& lines, const rigid::Mat3& R, const rigid::Vec3& at) {
    bool any = false;
    for (const auto& l : lines) {
        for (const auto& p : l) {
            const rigid::Vec3 x = at + R * p;
            os << fmt::format("{:.4f} {:.4f} {:.4f}\n", x.x(), x.y(), x.z());
            any = true;
        }
        os << "\n\n";  // two blank lines: separate polylines, not one surface
    }
    if (!any) os << fmt::format("{:.4f} {:.4f} {:.4f}\n", at.x(), at.y(), at.z());
    os << "e\n";
}

// One frame of the GIF: each body with its outline, axes, k, cones and trails up to sample k,
// as the splot of motion_gif_frame.gp, each curve in its line style of motion_gif.gp.
void gif_frame(Figure& fig, const std::vector<Motion>& bodies, std::size_t k) {
    std::string curves;
    std::ostringstream data;
    auto add = [&](int style, const std::vector<Points>& lines, const rigid::Mat3& R, const rigid::Vec3& at) {
        curves += fmt::format("{}'-' with lines ls {}", curves.empty() ? "" : ", ", style);
        block(data, lines, R, at);
    };
    for (const Motion& b : bodies) {
        const rigid::Vec3 h = half_axes(b.moments) * b.size, O = b.fixed_point;
        const rigid::Mat3& R = b.R[k];
        const rigid::Mat3 I = rigid::Mat3::Identity();
        add(101, outline(b, h), R, O);
        const double reach = 1.25 * h.maxCoeff() + b.centre_of_mass.norm();
        for (int i = 0; i < 3; ++i) add(102 + i, {{-0.8 * reach * I.col(i), reach * I.col(i)}}, R, O);
        add(105, {{rigid::Vec3::Zero(), 1.9 * b.k.normalized()}}, I, O);
        for (const auto& c : b.cones) add(c.body_fixed ? 106 : 107, cone_lines(c), c.body_fixed ? R : I, O);
        Points cm, tip;
        for (std::size_t j = 0; j <= k; ++j) {
            if (b.centre_of_mass.norm() > 0) cm.push_back(b.R[j] * b.centre_of_mass);
            tip.push_back(b.R[j].col(1) * (1.25 * h.maxCoeff()));
        }
        add(108, {cm}, I, O);
        add(109, {tip}, I, O);
    }
    fig.script(gp::motion_gif_frame, {{"t", fmt::format("{:.2f}", bodies.front().t[k])}, {"curves", curves}});
    fig << data.str();
}

// The GIF of write_motion (through kit::Figure, as every figure): 48 frames at most, played in
// the motion's own time at its speed, under 2 MB.
void write_gif(Scene& scene, const std::vector<Motion>& bodies, const fs::path& gif) {
    const Motion& m = bodies.front();
    const std::size_t n = m.t.size(), frames = std::min<std::size_t>(48, n);
    const double seconds = (m.t.back() - m.t.front()) / (m.speed > 0 ? m.speed : 1);
    const int delay = std::clamp(static_cast<int>(std::lround(100 * seconds / static_cast<double>(frames))), 4, 25);
    rigid::Vec3 lo = rigid::Vec3::Constant(1e300), hi = -lo;
    for (const Motion& b : bodies) {
        const double r = 1.3 * b.size + b.centre_of_mass.norm() + 0.3;
        lo = lo.cwiseMin(b.fixed_point - rigid::Vec3::Constant(r));
        hi = hi.cwiseMax(b.fixed_point + rigid::Vec3::Constant(r));
        for (const auto& c : b.cones) hi = hi.cwiseMax(b.fixed_point + rigid::Vec3::Constant(c.length));
    }
    hi.z() = std::max(hi.z(), 2.0);
    const Terminal terminal{fmt::format("set terminal gif animate delay {} size 480,360 font 'DejaVu Sans,9'", delay),
                            false};
    Figure fig(scene, fs::absolute(gif).string(), terminal);  // gif is already in the --out folder
    Fill range;
    for (int i = 0; i < 3; ++i) {
        range.emplace_back(fmt::format("{}min", "xyz"[i]), fmt::format("{}", lo(i)));
        range.emplace_back(fmt::format("{}max", "xyz"[i]), fmt::format("{}", hi(i)));
    }
    fig.script(gp::motion_gif, range);
    for (std::size_t f = 0; f < frames; ++f) gif_frame(fig, bodies, frames > 1 ? f * (n - 1) / (frames - 1) : 0);
    const std::uintmax_t size = fig.finish();
    if (size > 2'000'000)
        throw NumericalFailure("--motion: the animated GIF has " + std::to_string(size) +
                               " bytes; it must stay under 2 MB");
}

}  // namespace

void write_motion(Scene& scene, const std::string& file, const Motion& m) {
    write_motion(scene, file, std::vector<Motion>{m});
}

void write_motion(Scene& scene, const std::string& file, const std::vector<Motion>& bodies) {
    if (file.empty()) return;
    if (fs::path(file).extension() != ".json")
        throw BadInput("--motion: got '" + file + "'; it must name a .json file");
    if (bodies.empty()) throw NumericalFailure("--motion: no body to write");
    const Motion& m = bodies.front();
    for (const Motion& b : bodies)
        if (b.t.empty() || b.t.size() != b.R.size() || b.t != m.t)
            throw NumericalFailure("--motion: every body needs one R for each of the same sample times");
    Json t = Json::array(), others = Json::array();
    for (double x : m.t) t.push_back(light(x));
    for (std::size_t i = 1; i < bodies.size(); ++i) others.push_back(body_json(bodies[i]));
    Json out = {
        {"format", "workbook-motion-1"},
        {"scene", scene.options().scene()},
        {"title", m.title},
        {"parameters", m.parameters},
        {"error", m.error},
        {"error_measure", m.error_measure},
        {"k", vec(m.k.normalized())},
        {"speed", m.speed},
        {"t", t},
    };
    out.update(body_json(m));
    out["others"] = others;
    const fs::path final_path =
        fs::path(file).is_absolute() ? fs::path(file) : fs::path(scene.options().out_dir()) / file;
    if (!final_path.parent_path().empty()) fs::create_directories(final_path.parent_path());
    const fs::path staged = final_path.parent_path() / fmt::format(".{}.partial", final_path.filename().string());
    std::ofstream os(staged);
    os << out.dump() << "\n";
    os.close();
    if (!os) throw NumericalFailure("--motion: could not write " + staged.string());
    scene.stage_figure(staged.string(), final_path.string());
    // Beside it, unless --no-figure: the GIF of the same samples, <name>.gif.
    if (!scene.options().figures()) return;
    const fs::path gif = fs::path(final_path).replace_extension(".gif");
    write_gif(scene, bodies, gif);
}

}  // namespace kit
