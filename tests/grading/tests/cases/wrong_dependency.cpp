// case: a wrong rotation_about (the sign of its sine term flipped) costs rotation_about alone: body_angular_velocity and every other grader build their inputs without it
// replace: rotation_about
// expect: rotation_about: agrees with Eigen::AngleAxisd | fail | expected
// expect: rotation_about: turns counter-clockwise | fail | expected
// expect: rotation_about: normalises an axis | fail | expected
// expect: rotation_about: rejects | fail | expected
// expect: rotation_about: the quarter turn about e3 | fail | expected
// score: body_angular_velocity 1
namespace rigid {
Mat3 rotation_about(const Vec3& a, double phi) {
    const Vec3 u = require_axis(a, "rotation axis");
    require_finite(phi, "rotation angle");
    const double c = std::cos(phi), s = std::sin(phi);
    return c * Mat3::Identity() + (1 - c) * u * u.transpose() - s * hat(u);
}
}  // namespace rigid
