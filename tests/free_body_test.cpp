// Graders for Chapter 3, the free body (rigid/free_body.hpp). Each test name starts with the
// exercise it grades; each cross-checks against an independent computation: the equations
// written out with the Levi-Civita symbol or by components, and the exact elliptic motion
// (rigid/free_body_exact.hpp, provided) integrated against with GSL's rk8pd.
#include "rigid/free_body.hpp"

#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <vector>

#include "checks.hpp"
#include "inputs.hpp"
#include "rigid/free_body_exact.hpp"
#include "rigid/ode.hpp"

using rigid::Mat3;
using rigid::Vec3;
using rigid::VecX;

namespace {

using checks::inf_;
using checks::nan_;

double eps3(int i, int j, int k) { return 0.5 * (i - j) * (j - k) * (k - i); }

Vec3 random_moments() {
    // Three moments that obey the triangle inequality: I_k = sum of two positive "mass" terms.
    const double x = checks::uniform(0.2, 2), y = checks::uniform(0.2, 2), z = checks::uniform(0.2, 2);
    return Vec3(y + z, z + x, x + y);
}

Mat3 random_rotation() { return Eigen::AngleAxisd(checks::uniform(0, 3), checks::random_unit()).toRotationMatrix(); }

}  // namespace

TEST_SUITE("ch03_free_body") {
    TEST_CASE("euler_rhs: equals Euler's equations written by components") {
        for (int n = 0; n < 20; ++n) {
            const Vec3 I = random_moments(), w = checks::random_vector(3);
            INPUTS(UNIT(I, "kg·m²"), UNIT(w, "rad/s"));
            INPUTS(UNIT(I, "kg·m²"));
            const Vec3 expected((I(1) - I(2)) * w(1) * w(2) / I(0), (I(2) - I(0)) * w(2) * w(0) / I(1),
                                (I(0) - I(1)) * w(0) * w(1) / I(2));
            CHECK_MAT_NEAR(rigid::euler_rhs(I, w), expected, 1e-14);
        }
    }

    TEST_CASE("euler_rhs: vanishes along principal axes and keeps Omega3 of a symmetric body") {
        const Vec3 I(1.0, 2.0, 2.5);
        INPUTS(UNIT(I, "kg·m²"));
        for (int k = 0; k < 3; ++k) CHECK_MAT_NEAR(rigid::euler_rhs(I, 1.7 * Vec3::Unit(k)), Vec3::Zero(), 0.0);
        const Vec3 d = rigid::euler_rhs(Vec3(1.5, 1.5, 2.0), Vec3(0.3, -0.8, 1.1));
        CHECK_SMALL(std::abs(d(2)), 1e-16);
        CHECK(d.norm() > 0.1);
    }

    TEST_CASE("poisson_rhs: equals -eps_jkm Omega_k R_im of (6.8)") {
        for (int n = 0; n < 10; ++n) {
            const Mat3 R = random_rotation();
            INPUTS(R);
            const Vec3 w = checks::random_vector(2);
            INPUTS(UNIT(w, "rad/s"));
            Mat3 expected = Mat3::Zero();
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    for (int k = 0; k < 3; ++k)
                        for (int m = 0; m < 3; ++m) expected(i, j) -= eps3(j + 1, k + 1, m + 1) * w(k) * R(i, m);
            CHECK_MAT_NEAR(rigid::poisson_rhs(R, w), expected, 1e-15);
        }
    }

    TEST_CASE("poisson_rhs: moves every body vector with the velocity omega x x") {
        // d/dt (R x_body) = R (Omega x x_body) = omega x (R x_body), omega = R Omega.
        const Mat3 R = random_rotation();
        INPUTS(R);
        const Vec3 w = checks::random_vector(2), x = checks::random_vector(1);
        INPUTS(UNIT(w, "rad/s"), x);
        CHECK_MAT_NEAR(rigid::poisson_rhs(R, w) * x, (R * w).cross(R * x), 1e-14);
    }

    TEST_CASE("free_body_equations: packs (6.7) and (6.8) in the documented layout") {
        const Vec3 I = random_moments(), w = checks::random_vector(2);
        INPUTS(UNIT(I, "kg·m²"), UNIT(w, "rad/s"));
        const Mat3 R = random_rotation();
        INPUTS(R);
        const rigid::OdeRhs f = rigid::free_body_equations(I);
        VecX y(12);
        INPUTS(y);
        y << w, R.row(0).transpose(), R.row(1).transpose(), R.row(2).transpose();
        const VecX d = f(0.3, y);
        REQUIRE(d.size() == 12);
        const Vec3 ew((I(1) - I(2)) * w(1) * w(2) / I(0), (I(2) - I(0)) * w(2) * w(0) / I(1),
                      (I(0) - I(1)) * w(0) * w(1) / I(2));
        CHECK_MAT_NEAR(d.head<3>(), ew, 1e-14);
        // Row i of R hat(Omega) is (row i of R) x Omega, as a cross product.
        for (int i = 0; i < 3; ++i) CHECK_MAT_NEAR(d.segment<3>(3 + 3 * i), Vec3(R.row(i).transpose().cross(w)), 1e-15);
    }

    TEST_CASE("free_body_equations: integrated by rk8pd it follows the exact elliptic motion") {
        for (const Vec3& w0 : {Vec3(0.3, -2.0, 0.5), Vec3(1.2, 0.4, -0.9), Vec3(0.01, 3.0, 0.02)}) {
            INPUTS(UNIT(w0, "rad/s"));
            const Vec3 I(1.0, 2.0, 2.6);
            INPUTS(UNIT(I, "kg·m²"));
            const auto times = rigid::linspace(0, 8, 16);
            const auto exact = rigid::free_body_motion(I, w0);
            const auto R_ex = rigid::free_body_exact_rotations(exact, times);
            double err = 0;
            std::size_t k = 0;
            rigid::integrate_gsl(rigid::free_body_equations(I), rigid::pack({w0, Mat3::Identity()}), times,
                                 [&](double t, const VecX& y) {
                                     const rigid::BodyState s = rigid::unpack(y);
                                     err = std::max(
                                         err, (s.Omega - rigid::free_body_exact_omega(exact, t)).norm() / w0.norm());
                                     err = std::max(err, (s.R - R_ex[k++]).norm());
                                 },
                                 {.method = "rk8pd", .rel_tol = 1e-12, .abs_tol = 1e-12});
            CHECK_SMALL(err, 1e-8);
        }
    }

    TEST_CASE("free_body_equations: rejects bad moments and accepts a flat body") {
        CHECK_THROWS_AS(rigid::free_body_equations(Vec3(-1, 2, 2)), std::invalid_argument);
        CHECK_THROWS_AS(rigid::free_body_equations(Vec3(0, 2, 2)), std::invalid_argument);
        CHECK_THROWS_AS(rigid::free_body_equations(Vec3(1, 2, 3.5)), std::invalid_argument);
        CHECK_THROWS_AS(rigid::free_body_equations(Vec3(4, 1, 2)), std::invalid_argument);
        CHECK_THROWS_AS(rigid::free_body_equations(Vec3(1, 1.5, 3)), std::invalid_argument);
        CHECK_THROWS_AS(rigid::free_body_equations(Vec3(1, nan_, 2)), std::invalid_argument);
        CHECK_THROWS_AS(rigid::free_body_equations(Vec3(1, 2, inf_)), std::invalid_argument);
        // I1 + I2 = I3 is a flat body: admissible, and its equations work.
        const Vec3 I(1, 2, 3), Omega(1, 1, 1);
        INPUTS(UNIT(I, "kg·m²"), UNIT(Omega, "rad/s"));
        INFO("the right-hand side at t = 0 and R = 1");
        const rigid::OdeRhs f = rigid::free_body_equations(I);
        const VecX d = f(0.0, rigid::pack({Omega, Mat3::Identity()}));
        CHECK_NEAR(d(0), (2.0 - 3.0) / 1.0, 1e-15);
    }

    TEST_CASE("rotational_energy: is half of Omega . I Omega") {
        for (int n = 0; n < 10; ++n) {
            const Vec3 I = random_moments(), w = checks::random_vector(3);
            INPUTS(UNIT(I, "kg·m²"), UNIT(w, "rad/s"));
            CHECK_NEAR(rigid::rotational_energy(I, w), 0.5 * w.dot(I.asDiagonal() * w), 1e-14);
        }
        const Vec3 I(1, 2, 3), w(1, 1, 1);
        INPUTS(UNIT(I, "kg·m²"), UNIT(w, "rad/s"));
        CHECK_NEAR(rigid::rotational_energy(I, w), 3.0, 0.0);
    }

    TEST_CASE("angular_momentum_squared: is |I Omega|^2") {
        for (int n = 0; n < 10; ++n) {
            const Vec3 I = random_moments(), w = checks::random_vector(3);
            INPUTS(UNIT(I, "kg·m²"), UNIT(w, "rad/s"));
            CHECK_NEAR(rigid::angular_momentum_squared(I, w), (I.asDiagonal() * w).squaredNorm(), 1e-13);
        }
        const Vec3 I(1, 2, 3), w(1, 1, 1);
        INPUTS(UNIT(I, "kg·m²"), UNIT(w, "rad/s"));
        CHECK_NEAR(rigid::angular_momentum_squared(I, w), 14.0, 0.0);
    }

    TEST_CASE("rotational_energy: both integrals of (6.9) are constant along the exact motion") {
        const Vec3 I(1.0, 1.7, 2.2), w0(0.8, -0.6, 1.4);
        INPUTS(UNIT(I, "kg·m²"), UNIT(w0, "rad/s"));
        const auto mo = rigid::free_body_motion(I, w0);
        const double E0 = rigid::rotational_energy(I, w0), M0 = (I.asDiagonal() * w0).squaredNorm();
        for (double t : {0.5, 7.0, 60.0}) {
            const Vec3 w = rigid::free_body_exact_omega(mo, t);
            CHECK_NEAR(rigid::rotational_energy(I, w), E0, 1e-14 * E0);
            CHECK_NEAR((I.asDiagonal() * w).squaredNorm(), M0, 1e-14 * M0);
        }
    }

}  // TEST_SUITE

// The derivation exercise of Chapter 3. The reference is Euler's equation itself, linearised
// numerically: its Jacobian at Omega = spin e_axis by central differences (exact up to
// round-off, the right-hand side being quadratic) and the eigenvalues of that 3 x 3 matrix,
// lambda = +-i nu (stable) or +-sqrt(-nu^2) (unstable), and 0 along the axis.
namespace {

Vec3 euler_written_out(const Vec3& I, const Vec3& W) {  // I W' = (I W) x W, by components
    return Vec3((I(1) - I(2)) * W(1) * W(2) / I(0), (I(2) - I(0)) * W(2) * W(0) / I(1),
                (I(0) - I(1)) * W(0) * W(1) / I(2));
}

double nu_squared_from_jacobian(const Vec3& I, int axis, double spin) {
    Vec3 W0 = Vec3::Zero();
    W0(axis) = spin;
    Mat3 J;
    const double h = 1e-3 * (1 + std::abs(spin));
    for (int c = 0; c < 3; ++c) {
        Vec3 d = Vec3::Zero();
        d(c) = h;
        J.col(c) = (euler_written_out(I, W0 + d) - euler_written_out(I, W0 - d)) / (2 * h);
    }
    const Eigen::Vector3cd lambda = Eigen::EigenSolver<Mat3>(J).eigenvalues();
    std::complex<double> big = 0;  // the pair +-lambda; lambda^2 = -nu^2
    for (int k = 0; k < 3; ++k)
        if (std::abs(lambda(k)) > std::abs(big)) big = lambda(k);
    return -(big * big).real();
}

}  // namespace

TEST_SUITE("ch03_free_body") {
    TEST_CASE("wobble_frequency_squared: equals -lambda^2 of Euler's equation linearised about the spin") {
        for (int n = 0; n < 30; ++n) {
            const Vec3 I = random_moments();
            INPUTS(UNIT(I, "kg·m²"));
            const int axis = n % 3;
            INPUTS(axis);
            const double spin = checks::uniform(-3, 3);
            INPUTS(UNIT(spin, "rad/s"));
            INPUTS(UNIT(I, "kg·m²"));
            INPUTS(axis);
            INPUTS(UNIT(spin, "rad/s"));
            const double expected = nu_squared_from_jacobian(I, axis, spin);
            CHECK_NEAR(rigid::wobble_frequency_squared(I, axis, spin), expected, 1e-10 * spin * spin);
        }
    }

    TEST_CASE(
        "wobble_frequency_squared: stable about the largest and smallest axes and unstable about the middle one") {
        const Vec3 I(1.0, 2.0, 3.0);
        INPUTS(UNIT(I, "kg·m²"));
        CHECK(rigid::wobble_frequency_squared(I, 0, 1.0) > 0.1);
        CHECK(rigid::wobble_frequency_squared(I, 2, 1.0) > 0.1);
        CHECK(rigid::wobble_frequency_squared(I, 1, 1.0) < -0.1);
        // A disturbance about the middle axis grows like exp(sqrt(-nu^2) t): measured by integrating
        // Euler's equation (RK4, dt = 1e-3) from a 1e-9 kick, between t = 10 and t = 20 (where the
        // decaying mode is gone and the disturbance, near 1e-4, is still small).
        Vec3 W(1e-9, 1.0, 0.0);
        const double dt = 1e-3;
        double at10 = 0;
        for (int s = 1; s <= 20000; ++s) {
            const Vec3 k1 = euler_written_out(I, W), k2 = euler_written_out(I, W + 0.5 * dt * k1),
                       k3 = euler_written_out(I, W + 0.5 * dt * k2), k4 = euler_written_out(I, W + dt * k3);
            W += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
            if (s == 10000) at10 = std::hypot(W(0), W(2));
        }
        const double growth = std::log(std::hypot(W(0), W(2)) / at10) / 10.0;
        CHECK_NEAR(std::sqrt(-rigid::wobble_frequency_squared(I, 1, 1.0)), growth, 1e-3);
    }

    TEST_CASE("wobble_frequency_squared: rejects moments that are no body or a bad axis or a non-finite spin") {
        // A valid input first: a file that refuses every input earns nothing here.
        CHECK_NOTHROW((void)rigid::wobble_frequency_squared(Vec3(1, 2, 2.5), 0, 1.0));
        CHECK_THROWS_AS(rigid::wobble_frequency_squared(Vec3(1, 1, 3), 0, 1.0), std::invalid_argument);
        CHECK_THROWS_AS(rigid::wobble_frequency_squared(Vec3(-1, 2, 2), 0, 1.0), std::invalid_argument);
        CHECK_THROWS_AS(rigid::wobble_frequency_squared(Vec3(1, 2, 2.5), 3, 1.0), std::invalid_argument);
        CHECK_THROWS_AS(rigid::wobble_frequency_squared(Vec3(1, 2, 2.5), -1, 1.0), std::invalid_argument);
        CHECK_THROWS_AS(rigid::wobble_frequency_squared(Vec3(1, 2, 2.5), 1, nan_), std::invalid_argument);
    }

}  // TEST_SUITE

// The worked example of the chapter, number by number, as the prose states it.
TEST_SUITE("ch03_free_body") {
    TEST_CASE("rotational_energy: E = 3 for I = (2; 3; 4) and Omega = (1; 0; 1) in the worked example of Chapter 3") {
        const Vec3 I(2, 3, 4), Omega(1, 0, 1);
        INPUTS(UNIT(I, "kg·m²"), UNIT(Omega, "rad/s"));
        CHECK_NEAR(rigid::rotational_energy(I, Omega), 3.0, 1e-15);
    }

    TEST_CASE("angular_momentum_squared: M^2 = 20 in the worked example of Chapter 3") {
        const Vec3 I(2, 3, 4), Omega(1, 0, 1);
        INPUTS(UNIT(I, "kg·m²"), UNIT(Omega, "rad/s"));
        CHECK_NEAR(rigid::angular_momentum_squared(I, Omega), 20.0, 1e-14);
    }

    TEST_CASE("euler_rhs: dOmega/dt = (0; 2/3; 0) in the worked example of Chapter 3") {
        const Vec3 I(2, 3, 4), Omega(1, 0, 1);
        INPUTS(UNIT(I, "kg·m²"), UNIT(Omega, "rad/s"));
        CHECK_MAT_NEAR(rigid::euler_rhs(I, Omega), Vec3(0, 2.0 / 3, 0), 1e-15);
    }

}  // TEST_SUITE

// ---- Bad input at its boundary: every "throws ... for ..." rule of exercises/rigid/free_body.hpp ----
// The last bad value is refused with std::invalid_argument and the first good value beyond it
// is accepted, with the right answer. Graders check the exception's type, never its wording.
namespace {

// Moments that are no body, each just across one rule: a moment at or just below 0 or not
// finite, or one moment 1e-12 (about 1500 ulp) more than the sum of the other two.
std::vector<Vec3> bad_moments() {
    const double tiny = std::numeric_limits<double>::denorm_min();
    std::vector<Vec3> bad;
    for (double x : {0.0, -0.0, -tiny, inf_, -inf_, nan_})
        for (int i = 0; i < 3; ++i) {
            Vec3 I(2, 3, 4);
            I(i) = x;
            bad.push_back(I);
        }
    bad.push_back(Vec3(1, 2, 3 + 1e-12));
    bad.push_back(Vec3(3 + 1e-12, 1, 2));
    bad.push_back(Vec3(2, 3 + 1e-12, 1));
    return bad;
}

}  // namespace

TEST_SUITE("ch03_free_body") {
    TEST_CASE(
        "free_body_equations: rejects moments just across each rule and accepts the flat body and a tiny moment") {
        for (const Vec3& I : bad_moments()) {
            INPUTS(UNIT(I, "kg·m²"));
            CHECK_THROWS_AS(rigid::free_body_equations(I), std::invalid_argument);
        }
        // The triangle inequality with equality, in each position, is a flat body: accepted.
        const VecX y = rigid::pack({Vec3(1, 1, 1), Mat3::Identity()});
        for (const Vec3& I : {Vec3(1, 2, 3), Vec3(3, 1, 2), Vec3(2, 3, 1)}) {
            INPUTS(UNIT(I, "kg·m²"));
            INFO("the right-hand side at t = 0, Omega = (1, 1, 1) rad/s and R = 1");
            const VecX d = rigid::free_body_equations(I)(0.0, y);
            CHECK_MAT_NEAR(d.head<3>(), Vec3((I(1) - I(2)) / I(0), (I(2) - I(0)) / I(1), (I(0) - I(1)) / I(2)), 1e-15);
        }
        // A moment just above 0 (a thin rod along that axis) is a body too.
        CHECK_NOTHROW(rigid::free_body_equations(Vec3(1e-300, 1, 1)));
    }

    TEST_CASE(
        "wobble_frequency_squared: rejects moments or an axis or a spin just across each rule and accepts the edges") {
        for (const Vec3& I : bad_moments()) {
            INPUTS(UNIT(I, "kg·m²"));
            CHECK_THROWS_AS((void)rigid::wobble_frequency_squared(I, 0, 1.0), std::invalid_argument);
        }
        const Vec3 I(1, 2, 3);  // flat: accepted
        INPUTS(UNIT(I, "kg·m²"));
        for (int axis : {-1, 3}) {
            INPUTS(axis);
            CHECK_THROWS_AS((void)rigid::wobble_frequency_squared(I, axis, 1.0), std::invalid_argument);
        }
        for (double spin : {nan_, inf_, -inf_}) {
            INPUTS(UNIT(spin, "rad/s"));
            CHECK_THROWS_AS((void)rigid::wobble_frequency_squared(I, 1, spin), std::invalid_argument);
        }
        // The first and last axis, a spin of 0 and a negative spin are all valid. About axis k,
        // nu^2 = spin^2 (I_k - I_i)(I_k - I_j) / (I_i I_j).
        CHECK_NEAR(rigid::wobble_frequency_squared(I, 0, 2.0), 4.0 * (1 - 2) * (1 - 3) / (2 * 3), 1e-15);
        CHECK_NEAR(rigid::wobble_frequency_squared(I, 2, -1.0), (3 - 1) * (3 - 2) / (1 * 2.0), 1e-15);
        CHECK_SMALL(std::abs(rigid::wobble_frequency_squared(I, 1, 0.0)), 0.0);
    }
}  // TEST_SUITE
