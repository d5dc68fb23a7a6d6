// Checks of the provided GSL wrapper (rigid/ode.hpp). Not graders: nothing here is an
// exercise, so these tests are outside the stub gate.
#include "rigid/ode.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "checks.hpp"

using rigid::VecX;

TEST_SUITE("provided_ode") {
    TEST_CASE("integrate_gsl: the harmonic oscillator follows cos and sin with every explicit method") {
        const rigid::OdeRhs f = [](double, const VecX& y) { return VecX{{y(1), -y(0)}}; };
        for (const char* m : {"rk2", "rk4", "rkf45", "rkck", "rk8pd", "msadams"}) {
            CAPTURE(m);
            double worst = 0;
            const auto stats =
                rigid::integrate_gsl(f, VecX{{1.0, 0.0}}, rigid::linspace(0, 10, 20),
                                     [&](double t, const VecX& y) {
                                         worst = std::max(worst, std::hypot(y(0) - std::cos(t), y(1) + std::sin(t)));
                                     },
                                     {.method = m, .rel_tol = 1e-10, .abs_tol = 1e-10});
            CHECK_SMALL(worst, 1e-7);
            CHECK(stats.rhs_calls > 0);
        }
    }

    TEST_CASE("integrate_gsl: implicit methods use the Jacobian") {
        const rigid::OdeRhs f = [](double, const VecX& y) { return VecX{{y(1), -y(0)}}; };
        const rigid::OdeJacobian J = [](double, const VecX&) { return rigid::MatX{{0.0, 1.0}, {-1.0, 0.0}}; };
        for (const char* m : {"rk4imp", "bsimp", "msbdf"}) {
            CAPTURE(m);
            VecX last;
            const auto stats = rigid::integrate_gsl(
                f, VecX{{1.0, 0.0}}, {0.0, 5.0}, [&](double, const VecX& y) { last = y; },
                {.method = m, .rel_tol = 1e-10, .abs_tol = 1e-10}, J);
            CHECK_SMALL(std::hypot(last(0) - std::cos(5.0), last(1) + std::sin(5.0)), 1e-6);
            CHECK(stats.jacobian_calls > 0);
        }
        CHECK_THROWS_AS(
            rigid::integrate_gsl(f, VecX{{1.0, 0.0}}, {0.0, 1.0}, [](double, const VecX&) {}, {.method = "bsimp"}),
            std::invalid_argument);
    }

    TEST_CASE("integrate_gsl: rejects bad settings and passes the right-hand side's exceptions through") {
        const rigid::OdeRhs f = [](double, const VecX& y) { return VecX(-y); };
        const auto ignore = [](double, const VecX&) {};
        CHECK_THROWS_AS(rigid::integrate_gsl(f, VecX::Ones(2), {0.0, 1.0}, ignore, {.method = "euler"}),
                        std::invalid_argument);
        CHECK_THROWS_AS(rigid::integrate_gsl(f, VecX::Ones(2), {1.0, 0.0}, ignore), std::invalid_argument);
        CHECK_THROWS_AS(rigid::integrate_gsl(f, VecX::Ones(2), {0.0, 1.0}, ignore, {.rel_tol = -1}),
                        std::invalid_argument);
        CHECK_THROWS_AS(rigid::integrate_gsl(f, VecX{{1.0, NAN}}, {0.0, 1.0}, ignore), std::invalid_argument);
        const rigid::OdeRhs throws = [](double t, const VecX& y) -> VecX {
            if (t > 0.5) throw std::domain_error("from the right-hand side");
            return -y;
        };
        CHECK_THROWS_AS(rigid::integrate_gsl(throws, VecX::Ones(2), {0.0, 1.0}, ignore), std::domain_error);
    }

    TEST_CASE("integrate_gsl: a right-hand side in place gives exactly the same states as an OdeRhs") {
        const rigid::OdeRhs f = [](double, const VecX& y) { return VecX{{y(1), -y(0)}}; };
        const rigid::OdeRhsInPlace g = [](double, const double* y, double* dydt) { dydt[0] = y[1], dydt[1] = -y[0]; };
        for (bool compensated : {false, true}) {
            std::vector<VecX> a, b;
            const rigid::OdeSettings set{
                .method = "rk8pd", .rel_tol = 1e-12, .abs_tol = 1e-12, .compensated_time = compensated};
            const auto sa = rigid::integrate_gsl(
                f, VecX{{1.0, 0.0}}, rigid::linspace(0, 30, 7), [&](double, const VecX& y) { a.push_back(y); }, set);
            const auto sb = rigid::integrate_gsl(
                g, VecX{{1.0, 0.0}}, rigid::linspace(0, 30, 7), [&](double, const VecX& y) { b.push_back(y); }, set);
            REQUIRE(a.size() == b.size());
            for (std::size_t i = 0; i < a.size(); ++i) CHECK(checks::max_abs_diff(a[i], b[i]) == 0.0);
            CHECK(sa.rhs_calls == sb.rhs_calls);
        }
    }

    TEST_CASE("integrate_gsl: compensated_time keeps GSL's step control and follows the motion") {
        const rigid::OdeRhsInPlace g = [](double, const double* y, double* dydt) { dydt[0] = y[1], dydt[1] = -y[0]; };
        for (const char* m : {"rk2", "rk4", "rkf45", "rkck", "rk8pd"}) {
            CAPTURE(m);
            long calls[2] = {0, 0};
            for (int c = 0; c < 2; ++c) {
                double worst = 0, last_t = -1;
                calls[c] = rigid::integrate_gsl(
                               g, VecX{{1.0, 0.0}}, rigid::linspace(0, 50, 40),
                               [&](double t, const VecX& y) {
                                   worst = std::max(worst, std::hypot(y(0) - std::cos(t), y(1) + std::sin(t)));
                                   last_t = t;
                               },
                               {.method = m, .rel_tol = 1e-10, .abs_tol = 1e-10, .compensated_time = c == 1})
                               .rhs_calls;
                CHECK_SMALL(worst, 1e-6);
                CHECK(last_t == 50.0);
            }
            // The same stepper, control and retries as GSL's driver: exactly as many evaluations.
            CHECK(calls[1] == calls[0]);
        }
        // 1000 periods at tolerance 1e-14: GSL's own driver ends near 4e-9 (the rounding of t += h
        // shifts the phase), the compensated time near 2e-12.
        double worst = 0;
        rigid::integrate_gsl(g, VecX{{1.0, 0.0}}, rigid::linspace(0, 2000 * M_PI, 100),
                             [&](double t, const VecX& y) {
                                 worst = std::max(worst, std::hypot(y(0) - std::cos(t), y(1) + std::sin(t)));
                             },
                             {.method = "rk8pd", .rel_tol = 1e-14, .abs_tol = 1e-14, .compensated_time = true});
        CHECK_SMALL(worst, 1e-10);
        const auto ignore = [](double, const VecX&) {};
        CHECK_THROWS_AS(rigid::integrate_gsl(g, VecX{{1.0, 0.0}}, {0.0, 1.0}, ignore,
                                             {.method = "msadams", .compensated_time = true}),
                        std::invalid_argument);
    }

    TEST_CASE("pack and unpack: round trip in the documented layout") {
        rigid::BodyState s{rigid::Vec3(1, 2, 3), rigid::Mat3::Zero()};
        s.R << 4, 5, 6, 7, 8, 9, 10, 11, 12;
        const VecX y = rigid::pack(s);
        for (int i = 0; i < 12; ++i) CHECK(y(i) == i + 1.0);
        const rigid::BodyState back = rigid::unpack(y);
        CHECK_MAT_NEAR(back.R, s.R, 0.0);
        CHECK_MAT_NEAR(back.Omega, s.Omega, 0.0);
        CHECK_THROWS_AS(rigid::unpack(VecX::Zero(11)), std::invalid_argument);
    }

}  // TEST_SUITE
