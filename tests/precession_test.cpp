// Graders for Chapter 2, regular precession (rigid/precession.hpp). Each test name starts with
// the exercise it grades; each cross-checks against an independent computation: rotations
// from Eigen::AngleAxisd, angular velocities from finite differences of R(t).
#include "rigid/precession.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "checks.hpp"
#include "inputs.hpp"

using rigid::Mat3;
using rigid::RegularPrecession;
using rigid::Vec3;
using std::numbers::pi;

namespace {

Mat3 angle_axis(const Vec3& a, double phi) { return Eigen::AngleAxisd(phi, a.normalized()).toRotationMatrix(); }

// (1.4) built from Eigen alone.
Mat3 R_ref(const RegularPrecession& p, double t) { return angle_axis(p.b, p.beta * t) * angle_axis(p.a, p.alpha * t); }

// Omega_k = -1/2 eps_kij (R^T Rdot)_ij with Rdot from a fourth-order central difference of
// R_ref: truncation ~ (|Omega| h)^4 / 30 ~ 1e-12, round-off ~ eps / h ~ 2e-13 at h = 1e-3.
Vec3 omega_fd(const RegularPrecession& p, double t, bool lab) {
    const double h = 1e-3;
    const Mat3 Rd = (R_ref(p, t - 2 * h) - 8 * R_ref(p, t - h) + 8 * R_ref(p, t + h) - R_ref(p, t + 2 * h)) / (12 * h);
    const Mat3 R = R_ref(p, t);
    const Mat3 W = lab ? Mat3(Rd * R.transpose()) : Mat3(R.transpose() * Rd);
    return 0.5 * Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
}

RegularPrecession random_precession() {
    return {checks::random_unit(), checks::uniform(0.2, 3), checks::random_unit(), checks::uniform(0.2, 3)};
}

const double nan_ = std::numeric_limits<double>::quiet_NaN();

}  // namespace

TEST_SUITE("ch02_regular_precession") {
    TEST_CASE("precession_rotation: equals R^b(beta t) R^a(alpha t) from Eigen::AngleAxisd") {
        for (int n = 0; n < 30; ++n) {
            const RegularPrecession p = random_precession();
            const double t = checks::uniform(-10, 10);
            INPUTS(p, UNIT(t, "s"));
            CHECK_MAT_NEAR(rigid::precession_rotation(p, t), R_ref(p, t), 1e-14);
        }
    }

    TEST_CASE("precession_rotation: the factors come in the order of (1.4)") {
        // a = e3, b = e1 at alpha t = beta t = pi/2: R^b R^a sends e1 to e3, R^a R^b sends e1 to e2.
        const RegularPrecession p{Vec3::UnitZ(), 1.0, Vec3::UnitX(), 1.0};
        {
            const double t = pi / 2;
            INPUTS(p, UNIT(t, "s"));
            CHECK_MAT_NEAR(rigid::precession_rotation(p, t) * Vec3::UnitX(), Vec3::UnitZ(), 1e-15);
        }
        // Body points on the a axis only turn about b [P, after (1.4)].
        const RegularPrecession q = random_precession();
        for (double t : {0.3, 1.7, 5.0}) {
            INPUTS(q, UNIT(t, "s"));
            CHECK_MAT_NEAR(rigid::precession_rotation(q, t) * q.a, angle_axis(q.b, q.beta * t) * q.a, 1e-14);
        }
    }

    TEST_CASE("precession_rotation: normalises the axes and rejects bad input") {
        const RegularPrecession p{Vec3(0, 0, 5), 1.3, Vec3(2, 0, 2), 0.7};
        {
            const double t = 0.9;
            INPUTS(p, UNIT(t, "s"));
            CHECK_MAT_NEAR(rigid::precession_rotation(p, t), R_ref(p, t), 1e-15);
        }
        CHECK_THROWS_AS(rigid::precession_rotation({Vec3::Zero(), 1, Vec3::UnitX(), 1}, 0.1), std::invalid_argument);
        CHECK_THROWS_AS(rigid::precession_rotation({Vec3::UnitZ(), 1, Vec3(nan_, 0, 1), 1}, 0.1),
                        std::invalid_argument);
        CHECK_THROWS_AS(rigid::precession_rotation({Vec3::UnitZ(), 0.0, Vec3::UnitX(), 1}, 0.1), std::invalid_argument);
        CHECK_THROWS_AS(rigid::precession_rotation({Vec3::UnitZ(), 1, Vec3::UnitX(), -1}, 0.1), std::invalid_argument);
        CHECK_THROWS_AS(rigid::precession_rotation({Vec3::UnitZ(), 1, Vec3::UnitX(), 1}, nan_), std::invalid_argument);
    }

    TEST_CASE("precession_body_angular_velocity: matches finite differences of R(t) as in (1.5)") {
        for (int n = 0; n < 20; ++n) {
            const RegularPrecession p = random_precession();
            const double t = checks::uniform(-5, 5);
            INPUTS(p, UNIT(t, "s"));
            const Vec3 Omega = rigid::precession_body_angular_velocity(p, t);
            CHECK_MAT_NEAR(Omega, omega_fd(p, t, false), 2e-9);
        }
    }

    TEST_CASE("precession_body_angular_velocity: at t = 0 is alpha a + beta b and obeys the first form of (1.5)") {
        const RegularPrecession p{Vec3(1, 2, 2), 1.5, Vec3(0, 1, 0), 0.4};
        {
            const double t = 0.0;
            INPUTS(p, UNIT(t, "s"));
            CHECK_MAT_NEAR(rigid::precession_body_angular_velocity(p, t), 1.5 * p.a.normalized() + 0.4 * p.b, 1e-15);
        }
        // Omega^a + R^a(alpha t)^T Omega^b, with Omega^a = alpha a and Omega^b = beta b (1.2).
        const double t = 2.3;
        INPUTS(p, UNIT(t, "s"));
        const Vec3 first_form = 1.5 * p.a.normalized() + angle_axis(p.a, -1.5 * t) * (0.4 * p.b);
        CHECK_MAT_NEAR(rigid::precession_body_angular_velocity(p, t), first_form, 1e-15);
    }

    TEST_CASE("precession_lab_angular_velocity: equals R Omega and finite differences of R(t)") {
        for (int n = 0; n < 20; ++n) {
            const RegularPrecession p = random_precession();
            const double t = checks::uniform(-5, 5);
            INPUTS(p, UNIT(t, "s"));
            const Vec3 omega = rigid::precession_lab_angular_velocity(p, t);
            CHECK_MAT_NEAR(omega, omega_fd(p, t, true), 2e-9);
            CHECK_MAT_NEAR(omega, R_ref(p, t) * omega_fd(p, t, false), 2e-9);
        }
    }

    TEST_CASE("precession_omega_squared: equals |Omega(t)|^2 evaluated directly at many times") {
        for (int n = 0; n < 10; ++n) {
            const RegularPrecession p = random_precession();
            const double w2 = rigid::precession_omega_squared(p);
            for (double t : {0.0, 0.37, 1.9, 7.1}) {
                INPUTS(p);
                INFO("expected |Omega(t)|^2 in rad^2/s^2 from finite differences of R(t) at t = " << t << " s");
                const Vec3 Omega = omega_fd(p, t, false);
                CHECK_NEAR(w2, Omega.squaredNorm(), 1e-9 * (1 + w2));
            }
        }
    }

    TEST_CASE("precession_omega_squared: is not the printed (alpha + beta)^2 when a and b are not collinear") {
        // a, b at 60 degrees, alpha = 2, beta = 1: |Omega|^2 = 4 + 1 + 2 = 7, while (1.6) prints 9.
        const RegularPrecession p{Vec3::UnitZ(), 2.0, Vec3(std::sqrt(3.0) / 2, 0, 0.5), 1.0};
        INPUTS(p);
        CHECK_NEAR(rigid::precession_omega_squared(p), omega_fd(p, 0.8, false).squaredNorm(), 1e-9);
        CHECK_NEAR(rigid::precession_omega_squared(p), 7.0, 1e-14);
        // Orthogonal a, b (the only case Theorem 1 allows): alpha^2 + beta^2.
        const RegularPrecession q{Vec3::UnitZ(), 2.0, Vec3::UnitX(), 1.0};
        INPUTS(q);
        CHECK_NEAR(rigid::precession_omega_squared(q), 5.0, 1e-14);
    }

    TEST_CASE("precession_axial_component: equals a.Omega(t) evaluated directly as in (1.7)") {
        for (int n = 0; n < 10; ++n) {
            const RegularPrecession p = random_precession();
            const double c = rigid::precession_axial_component(p);
            for (double t : {0.0, 0.5, 2.5, 9.0}) {
                INPUTS(p);
                INFO("expected a.Omega(t) in rad/s from finite differences of R(t) at t = " << t << " s");
                CHECK_NEAR(c, p.a.normalized().dot(omega_fd(p, t, false)), 1e-9);
            }
        }
        CHECK_THROWS_AS(rigid::precession_axial_component({Vec3::UnitZ(), nan_, Vec3::UnitX(), 1}),
                        std::invalid_argument);
    }

    TEST_CASE("precession_omega_circle: every Omega(t) lies on it and it is centred on the a axis") {
        for (int n = 0; n < 10; ++n) {
            const RegularPrecession p = random_precession();
            INPUTS(p);
            const rigid::Circle c = rigid::precession_omega_circle(p);
            const Vec3 a = p.a.normalized();
            CHECK_NEAR(std::abs(c.normal.dot(a)), 1.0, 1e-14);
            CHECK_MAT_NEAR(c.centre - c.centre.dot(a) * a, Vec3::Zero(), 1e-14);
            for (double t : {0.0, 0.8, 2.0, 4.4}) {
                INFO("Omega(t) - c.centre in rad/s, from finite differences of R(t) at t = " << t << " s");
                const Vec3 d = omega_fd(p, t, false) - c.centre;
                CHECK_NEAR(d.dot(a), 0.0, 1e-9);
                CHECK_NEAR(d.norm(), c.radius, 1e-9);
            }
        }
    }

    TEST_CASE("precession_omega_circle: the radius keeps its digits for nearly collinear a and b") {
        // b at angle 1e-9 from a: radius beta sin(1e-9); sqrt(1 - (a, b)^2) would return 0 or 1.5e-8.
        const double d = 1e-9;
        const RegularPrecession p{Vec3::UnitZ(), 1.0, Vec3(std::sin(d), 0, std::cos(d)), 2.0};
        INPUTS(p);
        const rigid::Circle c = rigid::precession_omega_circle(p);
        CHECK_NEAR(c.radius, 2 * std::sin(d), 1e-22);
    }

    TEST_CASE("fit_circle: recovers a circle in a tilted plane") {
        for (int n = 0; n < 5; ++n) {
            const Vec3 centre = checks::random_vector(3), normal = checks::random_unit();
            const double radius = checks::uniform(0.1, 2);
            const Vec3 u = normal.unitOrthogonal(), v = normal.cross(u);
            INPUTS(centre, normal, radius, u, v);
            INFO("points: 40, centre + radius (cos th u + sin th v) at th = 0.3 + 1.7 k, k = 0, ..., 39");
            std::vector<Vec3> pts;
            for (int k = 0; k < 40; ++k) {
                const double th = 0.3 + 1.7 * k;  // scattered angles, all round the circle
                pts.push_back(centre + radius * (std::cos(th) * u + std::sin(th) * v));
            }
            const rigid::CircleFit f = rigid::fit_circle(pts);
            CHECK_MAT_NEAR(f.circle.centre, centre, 1e-13);
            CHECK_NEAR(std::abs(f.circle.normal.dot(normal)), 1.0, 1e-14);
            CHECK_NEAR(f.circle.radius, radius, 1e-13);
            CHECK_SMALL(f.plane_residual, 1e-13);
            CHECK_SMALL(f.circle_residual, 1e-13);
        }
    }

    TEST_CASE("fit_circle: measures how far an ellipse and a saddle curve are from a plane circle") {
        // Ellipse with semi-axes 2 and 1, sampled evenly: Kasa radius sqrt((4 + 1) / 2), and the
        // largest radial miss is sqrt(2.5) - 1 (at the minor axis). Plane residual zero.
        std::vector<Vec3> ellipse, saddle;
        const int n = 360;
        for (int k = 0; k < n; ++k) {
            const double th = 2 * pi * k / n;
            ellipse.push_back(Vec3(2 * std::cos(th), std::sin(th), 5.0));
            saddle.push_back(Vec3(std::cos(th), std::sin(th), 0.01 * std::cos(2 * th)));
        }
        const rigid::CircleFit e = rigid::fit_circle(ellipse);
        {
            INPUTS(n);
            INFO("points: the ellipse (2 cos th, sin th, 5) at th = 2 pi k / n, k = 0, ..., n - 1");
            CHECK_NEAR(e.circle.radius, std::sqrt(2.5), 1e-12);
            CHECK_NEAR(e.circle_residual, std::sqrt(2.5) - 1, 1e-12);
            CHECK_SMALL(e.plane_residual, 1e-13);
            CHECK_MAT_NEAR(e.circle.centre, Vec3(0, 0, 5), 1e-13);
        }
        // Saddle: best plane z = 0 by symmetry, so the plane residual is the height 0.01.
        const rigid::CircleFit s = rigid::fit_circle(saddle);
        INPUTS(n);
        INFO("points: the saddle (cos th, sin th, 0.01 cos 2 th) at th = 2 pi k / n, k = 0, ..., n - 1");
        CHECK_NEAR(s.plane_residual, 0.01, 1e-13);
        CHECK_NEAR(std::abs(s.circle.normal.z()), 1.0, 1e-12);
        CHECK_SMALL(s.circle_residual, 1e-12);
    }

    // The refusals are relative: a circle of radius 1e-3 far from the origin spans a plane as well as
    // one of radius 1 (a check of the largest singular value against an absolute number refuses it).
    // Points at irregular angles: every coefficient of the Kasa fit matters.
    TEST_CASE("fit_circle: recovers a small circle far from the origin from points on part of it") {
        const Vec3 centre(10, -20, 5), normal = Vec3(1, 2, 2) / 3;
        const Vec3 u = normal.unitOrthogonal(), v = normal.cross(u);
        for (double radius : {1e-3, 1e-1}) {
            INPUTS(centre, normal, radius, u, v);
            INFO(
                "points: centre + radius (cos th u + sin th v) at th = 0.1, 0.35, 0.5, 1.2, 1.4, 2.3, 2.45, 3, 3.9, "
                "4.1");
            std::vector<Vec3> pts;
            // Irregular angles over 3/4 of a turn: the centre is not the centroid of the points (as it
            // is for a full turn), nor on an axis of their scatter (as for evenly spaced points on an arc).
            for (double th : {0.1, 0.35, 0.5, 1.2, 1.4, 2.3, 2.45, 3.0, 3.9, 4.1})
                pts.push_back(centre + radius * (std::cos(th) * u + std::sin(th) * v));
            const rigid::CircleFit f = rigid::fit_circle(pts);
            // Round-off of coordinates of size 20: a few eps * 20 in the centre and the radius.
            CHECK_MAT_NEAR(f.circle.centre, centre, 1e-12);
            CHECK_NEAR(f.circle.radius, radius, 1e-12);
            CHECK_NEAR(std::abs(f.circle.normal.dot(normal)), 1.0, 1e-14);
            CHECK_SMALL(f.plane_residual, 1e-12);
            CHECK_SMALL(f.circle_residual, 1e-12);
        }
    }

    TEST_CASE("fit_circle: rejects too few or non-finite or coincident or collinear points") {
        CHECK_THROWS_AS(rigid::fit_circle({Vec3::UnitX(), Vec3::UnitY()}), std::invalid_argument);
        CHECK_THROWS_AS(rigid::fit_circle({Vec3::UnitX(), Vec3::UnitY(), Vec3(nan_, 0, 0)}), std::invalid_argument);
        CHECK_THROWS_AS(rigid::fit_circle({Vec3::UnitX(), Vec3::UnitX(), Vec3::UnitX()}), std::invalid_argument);
        CHECK_THROWS_AS(rigid::fit_circle({Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(3, 3, 3)}), std::invalid_argument);
        // The line rule on both sides of its threshold: four points whose centred coordinates are
        // orthogonal columns, so the singular values are sqrt(2) and sqrt(2) r, and r is their ratio.
        auto rhombus = [](double r) {
            return std::vector<Vec3>{Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, r, 0), Vec3(0, -r, 0)};
        };
        for (double r : {0.5e-12, 2e-12}) {
            const std::vector<Vec3> points = rhombus(r);
            INPUTS(points);
            if (r < 1e-12)
                CHECK_THROWS_AS(rigid::fit_circle(points), std::invalid_argument);
            else
                CHECK_NOTHROW(rigid::fit_circle(points));
        }
        // Three points of a triangle do span a plane: their circumcircle.
        const std::vector<Vec3> triangle{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0)};
        INPUTS(triangle);
        const rigid::CircleFit f = rigid::fit_circle(triangle);
        CHECK_NEAR(f.circle.radius, 1.0, 1e-14);
    }

}  // TEST_SUITE

// The derivation exercise of Chapter 2. The circle is checked against omega(t) = vee(Rdot R^T)
// from finite differences of R(t) built with Eigen (omega_fd above): every sample lies in the
// plane of the circle and at its radius from its centre, and over one period the samples go
// round the whole circle (their mean, at equally spaced phases, is the centre).
TEST_SUITE("ch02_regular_precession") {
    TEST_CASE("precession_lab_circle: omega(t) from R(t) lies on it and goes all the way round") {
        for (int n = 0; n < 20; ++n) {
            const RegularPrecession p = random_precession();
            INPUTS(p);
            const rigid::Circle c = rigid::precession_lab_circle(p);
            const double scale = p.alpha + p.beta;
            CHECK_NEAR(c.normal.norm(), 1.0, 1e-14);
            CHECK_NEAR(c.normal.dot(p.b.normalized()), 1.0, 1e-14);
            const int m = 24;
            Vec3 mean = Vec3::Zero();
            for (int j = 0; j < m; ++j) {
                const double t = 2 * pi / p.beta * j / m;  // omega(t) turns with the precession
                INFO("omega(t) in rad/s from finite differences of R(t) at t = " << t
                                                                                 << " s, in units of alpha + beta");
                const Vec3 w = omega_fd(p, t, true);
                mean += w / m;
                CHECK_NEAR((w - c.centre).dot(c.normal) / scale, 0.0, 1e-10);
                CHECK_NEAR(((w - c.centre) - (w - c.centre).dot(c.normal) * c.normal).norm() / scale, c.radius / scale,
                           1e-10);
            }
            INFO("the mean of omega(t) over one period (24 times), in units of alpha + beta");
            CHECK_MAT_NEAR(c.centre / scale, mean / scale, 1e-10);
        }
    }

    TEST_CASE("precession_lab_circle: orthogonal axes with alpha = 2 and beta = 1 give centre b and radius 2") {
        const RegularPrecession p{Vec3(0, 0, 3), 2.0, Vec3(0, 1, 0), 1.0};
        INPUTS(p);
        const rigid::Circle c = rigid::precession_lab_circle(p);
        CHECK_MAT_NEAR(c.centre, Vec3(0, 1, 0), 1e-15);
        CHECK_MAT_NEAR(c.normal, Vec3(0, 1, 0), 1e-15);
        CHECK_NEAR(c.radius, 2.0, 1e-15);
    }

    TEST_CASE("precession_lab_circle: bad input is rejected as by precession_rotation") {
        // A valid input first: a file that refuses every input earns nothing here.
        CHECK_NOTHROW((void)rigid::precession_lab_circle({Vec3::UnitX(), 1.0, Vec3::UnitZ(), 1.0}));
        CHECK_THROWS_AS(rigid::precession_lab_circle({Vec3::Zero(), 1.0, Vec3::UnitZ(), 1.0}), std::invalid_argument);
        CHECK_THROWS_AS(rigid::precession_lab_circle({Vec3::UnitX(), nan_, Vec3::UnitZ(), 1.0}), std::invalid_argument);
    }

}  // TEST_SUITE

// The worked example of the chapter, number by number, as the prose states it.
TEST_SUITE("ch02_regular_precession") {
    TEST_CASE("precession_body_angular_velocity: Omega(t) = (sin 2t; cos 2t; 2) in the worked example of Chapter 2") {
        const RegularPrecession p{Vec3::UnitZ(), 2.0, Vec3::UnitY(), 1.0};
        for (double t : {0.0, 0.1, 1.0, pi}) {
            INPUTS(p, UNIT(t, "s"));
            CHECK_MAT_NEAR(rigid::precession_body_angular_velocity(p, t), Vec3(std::sin(2 * t), std::cos(2 * t), 2.0),
                           1e-14);
        }
    }

    TEST_CASE("precession_omega_squared: 5 in the worked example of Chapter 2") {
        const RegularPrecession p{Vec3::UnitZ(), 2.0, Vec3::UnitY(), 1.0};
        INPUTS(p);
        CHECK_NEAR(rigid::precession_omega_squared(p), 5.0, 1e-14);
    }

    TEST_CASE("precession_axial_component: 2 in the worked example of Chapter 2") {
        const RegularPrecession p{Vec3::UnitZ(), 2.0, Vec3::UnitY(), 1.0};
        INPUTS(p);
        CHECK_NEAR(rigid::precession_axial_component(p), 2.0, 1e-14);
    }

    TEST_CASE("precession_omega_circle: centre (0; 0; 2) and radius 1 in the worked example of Chapter 2") {
        const RegularPrecession p{Vec3::UnitZ(), 2.0, Vec3::UnitY(), 1.0};
        INPUTS(p);
        const rigid::Circle c = rigid::precession_omega_circle(p);
        CHECK_MAT_NEAR(c.centre, Vec3(0, 0, 2), 1e-14);
        CHECK_NEAR(c.radius, 1.0, 1e-14);
    }

}  // TEST_SUITE

// ---- Bad input at its boundary: every "throws ... for ..." rule of exercises/rigid/precession.hpp ----
// The last bad value is refused with std::invalid_argument and the first good value beyond it
// is accepted, with the right answer. Graders check the exception's type, never its wording.
namespace {

const double tiny_ = std::numeric_limits<double>::denorm_min();
const double inf_ = std::numeric_limits<double>::infinity();

// Constants that break one rule each: a frequency at or just below 0 or not finite, an axis
// that is zero or not finite.
std::vector<RegularPrecession> bad_precessions() {
    const Vec3 a = Vec3(0, 0.6, 0.8), b = Vec3(1, 0, 1);
    std::vector<RegularPrecession> bad;
    for (double w : {0.0, -0.0, -tiny_, -1.0, inf_, -inf_, nan_}) {
        bad.push_back({a, w, b, 1.0});
        bad.push_back({a, 1.0, b, w});
    }
    for (const Vec3& v : {Vec3(0, 0, 0), Vec3(-0.0, 0, 0), Vec3(0, inf_, 1), Vec3(-inf_, 0, 0), Vec3(0, 0, nan_)}) {
        bad.push_back({v, 1.0, b, 1.0});
        bad.push_back({a, 1.0, v, 1.0});
    }
    return bad;
}

// The first good constants beyond the rules: the smallest positive frequency, axes of length
// 1e-300 (normalised as any other).
std::vector<RegularPrecession> edge_precessions() {
    const Vec3 a = Vec3(0, 0.6, 0.8), b = Vec3(1, 0, 1);
    return {{a, tiny_, b, 1.3}, {a, 0.7, b, tiny_}, {1e-300 * a, 0.7, 1e-300 * b, 1.3}};
}

}  // namespace

TEST_SUITE("ch02_regular_precession") {
    TEST_CASE(
        "precession_rotation: rejects alpha or beta <= 0 or a bad axis or time and accepts the smallest alpha and "
        "beta") {
        const double t0 = 0.4;
        for (const RegularPrecession& p : bad_precessions()) {
            INPUTS(p, UNIT(t0, "s"));
            CHECK_THROWS_AS(rigid::precession_rotation(p, t0), std::invalid_argument);
        }
        const RegularPrecession good{Vec3(0, 0.6, 0.8), 0.7, Vec3(1, 0, 1), 1.3};
        for (double t : {nan_, inf_, -inf_}) {
            INPUTS(good, UNIT(t, "s"));
            CHECK_THROWS_AS(rigid::precession_rotation(good, t), std::invalid_argument);
        }
        for (const RegularPrecession& p : edge_precessions()) {
            INPUTS(p, UNIT(t0, "s"));
            CHECK_MAT_NEAR(
                rigid::precession_rotation(p, t0),
                angle_axis(p.b.stableNormalized(), p.beta * t0) * angle_axis(p.a.stableNormalized(), p.alpha * t0),
                4e-15);
        }
    }

    TEST_CASE(
        "precession_body_angular_velocity: rejects alpha or beta <= 0 or a bad axis or time and accepts the smallest "
        "alpha and beta") {
        const double t0 = 0.4;
        for (const RegularPrecession& p : bad_precessions()) {
            INPUTS(p, UNIT(t0, "s"));
            CHECK_THROWS_AS(rigid::precession_body_angular_velocity(p, t0), std::invalid_argument);
        }
        const RegularPrecession good{Vec3(0, 0.6, 0.8), 0.7, Vec3(1, 0, 1), 1.3};
        for (double t : {nan_, inf_, -inf_}) {
            INPUTS(good, UNIT(t, "s"));
            CHECK_THROWS_AS(rigid::precession_body_angular_velocity(good, t), std::invalid_argument);
        }
        for (const RegularPrecession& p : edge_precessions()) {
            INPUTS(p, UNIT(t0, "s"));
            const Vec3 a = p.a.stableNormalized(), b = p.b.stableNormalized();
            const Vec3 expected = p.alpha * a + p.beta * angle_axis(a, p.alpha * t0).transpose() * b;
            CHECK_MAT_NEAR(rigid::precession_body_angular_velocity(p, t0), expected, 4e-15);
        }
    }

    TEST_CASE(
        "precession_lab_angular_velocity: rejects alpha or beta <= 0 or a bad axis or time and accepts the smallest "
        "alpha and beta") {
        const double t0 = 0.4;
        for (const RegularPrecession& p : bad_precessions()) {
            INPUTS(p, UNIT(t0, "s"));
            CHECK_THROWS_AS(rigid::precession_lab_angular_velocity(p, t0), std::invalid_argument);
        }
        const RegularPrecession good{Vec3(0, 0.6, 0.8), 0.7, Vec3(1, 0, 1), 1.3};
        for (double t : {nan_, inf_, -inf_}) {
            INPUTS(good, UNIT(t, "s"));
            CHECK_THROWS_AS(rigid::precession_lab_angular_velocity(good, t), std::invalid_argument);
        }
        for (const RegularPrecession& p : edge_precessions()) {
            INPUTS(p, UNIT(t0, "s"));
            const Vec3 a = p.a.stableNormalized(), b = p.b.stableNormalized();
            const Vec3 expected = p.beta * b + p.alpha * angle_axis(b, p.beta * t0) * a;
            CHECK_MAT_NEAR(rigid::precession_lab_angular_velocity(p, t0), expected, 4e-15);
        }
    }

    TEST_CASE(
        "precession_omega_squared: rejects alpha or beta <= 0 or a bad axis and accepts the smallest alpha and beta") {
        for (const RegularPrecession& p : bad_precessions()) {
            INPUTS(p);
            CHECK_THROWS_AS((void)rigid::precession_omega_squared(p), std::invalid_argument);
        }
        for (const RegularPrecession& p : edge_precessions()) {
            INPUTS(p);
            // |Omega(0)|^2 = |alpha a + beta b|^2.
            const Vec3 W0 = p.alpha * p.a.stableNormalized() + p.beta * p.b.stableNormalized();
            CHECK_NEAR(rigid::precession_omega_squared(p), W0.squaredNorm(), 4e-15);
        }
    }

    TEST_CASE(
        "precession_axial_component: rejects alpha or beta <= 0 or a bad axis and accepts the smallest alpha and "
        "beta") {
        for (const RegularPrecession& p : bad_precessions()) {
            INPUTS(p);
            CHECK_THROWS_AS((void)rigid::precession_axial_component(p), std::invalid_argument);
        }
        for (const RegularPrecession& p : edge_precessions()) {
            INPUTS(p);
            const Vec3 a = p.a.stableNormalized(), W0 = p.alpha * a + p.beta * p.b.stableNormalized();
            CHECK_NEAR(rigid::precession_axial_component(p), a.dot(W0), 4e-15);
        }
    }

    TEST_CASE(
        "precession_omega_circle: rejects alpha or beta <= 0 or a bad axis and accepts the smallest alpha and beta") {
        for (const RegularPrecession& p : bad_precessions()) {
            INPUTS(p);
            CHECK_THROWS_AS((void)rigid::precession_omega_circle(p), std::invalid_argument);
        }
        for (const RegularPrecession& p : edge_precessions()) {
            INPUTS(p);
            const Vec3 a = p.a.stableNormalized(), W0 = p.alpha * a + p.beta * p.b.stableNormalized();
            const rigid::Circle c = rigid::precession_omega_circle(p);
            CHECK_MAT_NEAR(c.centre, a.dot(W0) * a, 1e-15);
            CHECK_MAT_NEAR(c.normal, a, 1e-15);
            CHECK_NEAR(c.radius, (W0 - a.dot(W0) * a).norm(), 4e-15);
        }
    }

    TEST_CASE(
        "precession_lab_circle: rejects alpha or beta <= 0 or a bad axis and accepts the smallest alpha and beta") {
        for (const RegularPrecession& p : bad_precessions()) {
            INPUTS(p);
            CHECK_THROWS_AS((void)rigid::precession_lab_circle(p), std::invalid_argument);
        }
        for (const RegularPrecession& p : edge_precessions()) {
            INPUTS(p);
            const Vec3 b = p.b.stableNormalized(), w0 = p.alpha * p.a.stableNormalized() + p.beta * b;
            const rigid::Circle c = rigid::precession_lab_circle(p);
            CHECK_MAT_NEAR(c.centre, b.dot(w0) * b, 4e-15);
            CHECK_MAT_NEAR(c.normal, b, 1e-15);
            CHECK_NEAR(c.radius, (w0 - b.dot(w0) * b).norm(), 4e-15);
        }
    }

    TEST_CASE("fit_circle: rejects an infinite point and accepts exactly 3 points") {
        CHECK_THROWS_AS(rigid::fit_circle({Vec3::UnitX(), Vec3(0, -inf_, 0), Vec3::UnitZ()}), std::invalid_argument);
        CHECK_THROWS_AS(rigid::fit_circle({Vec3::UnitX(), Vec3::UnitY(), Vec3(0, 0, inf_)}), std::invalid_argument);
        CHECK_THROWS_AS(rigid::fit_circle({}), std::invalid_argument);
        // 3 points, the fewest allowed: the circumcircle of (0, 0, 2), (0, 2, 0), (2, 0, 0).
        const std::vector<Vec3> points{Vec3(0, 0, 2), Vec3(0, 2, 0), Vec3(2, 0, 0)};
        INPUTS(points);
        const rigid::CircleFit f = rigid::fit_circle(points);
        CHECK_MAT_NEAR(f.circle.centre, Vec3(2, 2, 2) / 3, 1e-14);
        CHECK_NEAR(f.circle.radius, std::sqrt(8.0 / 3), 1e-14);
        CHECK_NEAR(std::abs(f.circle.normal.dot(Vec3(1, 1, 1) / std::sqrt(3.0))), 1.0, 1e-14);
    }
}  // TEST_SUITE
