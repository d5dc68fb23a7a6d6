// The body on the command line: one validator for the principal moments, whichever way a
// scene names them, and one set of messages that name the options.
//
// The chapters keep the names [P] uses where they stand: the moments at O are --A --B --C
// (Chapters 4, 5, 8), the moments at the centre of mass --Ag --Bg --Cg (Chapter 6), and the
// free body of Chapter 3 takes its three moments as one vector --I I1,I2,I3, in any order.
// Each option's own range (finite, > 0) is checked by kit::Options; what lies between the
// three moments is checked here:
//
//   kit::moment_options(opts, p.body);                           // --A --B --C, bound to p.body
//   kit::require_moments(p.body);                                // A < B < C, A + B >= C
//   kit::require_moments(p.A, p.B, p.C, {"A", "B", "C"});       // the same, for any three names
//   kit::require_moments(p.I, "I", {kit::Order::distinct});      // three distinct moments
//
// and a failure is kit::BadInput (exit status 2), e.g.
//   --A, --B, --C: the moments must be strictly ordered, A < B < C (an asymmetric body), got ...
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <limits>
#include <string>

#include "rigid/types.hpp"
#include "scene.hpp"

namespace kit {

// What the three moments must satisfy besides being finite and positive.
enum class Order {
    any,         // the moments of a body, in any order (a symmetric body allowed)
    distinct,    // three different moments, in any order (an asymmetric body)
    increasing,  // strictly increasing in the order the options are named: A < B < C
};
enum class Triangle {
    flat_allowed,  // the largest at most the sum of the other two: A + B >= C (a flat body allowed)
    strict,        // the largest below the sum of the other two: A + B > C
};
struct BodyRules {
    Order order = Order::increasing;
    Triangle triangle = Triangle::flat_allowed;
};

// The names of three moment options, e.g. {"A", "B", "C"} or {"Ag", "Bg", "Cg"}.
struct MomentNames {
    std::string a, b, c;
};

namespace detail {

// How a moment is written in a message: A, B, C; A_g for the option Ag; I1, I2, I3.
inline std::string symbol(const std::string& option) {
    return option.size() == 2 && option[1] == 'g' ? option.substr(0, 1) + "_g" : option;
}

inline void check_moments(const rigid::Vec3& m, const std::string& options, const std::array<std::string, 3>& s,
                          BodyRules rules) {
    const auto got = fmt::format("got {} = {:.17g}, {} = {:.17g}, {} = {:.17g}", s[0], m(0), s[1], m(1), s[2], m(2));
    // The largest moment against the sum of the other two.
    std::array<int, 3> k = {0, 1, 2};
    std::stable_sort(k.begin(), k.end(), [&](int x, int y) { return m(x) < m(y); });
    const double sum = m(k[0]) + m(k[1]), largest = m(k[2]);
    const bool holds = rules.triangle == Triangle::strict
                           ? largest < sum
                           : largest <= sum * (1 + 8 * std::numeric_limits<double>::epsilon());
    if (!holds)
        throw BadInput(
            fmt::format("{}: the moments must obey the triangle inequality {} + {} {} {} (a real body), got "
                        "{} + {} = {:.17g}, {} = {:.17g}",
                        options, s[k[0]], s[k[1]], rules.triangle == Triangle::strict ? ">" : ">=", s[k[2]], s[k[0]],
                        s[k[1]], sum, s[k[2]], largest));
    if (rules.order == Order::increasing && !(m(0) < m(1) && m(1) < m(2)))
        throw BadInput(fmt::format("{}: the moments must be strictly ordered, {} < {} < {} (an asymmetric body), {}",
                                   options, s[0], s[1], s[2], got));
    if (rules.order == Order::distinct && !(m(0) != m(1) && m(1) != m(2) && m(0) != m(2)))
        throw BadInput(fmt::format("{}: the moments must be distinct (an asymmetric body), {}", options, got));
}

}  // namespace detail

// Three moments given as three options (--A --B --C, --Ag --Bg --Cg).
inline void require_moments(double a, double b, double c, const MomentNames& n, BodyRules rules = {}) {
    detail::check_moments(rigid::Vec3(a, b, c), fmt::format("--{}, --{}, --{}", n.a, n.b, n.c),
                          {detail::symbol(n.a), detail::symbol(n.b), detail::symbol(n.c)}, rules);
}

// Three moments given as one option x,y,z (--I I1,I2,I3), in any order.
inline void require_moments(const rigid::Vec3& I, const std::string& name, BodyRules rules) {
    detail::check_moments(I, "--" + name, {name + "1", name + "2", name + "3"}, rules);
}

// The principal moments at O as the options --A --B --C (Chapters 4, 5, 8): declared once, so
// every scene that takes them names, ranges and explains them the same way.
struct MomentsAtO {
    double A = 1.0, B = 1.5, C = 2.2;
};

inline Options& moment_options(Options& opts, MomentsAtO& m) {
    return opts.real("A", &m.A, "smallest principal moment at O", between(1e-6, 1e6))
        .real("B", &m.B, "intermediate principal moment at O", between(1e-6, 1e6))
        .real("C", &m.C, "largest principal moment at O (A + B >= C)", between(1e-6, 1e6));
}

// A < B < C and A + B >= C, or BadInput naming --A, --B, --C. Returns (A, B, C).
inline rigid::Vec3 require_moments(const MomentsAtO& m) {
    require_moments(m.A, m.B, m.C, {"A", "B", "C"});
    return {m.A, m.B, m.C};
}

// A heavy body (Chapters 5 and 8): its moments at O and f = g L mu, --A --B --C --f.
struct HeavyBody {
    MomentsAtO moments;
    double f = 1.0;
};

inline Options& heavy_body_options(Options& opts, HeavyBody& b) {
    return moment_options(opts, b.moments).real("f", &b.f, "f = g L mu", between(1e-6, 1e6));
}

}  // namespace kit
