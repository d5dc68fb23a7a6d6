// Assertions for the graders: explicit tolerances, both sides printed, NaN always fails.
//
// Every check is written as CHECK(distance <= tol): a NaN distance makes the comparison
// false, so a NaN result can never pass (CHECK_FALSE(distance > tol) would let it through).
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rigid/types.hpp"

namespace checks {

inline double max_abs_diff(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    if (a.rows() != b.rows() || a.cols() != b.cols()) return NAN;
    return (a - b).cwiseAbs().maxCoeff();
}

// A fixed-seed generator, reseeded at the start of every test case (tests/main.cpp): a test
// draws the same "random" cases whether it runs alone or after others, so a failure
// reproduces and a grader run in one process agrees with one run test by test.
std::mt19937_64& rng();
inline double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng()); }
inline rigid::Vec3 random_vector(double scale = 1.0) {
    return scale * rigid::Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
}
inline rigid::Vec3 random_unit() {
    rigid::Vec3 v;
    do v = random_vector();
    while (v.norm() < 0.1);
    return v.normalized();
}

// The margin of a passing check, tolerance / error, written to the file WORKBOOK_MARGINS names
// (one line per check: file, line, error, tolerance) when it is set; nothing otherwise. For the
// measurement that every tolerance leaves a correct ordinary implementation a margin of 10 or
// more (tests/margins.sh).
inline void log_margin(const char* file, int line, double err, double tol) {
    static std::FILE* out = [] {
        const char* path = std::getenv("WORKBOOK_MARGINS");
        return path && *path ? std::fopen(path, "a") : nullptr;
    }();
    if (out) std::fprintf(out, "%s\t%d\t%.17g\t%.17g\n", file, line, err, tol), std::fflush(out);
}

// x with 17 significant digits (every double exactly), for a failure message that must show
// the digits a relative check measured.
inline std::string digits17(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

// The relative error |x - expected| / |expected|, worked out in long double; NaN stays NaN.
inline double relative_error(double x, long double expected) {
    return static_cast<double>(std::abs((static_cast<long double>(x) - expected) / expected));
}

// Values every grader feeds to a function that must reject them.
inline constexpr double nan_ = std::numeric_limits<double>::quiet_NaN();
inline constexpr double inf_ = std::numeric_limits<double>::infinity();

// The rotation by phi about `axis` (normalised here), by Eigen's angle-axis: independent of the
// exercises' own rotation_about.
inline rigid::Mat3 Rot(const rigid::Vec3& axis, double phi) {
    return Eigen::AngleAxisd(phi, axis.normalized()).toRotationMatrix();
}

// hat(w) and its inverse, written out: skew(w) v = w x v.
inline rigid::Mat3 skew(const rigid::Vec3& w) {
    rigid::Mat3 S;
    S << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return S;
}
inline rigid::Vec3 unskew(const rigid::Mat3& W) {
    return 0.5 * rigid::Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
}

// A random rotation: the angle uniform in [lo, hi), drawn first, then a random axis.
inline rigid::Mat3 random_rotation(double lo, double hi) {
    const double angle = uniform(lo, hi);
    const rigid::Vec3 axis = random_unit();
    return Rot(axis, angle);
}

// The message of the std::invalid_argument that f() throws; "(another exception)" or
// "(no exception)" otherwise, so that a CHECK on the message fails with a reason.
template <class F>
std::string message_of(F&& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    } catch (...) {
        return "(another exception)";
    }
    return "(no exception)";
}

}  // namespace checks

// A grader that also calls other exercises of the student names them in every failure message it
// prints, so that a correct function is never blamed for another one: ALSO_USES("grioli_precession").
// (Where the input is easy to build independently, the grader builds it instead.)
#define ALSO_USES(names) \
    INFO("this test also uses your " names " (graded by their own tests): if one of them fails, fix it first")

// |actual - expected| <= tol, with both values and the tolerance in the failure message.
#define CHECK_NEAR(actual, expected, tol)                                                               \
    do {                                                                                                \
        const double check_actual_ = (actual), check_expected_ = (expected);                            \
        const double check_tol_ = (tol);                                                                \
        INFO("expected " << check_expected_ << ", actual " << check_actual_ << ", |diff| "              \
                         << std::abs(check_actual_ - check_expected_) << ", tolerance " << check_tol_); \
        CHECK(std::abs(check_actual_ - check_expected_) <= check_tol_);                                 \
        checks::log_margin(__FILE__, __LINE__, std::abs(check_actual_ - check_expected_), check_tol_);  \
    } while (0)

// Largest entry of |A - B| <= tol, with both matrices in the failure message.
#define CHECK_MAT_NEAR(A, B, tol)                                                                         \
    do {                                                                                                  \
        const Eigen::MatrixXd check_a_ = (A), check_b_ = (B);                                             \
        const double check_tol_ = (tol);                                                                  \
        INFO("expected\n"                                                                                 \
             << check_b_ << "\nactual\n"                                                                  \
             << check_a_ << "\nmax |diff| " << checks::max_abs_diff(check_a_, check_b_) << ", tolerance " \
             << check_tol_);                                                                              \
        CHECK(checks::max_abs_diff(check_a_, check_b_) <= check_tol_);                                    \
        checks::log_margin(__FILE__, __LINE__, checks::max_abs_diff(check_a_, check_b_), check_tol_);     \
    } while (0)

// |actual - expected| <= tol |expected|, a relative error (expected may be a long double
// reference), with the quantity, both values to 17 digits, the relative error and the tolerance
// in the failure message: CHECK_REL(rigid::grioli_root(m), S, 4e-15).
#define CHECK_REL(actual, expected, tol)                                                                    \
    do {                                                                                                    \
        const double check_actual_ = (actual);                                                              \
        const long double check_expected_ = (expected);                                                     \
        const double check_tol_ = (tol);                                                                    \
        const double check_rel_ = checks::relative_error(check_actual_, check_expected_);                   \
        INFO(#actual ": expected " << checks::digits17(static_cast<double>(check_expected_)) << ", actual " \
                                   << checks::digits17(check_actual_) << ", relative error " << check_rel_  \
                                   << ", tolerance " << check_tol_);                                        \
        CHECK(check_rel_ <= check_tol_);                                                                    \
        checks::log_margin(__FILE__, __LINE__, check_rel_, check_tol_);                                     \
    } while (0)

// error <= tol for an error measure (a norm, a relative error, a residual), with the error and
// the tolerance in the failure message like every other check.
#define CHECK_SMALL(error, tol)                                                                               \
    do {                                                                                                      \
        const double check_err_ = (error), check_tol_ = (tol);                                                \
        INFO("expected at most " << check_tol_ << ", actual " << check_err_ << ", tolerance " << check_tol_); \
        CHECK(check_err_ <= check_tol_);                                                                      \
        checks::log_margin(__FILE__, __LINE__, check_err_, check_tol_);                                       \
    } while (0)
