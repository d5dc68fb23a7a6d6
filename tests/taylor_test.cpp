// Checks of the provided Taylor-series reference integrator (rigid/taylor.hpp). Not graders.
// It is checked against the two closed forms of the workbook (the Grioli precession of
// Chapter 5 and the elliptic free-body motion of Chapter 3), against itself at half the step,
// and for its order of convergence.
#include "rigid/taylor.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "checks.hpp"
#include "rigid/free_body_exact.hpp"
#include "rigid/grioli.hpp"
#include "rigid/rotation.hpp"

using rigid::BodyState;
using rigid::HeavyTop;
using rigid::Mat3;
using rigid::Vec3;

namespace {

template <class Real>
std::vector<rigid::TaylorState<Real>> run(const HeavyTop& top, const BodyState& s0, const std::vector<double>& times,
                                          double h, int order) {
    std::vector<rigid::TaylorState<Real>> out;
    rigid::integrate_taylor<Real>(
        top, s0, times, [&](double, const rigid::TaylorState<Real>& s) { out.push_back(s); }, h, order);
    return out;
}

const HeavyTop free_body{Vec3(2, 3, 4).asDiagonal().toDenseMatrix(), 0.0, Vec3::UnitZ(), Vec3::UnitX()};
const Vec3 free_Omega0(1.0, 0.6, -0.8);

}  // namespace

TEST_CASE("integrate_taylor: follows the Grioli precession to the closed form's round-off") {
    const rigid::Moments m = rigid::moments(1.0, 1.5, 2.0);
    const rigid::GrioliPrecession g = rigid::grioli_precession(m, 1.0, rigid::Sense::ccw);
    const double P = 2 * std::acos(-1.0) / g.alpha;
    const std::vector<double> times = rigid::linspace(0, 3 * P, 12);
    const auto ref = run<long double>(rigid::grioli_top(m, g), rigid::grioli_initial_state(g), times, 0.1, 24);
    double worst = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
        const BodyState s = rigid::to_double(ref[i]);
        worst = std::max(worst, rigid::geodesic_angle(s.R, rigid::grioli_rotation(g, times[i])));
        worst = std::max(worst, (s.Omega - rigid::grioli_angular_velocity(g, times[i])).norm() / g.alpha);
    }
    CAPTURE(worst);
    CHECK_SMALL(worst, 2e-15);
}

TEST_CASE("integrate_taylor: follows the exact free-body motion") {
    const std::vector<double> times = rigid::linspace(0, 20, 10);
    const auto ref = run<long double>(free_body, {free_Omega0, Mat3::Identity()}, times, 0.05, 24);
    const rigid::FreeBodyMotion motion = rigid::free_body_motion(free_body.J.diagonal(), free_Omega0);
    const std::vector<Mat3> R = rigid::free_body_exact_rotations(motion, times);
    for (std::size_t i = 0; i < times.size(); ++i) {
        const BodyState s = rigid::to_double(ref[i]);
        CHECK_SMALL(rigid::geodesic_angle(s.R, R[i]), 1e-13);
        CHECK_MAT_NEAR(s.Omega, rigid::free_body_exact_omega(motion, times[i]), 1e-13);
    }
}

TEST_CASE("integrate_taylor: the error of degree N falls like h^N") {
    // Against a long-double run at degree 24 (exact here to 1e-18).
    const std::vector<double> times{0.0, 2.0};
    const BodyState s0{free_Omega0, Mat3::Identity()};
    const auto ref = run<long double>(free_body, s0, times, 0.02, 24).back();
    for (int order : {2, 3, 4, 6}) {
        CAPTURE(order);
        const auto e = [&](double h) {
            const auto x = run<long double>(free_body, s0, times, h, order).back();
            return static_cast<double>((x.R - ref.R).norm() + (x.Omega - ref.Omega).norm());
        };
        const double ratio = e(0.02) / e(0.01);
        CHECK_NEAR(std::log2(ratio), double(order), 0.15);
    }
}

TEST_CASE("integrate_taylor: in long double it agrees with itself at half the step to 5e-17") {
    const std::vector<double> times = rigid::linspace(0, 50, 5);
    const BodyState s0{free_Omega0, Mat3::Identity()};
    const auto a = run<long double>(free_body, s0, times, 0.1, 24),
               b = run<long double>(free_body, s0, times, 0.05, 24);
    const auto d = run<double>(free_body, s0, times, 0.1, 24);
    long double worst = 0, worst_double = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
        worst = std::max(worst, (a[i].R - b[i].R).norm());
        worst_double = std::max(worst_double, (a[i].R - d[i].R.cast<long double>()).norm());
    }
    CAPTURE(static_cast<double>(worst));
    CAPTURE(static_cast<double>(worst_double));
    CHECK_SMALL(worst, 5e-17L);
    CHECK(worst_double >= 1e-16L);  // the same steps in double: round-off of double, 100 times larger
}

TEST_CASE("integrate_taylor: compensated summation keeps the state to the round-off of its increments") {
    // 20000 short steps of a free body: plain summation rounds the state at every step, the
    // compensated sum only the increments (of size h |Omega|), so its distance from a long-double
    // run is far smaller (measured: 1.7e-13 against 1.2e-15).
    const std::vector<double> times{0.0, 20.0};
    const BodyState s0{free_Omega0, Mat3::Identity()};
    const auto ref = run<long double>(free_body, s0, times, 1e-3, 12).back();
    const auto error = [&](rigid::Summation sum) {
        std::vector<rigid::TaylorState<double>> out;
        rigid::integrate_taylor<double>(
            free_body, s0, times, [&](double, const rigid::TaylorState<double>& s) { out.push_back(s); }, 1e-3, 12,
            sum);
        return static_cast<double>((out.back().R.cast<long double>() - ref.R).norm() +
                                   (out.back().Omega.cast<long double>() - ref.Omega).norm());
    };
    const double plain = error(rigid::Summation::plain), compensated = error(rigid::Summation::compensated);
    CAPTURE(plain);
    CAPTURE(compensated);
    CHECK(compensated < plain / 10);
    CHECK_SMALL(compensated, 5e-15);
}

TEST_CASE("integrate_taylor: rejects bad settings or times or state") {
    const auto ignore = [](double, const rigid::TaylorState<double>&) {};
    const BodyState s0{free_Omega0, Mat3::Identity()};
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(rigid::integrate_taylor<double>(free_body, s0, {0.0, 1.0}, ignore, 0.0, 10), std::invalid_argument);
    CHECK_THROWS_AS(rigid::integrate_taylor<double>(free_body, s0, {0.0, 1.0}, ignore, 0.1, 0), std::invalid_argument);
    CHECK_THROWS_AS(rigid::integrate_taylor<double>(free_body, s0, {0.0, 1.0}, ignore, 0.1, 61), std::invalid_argument);
    CHECK_THROWS_AS(rigid::integrate_taylor<double>(free_body, s0, {1.0, 0.0}, ignore, 0.1, 10), std::invalid_argument);
    CHECK_THROWS_AS(
        rigid::integrate_taylor<double>(free_body, {Vec3(nan, 0, 0), Mat3::Identity()}, {0.0, 1.0}, ignore, 0.1, 10),
        std::invalid_argument);
}
