// A sampled motion for the book's motion viewer (cmake/book/web/motion_viewer.js): what a scene
// computed, written as JSON only when the scene is given `--motion FILE`, so that scenes that
// do not show a motion stay lean. The page never integrates anything: it plays back R(t) at
// the scene's own sample times (and turns the body between two samples along the shortest
// rotation, for a smooth picture), with the scene's name, parameters and error in the caption.
//
//   std::string motion_file;                        // one typed option: --motion FILE
//   opts.file("motion", &motion_file, kit::motion_help);
//   ...
//   kit::Motion m{.title = "...", .parameters = "...", .moments = {A, B, C}};
//   for (...) m.sample(t, R);                       // R(t): columns are the body axes in the lab
//   kit::write_motion(scene, motion_file, m);       // does nothing when motion_file is empty
//
// The file: {"format": "workbook-motion-1", "scene", "title", "parameters", "error",
// "error_measure", "body": {"shape", "moments", "half_axes"}, "fixed_point", "k",
// "centre_of_mass" (body frame), "speed", "label", "t": [...], "R": [[R00, R01, ..., R22] row by row, ...],
// "trails": {"centre_of_mass": [[x, y, z], ...], "tip_R_B": [...]}, "cones": [...]}.
// A relative FILE goes into the scene's --out folder; it is published with the figures, only
// when the whole scene succeeded. Unless --no-figure, the same samples also go to FILE's name
// with .gif (gnuplot's `gif animate` terminal, 48 frames, under 2 MB): the still-frame fallback
// that GitHub and print show where the viewer cannot run.
#pragma once

#include <string>
#include <vector>

#include "rigid/types.hpp"
#include "scene.hpp"

namespace kit {

// A circular cone with its apex at the fixed point: the cones of a regular precession,
// Theorem 1 [P, (4.5)]. A body cone's axis is in the body frame (it turns with R(t)), a space
// cone's in the lab.
struct MotionCone {
    std::string name;       // "space cone (about b)"
    rigid::Vec3 axis;       // unit vector
    double half_angle = 0;  // radians, in (0, pi)
    bool body_fixed = false;
    double length = 1.5;  // of its generators, in the viewer's units (the body's largest half-axis is 1)
};

struct Motion {
    std::string label;       // of this body, when a file holds several ("counter-clockwise")
    std::string title;       // one line: what the reader sees
    std::string parameters;  // "A = 1, B = 2, C = 2.5, ...": the caption's parameters
    double error = 0;        // the scene's error for this motion, and what it measures
    std::string error_measure;
    // The body drawn as the uniform ellipsoid or box with these principal moments (A, B, C)
    // about its centre, which lies at centre_of_mass (body frame, in the viewer's units: the
    // body's largest half-axis is 1) from the fixed point.
    rigid::Vec3 moments{1, 2, 3};
    std::string shape = "ellipsoid";  // or "box"
    double size = 1;                  // its largest half-axis, in the viewer's units
    rigid::Vec3 centre_of_mass = rigid::Vec3::Zero();
    rigid::Vec3 fixed_point = rigid::Vec3::Zero();
    rigid::Vec3 k = rigid::Vec3::UnitZ();
    std::vector<MotionCone> cones;
    double speed = 1;  // the viewer's playback at 1x, in units of t per second
    std::vector<double> t;
    std::vector<rigid::Mat3> R;

    void sample(double time, const rigid::Mat3& rotation) {
        t.push_back(time);
        R.push_back(rotation);
    }
};

// The help of a scene's `--motion FILE` option: opts.file("motion", &file, kit::motion_help).
inline constexpr const char* motion_help =
    "also write the sampled motion R(t) as JSON to this file (relative: in the --out folder), for the book's motion "
    "viewer";

// Writes `m` to `file` (relative: in the --out folder) when `file` is not empty. Throws BadInput
// for a file name that is not *.json, NumericalFailure for a sample that is not a rotation.
void write_motion(Scene& scene, const std::string& file, const Motion& m);

// Several bodies in one lab, side by side (each at its own fixed_point), sampled at the same
// times; the caption (title, parameters, error), k and speed are those of the first. The file
// holds the first body as above and the others under "others", each with its "label", "body",
// "fixed_point", "centre_of_mass", "R", "trails" and "cones".
void write_motion(Scene& scene, const std::string& file, const std::vector<Motion>& bodies);

}  // namespace kit
