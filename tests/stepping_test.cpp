// Checks of the provided fixed-step driver for steppers in increment form (rigid/stepping.hpp).
// Not graders: nothing here is an exercise. The steppers used here are exact rotations built
// with Eigen's AngleAxis, so every error is the driver's own.
#include "rigid/stepping.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "checks.hpp"

using rigid::BodyState;
using rigid::Increment;
using rigid::Mat3;
using rigid::Vec3;

namespace {

Mat3 rot(const Vec3& w) { return Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix(); }

// The exact motion of a spherical free body: Omega constant, R(t) = R(0) exp(t hat(Omega)).
// E = exp(h hat(Omega)) - 1 = sin(phi) hat(u) + 2 sin^2(phi/2) hat(u)^2, to a few ulp of itself.
rigid::IncrementStepper spinning() {
    return [](const BodyState& s, double h) {
        const Vec3 w = h * s.Omega;
        const double phi = w.norm();
        Mat3 U;
        U << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
        U /= phi;
        return Increment{Vec3::Zero(), std::sin(phi) * U + 2 * std::pow(std::sin(phi / 2), 2) * U * U};
    };
}

double defect(const Mat3& R) { return (R.transpose() * R - Mat3::Identity()).norm(); }

}  // namespace

TEST_CASE("apply: adds dOmega and multiplies R by 1 + E") {
    const BodyState s{Vec3(1, 2, 3), rot(Vec3(0.3, -0.2, 0.5))};
    const Increment d{Vec3(0.1, 0, -0.1), rot(Vec3(0, 0.4, 0)) - Mat3::Identity()};
    const BodyState n = rigid::apply(s, d);
    CHECK_MAT_NEAR(n.Omega, Vec3(1.1, 2, 2.9), 1e-15);
    CHECK_MAT_NEAR(n.R, s.R * rot(Vec3(0, 0.4, 0)), 1e-15);
}

TEST_CASE("integrate_steps: lands exactly on every output time and counts its steps") {
    const std::vector<double> times{0.0, 0.25, 1.0, 1.1, 3.0};
    std::vector<double> seen;
    const long steps = rigid::integrate_steps(
        spinning(), {Vec3(0, 0, 1), Mat3::Identity()}, times, [&](double t, const BodyState&) { seen.push_back(t); },
        0.1);
    REQUIRE(seen.size() == times.size());
    for (std::size_t i = 0; i < times.size(); ++i) CHECK(seen[i] == times[i]);
    long expected = 0;
    for (std::size_t i = 1; i < times.size(); ++i) expected += long(std::ceil((times[i] - times[i - 1]) / 0.1));
    CHECK(steps == expected);
}

TEST_CASE("integrate_steps: an exact stepper gives the exact motion with either summation") {
    const Vec3 w(0.3, -0.7, 1.1);
    const Mat3 R0 = rot(Vec3(1, 0.5, -0.2));
    for (auto sum : {rigid::Summation::plain, rigid::Summation::compensated}) {
        BodyState last;
        rigid::integrate_steps(
            spinning(), {w, R0}, {0.0, 10.0}, [&](double, const BodyState& s) { last = s; }, 0.01, sum);
        CHECK_MAT_NEAR(last.R, R0 * rot(10.0 * w), 1e-13);
        CHECK_MAT_NEAR(last.Omega, w, 0.0);
    }
}

TEST_CASE("integrate_steps: compensated summation keeps R^T R = 1 where the plain sum drifts") {
    // 200 000 small turns: the plain sum rounds R once per step and its defect grows like
    // eps sqrt(N), to about 6e-14 here; the compensated sum keeps only the errors of the
    // increments themselves, eps |E| per step, 5e-15 here.
    const Vec3 w(0.31, -0.72, 1.13);
    double plain = 0, compensated = 0;
    for (auto sum : {rigid::Summation::plain, rigid::Summation::compensated}) {
        BodyState last;
        rigid::integrate_steps(
            spinning(), {w, Mat3::Identity()}, {0.0, 200.0}, [&](double, const BodyState& s) { last = s; }, 0.001, sum);
        (sum == rigid::Summation::plain ? plain : compensated) = defect(last.R);
    }
    CAPTURE(plain);
    CAPTURE(compensated);
    CHECK_SMALL(compensated, 1.5e-14);
    CHECK(plain >= 4 * compensated);
}

TEST_CASE("integrate_steps: rejects a bad step or bad times or a non-finite state") {
    const auto ignore = [](double, const BodyState&) {};
    const BodyState s{Vec3(0, 0, 1), Mat3::Identity()};
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(rigid::integrate_steps(spinning(), s, {0.0, 1.0}, ignore, 0.0), std::invalid_argument);
    CHECK_THROWS_AS(rigid::integrate_steps(spinning(), s, {0.0, 1.0}, ignore, nan), std::invalid_argument);
    CHECK_THROWS_AS(rigid::integrate_steps(spinning(), s, {1.0, 0.0}, ignore, 0.1), std::invalid_argument);
    CHECK_THROWS_AS(rigid::integrate_steps(spinning(), s, {}, ignore, 0.1), std::invalid_argument);
    CHECK_THROWS_AS(rigid::integrate_steps(spinning(), {Vec3(nan, 0, 0), Mat3::Identity()}, {0.0, 1.0}, ignore, 0.1),
                    std::invalid_argument);
}
