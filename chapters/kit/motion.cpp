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
}

}  // namespace kit
