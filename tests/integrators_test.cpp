// Graders for the student's fixed-step Runge-Kutta method (rigid/integrators.hpp), part of
// Chapter 3. Each test cross-checks against a closed form: Taylor polynomials, exact
// solutions of linear and polynomial equations, and the order of convergence.
#include "rigid/integrators.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "checks.hpp"
#include "inputs.hpp"

using rigid::VecX;

namespace {

using checks::nan_;

// The harmonic oscillator y'' = -y as a first-order system; exact y = (cos t, -sin t).
VecX oscillator(double, const VecX& y) { return VecX{{y(1), -y(0)}}; }

}  // namespace

TEST_SUITE("ch03_free_body") {
    TEST_CASE("rk4_step: one step of y' = lambda y is the degree-4 Taylor polynomial of exp") {
        // For a linear autonomous equation RK4 multiplies by 1 + z + z^2/2 + z^3/6 + z^4/24, z = lambda h.
        for (double z : {0.1, -0.7, 1.3}) {
            const double lambda = 2.0, h = z / lambda, t = 0.4;
            const VecX y0{{3.0}};
            INPUTS(UNIT(lambda, "1/s"), UNIT(t, "s"), y0, UNIT(h, "s"));
            INFO("f(t, y) = lambda y");
            const VecX y = rigid::rk4_step([&](double, const VecX& x) { return VecX(lambda * x); }, t, y0, h);
            CHECK_NEAR(y(0), 3.0 * (1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24), 1e-14);
        }
    }

    TEST_CASE(
        "rk4_step: one step of y' = lambda y is the Taylor polynomial for random lambda and h and y (the graders' "
        "seed)") {
        for (int n = 0; n < 20; ++n) {
            const double lambda = checks::uniform(-3, 3), h = checks::uniform(0.01, 0.5), y0 = checks::uniform(-5, 5);
            const double z = lambda * h, t = checks::uniform(-1, 1);
            INPUTS(UNIT(lambda, "1/s"), UNIT(t, "s"), y0, UNIT(h, "s"));
            INFO("f(t, y) = lambda y");
            const VecX y = rigid::rk4_step([&](double, const VecX& x) { return VecX(lambda * x); }, t, VecX{{y0}}, h);
            CHECK_NEAR(y(0), y0 * (1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24), 1e-13 * std::abs(y0));
        }
    }

    TEST_CASE("rk4_step: uses the time argument and is exact for y' = t^3") {
        // Simpson's rule inside RK4 integrates cubics exactly: y(t + h) - y(t) = ((t+h)^4 - t^4) / 4.
        const rigid::OdeRhs f = [](double t, const VecX&) { return VecX{{t * t * t}}; };
        const double t = 0.7, h = 0.9;
        const VecX y0{{1.0}};
        INPUTS(UNIT(t, "s"), y0, UNIT(h, "s"));
        INFO("f(t, y) = t^3");
        const VecX y = rigid::rk4_step(f, t, y0, h);
        CHECK_NEAR(y(0), 1.0 + (std::pow(t + h, 4) - std::pow(t, 4)) / 4, 1e-14);
    }

    TEST_CASE("rk4_step: the error of one step on the oscillator falls like h^5") {
        double previous = 0;
        for (double h : {0.2, 0.1, 0.05}) {
            const double t = 0.0;
            const VecX y0{{1.0, 0.0}};
            INPUTS(UNIT(t, "s"), y0, UNIT(h, "s"));
            INFO("f(t, y) = (y_1, -y_0), the oscillator; the error of the step against (cos h, -sin h)");
            const VecX y = rigid::rk4_step(oscillator, t, y0, h);
            const double err = std::hypot(y(0) - std::cos(h), y(1) + std::sin(h));
            // Exact local error of RK4 here: |e^{ih} - sum_{k<=4} (ih)^k / k!| ~ h^5 / 120.
            CHECK_NEAR(err, std::pow(h, 5) / 120, 0.05 * std::pow(h, 5) / 120);
            if (previous > 0) CHECK_NEAR(previous / err, 32.0, 1.0);
            previous = err;
        }
    }

    TEST_CASE("integrate_rk4: lands exactly on every output time and counts its steps") {
        const std::vector<double> times{0.0, 0.25, 1.0, 1.1, 3.0};
        const VecX y0{{1.0, 0.0}};
        const double h = 0.1;
        INPUTS(y0, UNIT(times, "s"), UNIT(h, "s"));
        INFO("f(t, y) = (y_1, -y_0), the oscillator");
        std::vector<double> seen;
        const long steps = rigid::integrate_rk4(
            oscillator, y0, times, [&](double t, const VecX&) { seen.push_back(t); }, h);
        REQUIRE(seen.size() == times.size());
        for (std::size_t i = 0; i < times.size(); ++i) CHECK(seen[i] == times[i]);
        // ceil(0.25/0.1) + ceil(0.75/0.1) + ceil(0.1/0.1 + rounding) + ceil(1.9/0.1) steps.
        long expected = 0;
        for (std::size_t i = 1; i < times.size(); ++i) expected += long(std::ceil((times[i] - times[i - 1]) / 0.1));
        CHECK(steps == expected);
    }

    TEST_CASE("integrate_rk4: lands on random output times and counts its steps (the graders' seed)") {
        std::vector<double> times{checks::uniform(-1, 1)};
        for (int i = 0; i < 5; ++i) times.push_back(times.back() + checks::uniform(0.05, 1));
        const double h = checks::uniform(0.01, 0.1);
        const VecX y0{{1.0, 0.0}};
        INPUTS(y0, UNIT(times, "s"), UNIT(h, "s"));
        INFO("f(t, y) = (y_1, -y_0), the oscillator");
        std::vector<double> seen;
        const long steps = rigid::integrate_rk4(
            oscillator, y0, times, [&](double t, const VecX&) { seen.push_back(t); }, h);
        REQUIRE(seen.size() == times.size());
        for (std::size_t i = 0; i < times.size(); ++i) CHECK(seen[i] == times[i]);
        long expected = 0;
        for (std::size_t i = 1; i < times.size(); ++i) expected += long(std::ceil((times[i] - times[i - 1]) / h));
        CHECK(steps == expected);
    }

    TEST_CASE("integrate_rk4: converges with order 4 on the oscillator") {
        auto error_at = [](double h) {
            VecX last;
            rigid::integrate_rk4(
                oscillator, VecX{{1.0, 0.0}}, {0.0, 10.0}, [&](double, const VecX& y) { last = y; }, h);
            return std::hypot(last(0) - std::cos(10.0), last(1) + std::sin(10.0));
        };
        const VecX y0{{1.0, 0.0}};
        const std::vector<double> times{0.0, 10.0};
        INPUTS(y0, UNIT(times, "s"));
        INFO(
            "f(t, y) = (y_1, -y_0), the oscillator, with h = 0.1 s and 0.05 s; e1 and e2 the errors at t = 10 s "
            "against (cos t, -sin t), e1 / e2 the order's ratio");
        const double e1 = error_at(0.1), e2 = error_at(0.05);
        // Global error ~ T h^4 / 120 for the oscillator: 10 * 1e-4 / 120 = 8.3e-6 at h = 0.1.
        CHECK_NEAR(e1, 10 * std::pow(0.1, 4) / 120, 1e-6);
        CHECK_NEAR(e1 / e2, 16.0, 0.5);
    }

    TEST_CASE("integrate_rk4: the first observation is the initial state itself") {
        VecX first;
        bool called = false;
        const VecX y0{{0.3, -0.2}};
        const std::vector<double> times{2.0, 2.5};
        INPUTS(y0, UNIT(times, "s"));
        INFO("f(t, y) = (y_1, -y_0), the oscillator, with h = 0.1 s");
        rigid::integrate_rk4(
            oscillator, y0, times,
            [&](double, const VecX& y) {
                if (!called) first = y;
                called = true;
            },
            0.1);
        REQUIRE(called);
        CHECK_MAT_NEAR(first, VecX({{0.3, -0.2}}), 0.0);
    }

    TEST_CASE("integrate_rk4: rejects a bad step or bad times or a non-finite state") {
        const auto ignore = [](double, const VecX&) {};
        const VecX y0{{1.0, 0.0}};
        INPUTS(y0);
        INFO("f(t, y) = (y_1, -y_0), the oscillator; the observer does nothing");
        // A valid input first: a file that refuses every input earns nothing here.
        CHECK_NOTHROW((void)rigid::integrate_rk4(oscillator, y0, {0.0, 1.0}, ignore, 0.1));
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, y0, {0.0, 1.0}, ignore, 0.0), std::invalid_argument);
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, y0, {0.0, 1.0}, ignore, -0.1), std::invalid_argument);
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, y0, {0.0, 1.0}, ignore, nan_), std::invalid_argument);
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, y0, {1.0, 0.0}, ignore, 0.1), std::invalid_argument);
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, y0, {0.0, nan_}, ignore, 0.1), std::invalid_argument);
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, y0, {}, ignore, 0.1), std::invalid_argument);
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, VecX{{nan_, 0.0}}, {0.0, 1.0}, ignore, 0.1),
                        std::invalid_argument);
    }

    TEST_CASE("integrate_rk4: gives every step its own time (y' = t^3 with many steps per output interval)") {
        // RK4 on y' = f(t) is Simpson's rule, exact for cubics: y(3) = 1 + 3^4 / 4 whatever the step,
        // provided step j of an interval is evaluated at t_k + j h (a wrong time breaks it at once).
        const rigid::OdeRhs f = [](double t, const VecX&) { return VecX{{t * t * t}}; };
        const VecX y0{{1.0}};
        const std::vector<double> times{0.0, 1.0, 3.0};
        const double h = 0.25;
        INPUTS(y0, UNIT(times, "s"), UNIT(h, "s"));
        INFO("f(t, y) = t^3");
        std::vector<double> seen;
        rigid::integrate_rk4(
            f, y0, times, [&](double, const VecX& y) { seen.push_back(y(0)); }, h);
        REQUIRE(seen.size() == 3);
        CHECK_NEAR(seen[1], 1.0 + 1.0 / 4, 1e-14);
        CHECK_NEAR(seen[2], 1.0 + 81.0 / 4, 1e-13);
    }

    TEST_CASE(
        "integrate_rk4: rejects equal or decreasing output times anywhere and a lone non-finite time and an empty "
        "state") {
        const auto ignore = [](double, const VecX&) {};
        const VecX y0{{1.0, 0.0}};
        INPUTS(y0);
        INFO("f(t, y) = (y_1, -y_0), the oscillator; the observer does nothing");
        // A valid input first: a file that refuses every input earns nothing here.
        CHECK_NOTHROW((void)rigid::integrate_rk4(oscillator, y0, {0.0, 1.0, 3.0}, ignore, 0.1));
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, y0, {0.0, 1.0, 1.0}, ignore, 0.1), std::invalid_argument);
        // 2 < 3 comes after 1 < 3: the check must compare each time with the one just before it.
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, y0, {0.0, 1.0, 3.0, 2.0}, ignore, 0.1), std::invalid_argument);
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, y0, {nan_}, ignore, 0.1), std::invalid_argument);
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, VecX(), {0.0, 1.0}, ignore, 0.1), std::invalid_argument);
    }

}  // TEST_SUITE

// ---- Bad input at its boundary: every "throws ... for ..." rule of exercises/rigid/integrators.hpp ----
// The last bad value is refused with std::invalid_argument and the first good value beyond it
// is accepted, with the right answer. Graders check the exception's type, never its wording.
TEST_SUITE("ch03_free_body") {
    TEST_CASE(
        "integrate_rk4: rejects a step <= 0 or infinite and times or a state that are not finite and accepts the "
        "smallest valid gap") {
        const auto ignore = [](double, const VecX&) {};
        const VecX y0{{1.0, 0.0}};
        INPUTS(y0);
        INFO("f(t, y) = (y_1, -y_0), the oscillator; the observer does nothing");
        const double inf = std::numeric_limits<double>::infinity(), tiny = std::numeric_limits<double>::denorm_min();
        for (double h : {-0.0, -tiny, inf, -inf}) {
            INPUTS(UNIT(h, "s"));
            CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, y0, {0.0, 1.0}, ignore, h), std::invalid_argument);
        }
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, y0, {0.0, inf}, ignore, 0.1), std::invalid_argument);
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, y0, {-inf, 0.0}, ignore, 0.1), std::invalid_argument);
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, VecX{{0.0, -inf}}, {0.0, 1.0}, ignore, 0.1),
                        std::invalid_argument);
        // Equal times are refused; the next double up is strictly increasing: one step of that size.
        const double t1 = std::nextafter(1.0, 2.0);
        CHECK_THROWS_AS(rigid::integrate_rk4(oscillator, y0, {1.0, 1.0}, ignore, 0.1), std::invalid_argument);
        std::vector<VecX> seen;
        const auto keep = [&](double, const VecX& y) { seen.push_back(y); };
        CHECK(rigid::integrate_rk4(oscillator, y0, {1.0, t1}, keep, 0.1) == 1);
        REQUIRE(seen.size() == 2);
        CHECK_MAT_NEAR(seen[1], y0, 4e-15);
        // A step far longer than the interval is a valid step: one step of the interval's length.
        seen.clear();
        CHECK(rigid::integrate_rk4(oscillator, y0, {0.0, 0.5}, keep, 1e300) == 1);
        REQUIRE(seen.size() == 2);
        const double h = 0.5, taylor_cos = 1 - h * h / 2 + h * h * h * h / 24;  // RK4 on y'' = -y: degree 4
        CHECK_NEAR(seen[1](0), taylor_cos, 1e-15);
        // A single output time is strictly increasing: no step, y0 observed once.
        seen.clear();
        CHECK(rigid::integrate_rk4(oscillator, y0, {2.0}, keep, 0.1) == 0);
        REQUIRE(seen.size() == 1);
        CHECK_MAT_NEAR(seen[0], y0, 0.0);
    }
}  // TEST_SUITE
