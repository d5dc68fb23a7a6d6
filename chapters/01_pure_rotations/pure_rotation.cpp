// Chapter 1 scene: the points of a body under a pure rotation R^a(alpha t) [P, (1.1), (1.3)].
//
// A box-shaped body, off the axis, is drawn at several instants of one turn, with the
// circles its corners trace. Checked against an independent reference: Eigen::AngleAxisd
// for every rotated corner, and the two facts that make the paths circles about a (the
// height along a and the distance from the axis stay constant).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "figure.hpp"
#include "motion.hpp"
#include "pure_rotation.gp.hpp"
#include "rigid/rotation.hpp"
#include "scene.hpp"

using rigid::Mat3;
using rigid::Vec3;

namespace {

// The body: a box with these half-sizes, centred off the axis. Corners in body coordinates.
std::vector<Vec3> box_corners(const Vec3& centre, const Vec3& half) {
    std::vector<Vec3> corners;
    for (int i = 0; i < 8; ++i)
        corners.push_back(centre +
                          Vec3((i & 1 ? 1 : -1) * half.x(), (i & 2 ? 1 : -1) * half.y(), (i & 4 ? 1 : -1) * half.z()));
    return corners;
}

// The 12 edges of the box, as pairs of corner indices (corners differ in exactly one bit).
std::vector<std::pair<int, int>> box_edges() {
    std::vector<std::pair<int, int>> edges;
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            if (!(i & bit)) edges.emplace_back(i, i | bit);
    return edges;
}

// The body of the scene: this box, off the axis.
const Vec3 box_centre(1.3, 0.0, 0.2), box_half(0.35, 0.12, 0.12);

struct Params {
    Vec3 axis = Vec3(0.25, 0.35, 1.0);
    double alpha = 1.0;
    int frames = 5;
    std::string motion_file;  // --motion: the book's viewer data (motion.hpp)
};

void declare(kit::Options& opts, Params& p) {
    opts.vector("axis", &p.axis, "rotation axis a (normalised)", kit::nonzero_vector(-1e6, 1e6))
        .real("alpha", &p.alpha, "rotation frequency alpha", kit::between(1e-6, 1e6))
        .integer("frames", &p.frames, "instants drawn over one turn", 2, 36)
        .file("motion", &p.motion_file, kit::motion_help);
    // The work is fixed (361 rotations of 8 corners, 5 times): far below any budget.
}

// Every corner of the body at every instant of a finely sampled turn.
struct Turn {
    Vec3 a;         // the axis, normalised
    double period;  // 2 pi / alpha
    std::vector<Vec3> corners;
    std::vector<std::vector<Vec3>> path;  // path[c][k]: corner c at t = k T / samples
    double run_time;
};
constexpr int samples = 360;

Turn compute(const Params& p) {
    Turn turn{p.axis.normalized(), 2 * std::numbers::pi / p.alpha, box_corners(box_centre, box_half), {}, 0};
    turn.path.resize(turn.corners.size());
    auto rotate_all = [&] {
        for (int k = 0; k <= samples; ++k) {
            const Mat3 R = rigid::rotation_about(turn.a, p.alpha * turn.period * k / samples);
            for (std::size_t c = 0; c < turn.corners.size(); ++c) turn.path[c].push_back(R * turn.corners[c]);
        }
    };
    turn.run_time = kit::min_time([&] {
        for (auto& x : turn.path) x.clear();
        rotate_all();
        kit::keep(turn.path);
    });
    return turn;
}

// Against Eigen's independent AngleAxis, and the circle invariants about a. Returns the error.
double report(kit::Scene& scene, const Params& p, const Turn& turn) {
    const Vec3& a = turn.a;
    double err_eigen = 0, err_height = 0, err_radius = 0;
    for (std::size_t c = 0; c < turn.corners.size(); ++c) {
        const Vec3& x0 = turn.corners[c];
        const double height = a.dot(x0), radius = (x0 - height * a).norm();
        for (int k = 0; k <= samples; ++k) {
            const double phi = p.alpha * turn.period * k / samples;
            const Vec3& x = turn.path[c][k];
            const Vec3 ref = Eigen::AngleAxisd(phi, a) * x0;
            err_eigen = std::max(err_eigen, (x - ref).norm() / x0.norm());
            err_height = std::max(err_height, std::abs(a.dot(x) - height) / x0.norm());
            err_radius = std::max(err_radius, std::abs((x - a.dot(x) * a).norm() - radius) / x0.norm());
        }
    }
    scene.report.headline("max |R^a(alpha t) x - AngleAxis(alpha t, a) x| / |x| over the corners of one turn",
                          err_eigen, turn.run_time);
    scene.report.add("axis", a, "a, normalised");
    scene.report.add("alpha", p.alpha);
    scene.report.add("rotations_evaluated", static_cast<long>(samples + 1));
    scene.report.add("height_drift", err_height, "max |a.x(t) - a.x(0)| / |x|");
    scene.report.add("radius_drift", err_radius, "max change of the distance from the axis / |x|");
    scene.report.add("run_time_per_rotation_s", turn.run_time / (samples + 1));
    return err_eigen;
}

// The book's motion viewer: the scene's box over one turn of R^a(alpha t), and the cone that the
// line from O to its centre sweeps about a.
void write_turn_motion(kit::Scene& scene, const std::string& file, const Vec3& a, double alpha, double err,
                       const Vec3& centre, const Vec3& half) {
    if (file.empty()) return;
    const double period = 2 * std::numbers::pi / alpha;
    kit::Motion m;
    m.title = "a pure rotation R^a(αt): every point of the box circles the axis a";
    m.parameters = fmt::format("a = ({:.3g}, {:.3g}, {:.3g}), α = {:g}; one turn", a.x(), a.y(), a.z(), alpha);
    m.error = err;
    m.error_measure = "max |R^a(αt) x − AngleAxis(αt, a) x| / |x| over the corners of one turn";
    // The box's moments about its centre, up to its mass: (b² + c², c² + a², a² + b²) / 3.
    m.moments = Vec3(half.y() * half.y() + half.z() * half.z(), half.z() * half.z() + half.x() * half.x(),
                     half.x() * half.x() + half.y() * half.y()) /
                3;
    m.shape = "box";
    m.size = half.x();
    m.centre_of_mass = centre;
    m.cones = {{"cone swept by the line from O to the box's centre (about a)", a, std::acos(a.dot(centre.normalized())),
                false, centre.norm()}};
    m.speed = period / 8;
    for (int k = 0; k <= 180; ++k) m.sample(period * k / 180, rigid::rotation_about(a, alpha * period * k / 180));
    kit::write_motion(scene, file, m);
}

// The edges of the box rotated by R, as separate segments.
void add_edges(std::vector<std::vector<double>>& rows, const Mat3& R, const std::vector<Vec3>& corners) {
    for (auto [i, j] : box_edges()) {
        const Vec3 p = R * corners[i], q = R * corners[j];
        rows.push_back({p.x(), p.y(), p.z()});
        rows.push_back({q.x(), q.y(), q.z()});
        rows.push_back({});
        rows.push_back({});
    }
}

void draw(kit::Scene& scene, const Params& p, const Turn& turn) {
    kit::Figure fig(scene, "pure_rotation.svg", 760, 620);
    if (!fig.enabled()) return;
    const Vec3& a = turn.a;
    fig.script(kit::gp::pure_rotation, {{"frames", std::to_string(p.frames)}});
    fig.data({{-1.2 * a.x(), -1.2 * a.y(), -1.2 * a.z()}, {1.6 * a.x(), 1.6 * a.y(), 1.6 * a.z()}});
    std::vector<std::vector<double>> paths, bodies, first;
    for (const auto& path : turn.path) {
        for (const Vec3& x : path) paths.push_back({x.x(), x.y(), x.z()});
        paths.push_back({});  // two blank lines: separate curves, not one mesh
        paths.push_back({});
    }
    for (int f = 1; f < p.frames; ++f)
        add_edges(bodies, rigid::rotation_about(a, p.alpha * turn.period * f / p.frames), turn.corners);
    add_edges(first, Mat3::Identity(), turn.corners);
    fig.data(paths).data(bodies).data(first);
    fig.finish();
}

}  // namespace

int main(int argc, char** argv) {
    Params p;
    kit::Options opts("pure_rotation", "Chapter 1: the points of a body under a pure rotation R^a(alpha t)");
    declare(opts, p);
    return kit::run(argc, argv, opts, [&](const kit::Options&, kit::Scene& scene) {
        const Turn turn = compute(p);
        const double error = report(scene, p, turn);
        write_turn_motion(scene, p.motion_file, turn.a, p.alpha, error, box_centre, box_half);
        draw(scene, p, turn);
    });
}
