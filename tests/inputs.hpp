// What a grader's check was given, by name, in its failure message: one line per scope,
//
//   INPUTS(A, B, C, UNIT(t, "s"), UNIT(p.alpha, "rad/s"));
//
// prints, when a check in the scope fails (and costs nothing while they pass: doctest's INFO is
// lazy), the line
//
//   inputs: A = 1; B = 1.5; C = 2.2; t = 0.25 s; p.alpha = 1.2 rad/s
//
// Each input is named as the grader spells it; UNIT(x, "unit") adds its unit. Numbers are written
// with the fewest digits that give back the same double (std::to_chars: 0.1 is 0.1, and every
// digit of 0.30000000000000004 is kept), vectors as (x, y, z), matrices row by row as
// [[a, b], [c, d]], lists as [u, v, ...]. A struct of the API that several graders pass is shown by
// its fields, with their units (below: BodyState, RegularPrecession, HeavyTop); another is shown by a
// checks::Show<T> of its grader's own, or by naming its fields (INPUTS(p.a, p.alpha)).
// The test suite reads every grader's failure messages and fails on a failing check without an
// inputs line (cmake/checks/messages.py; tests/README.md, "Failure messages").
#pragma once

#include <doctest/doctest.h>

#include <Eigen/Core>
#include <array>
#include <charconv>
#include <cmath>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "rigid/heavy_top.hpp"  // HeavyTop, and RegularPrecession of rigid/precession.hpp
#include "rigid/ode.hpp"        // BodyState

namespace checks {

// How an input is written; specialise it for a type of the grader's own.
template <class T, class = void>
struct Show {
    static void to(std::ostream& s, const T& x) { s << x; }
};

template <class T>
void show(std::ostream& s, const T& x) {
    Show<T>::to(s, x);
}

// A double with the fewest digits that read back as the same double; nan, inf, -inf.
inline void show_number(std::ostream& s, double x) {
    if (std::isnan(x)) {
        s << "nan";
        return;
    }
    std::array<char, 32> text{};
    const auto r = std::to_chars(text.data(), text.data() + text.size(), x);
    s << std::string_view(text.data(), static_cast<std::size_t>(r.ptr - text.data()));
}

template <class T>
struct Show<T, std::enable_if_t<std::is_floating_point_v<T>>> {
    static void to(std::ostream& s, T x) { show_number(s, static_cast<double>(x)); }
};
template <>
struct Show<bool> {
    static void to(std::ostream& s, bool x) { s << (x ? "true" : "false"); }
};

// Eigen: a vector as (x, y, z), a matrix as [[row], [row]].
template <class T>
struct Show<T, std::enable_if_t<std::is_base_of_v<Eigen::DenseBase<T>, T>>> {
    static void to(std::ostream& s, const T& m) {
        const bool vector = m.rows() == 1 || m.cols() == 1;
        s << (vector ? "(" : "[");
        for (Eigen::Index i = 0; i < (vector ? m.size() : m.rows()); ++i) {
            s << (i ? ", " : "");
            if (vector) {
                show_number(s, static_cast<double>(m(i)));
                continue;
            }
            s << "[";
            for (Eigen::Index j = 0; j < m.cols(); ++j) s << (j ? ", " : ""), show_number(s, double(m(i, j)));
            s << "]";
        }
        s << (vector ? ")" : "]");
    }
};

template <class T, class A>
struct Show<std::vector<T, A>> {
    static void to(std::ostream& s, const std::vector<T, A>& v) {
        s << "[";
        for (std::size_t i = 0; i < v.size(); ++i) s << (i ? ", " : ""), show(s, v[i]);
        s << "]";
    }
};

// An input and its unit: UNIT(t, "s").
template <class T>
struct WithUnit {
    const T& value;
    const char* unit;
};
template <class T>
WithUnit<T> with_unit(const T& value, const char* unit) {
    return {value, unit};
}
template <class T>
struct Show<WithUnit<T>> {
    static void to(std::ostream& s, const WithUnit<T>& x) { show(s, x.value), s << " " << x.unit; }
};

// A struct of the API as {name = value, ...}, for a Show of the grader's own:
//   show_fields(s, "a", p.a, "alpha", with_unit(p.alpha, "rad/s"))   writes {a = (0, 0, 1), alpha = 2 rad/s}
template <class... T>
void show_fields(std::ostream& s, const T&... names_and_values) {
    s << "{";
    int k = 0;
    ((s << (k % 2 ? " = " : k ? ", " : ""), show(s, names_and_values), ++k), ...);
    s << "}";
}

// The API's structs that several graders pass.
template <>
struct Show<rigid::RegularPrecession> {
    static void to(std::ostream& s, const rigid::RegularPrecession& p) {
        show_fields(s, "a", p.a, "alpha", with_unit(p.alpha, "rad/s"), "b", p.b, "beta", with_unit(p.beta, "rad/s"));
    }
};
template <>
struct Show<rigid::BodyState> {
    static void to(std::ostream& s, const rigid::BodyState& x) {
        show_fields(s, "Omega", with_unit(x.Omega, "rad/s"), "R", x.R);
    }
};
template <>
struct Show<rigid::OdeSettings> {
    static void to(std::ostream& s, const rigid::OdeSettings& o) {
        show_fields(s, "method", o.method, "rel_tol", o.rel_tol, "abs_tol", o.abs_tol, "first_step",
                    with_unit(o.first_step, "s"), "max_steps", o.max_steps, "compensated_time", o.compensated_time);
    }
};
template <>
struct Show<rigid::HeavyTop> {
    static void to(std::ostream& s, const rigid::HeavyTop& top) {
        show_fields(s, "J", with_unit(top.J, "kg·m²"), "f", with_unit(top.f, "kg·m²/s²"), "k", top.k, "z0", top.z0);
    }
};

namespace inputs {

// The names in INPUTS's argument text, split at its top-level commas; UNIT(x, "u") is named x.
inline std::vector<std::string> names(std::string_view text) {
    std::vector<std::string> out(1);
    int depth = 0;
    bool quoted = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '"' && !(quoted && text[i - 1] == '\\')) quoted = !quoted;
        if (!quoted && (c == '(' || c == '[' || c == '{')) ++depth;
        if (!quoted && (c == ')' || c == ']' || c == '}')) --depth;
        if (!quoted && depth == 0 && c == ',') {
            out.emplace_back();
            continue;
        }
        if (!out.back().empty() || c != ' ') out.back() += c;
    }
    for (auto& name : out) {
        if (name.rfind("UNIT(", 0) == 0) name = names(std::string_view(name).substr(5, name.size() - 6)).front();
        while (!name.empty() && name.back() == ' ') name.pop_back();
    }
    return out;
}

template <class... T>
std::string line(const char* text, const T&... values) {
    const std::vector<std::string> n = names(text);
    std::ostringstream s;
    s << "inputs: ";
    std::size_t k = 0;
    ((s << (k ? "; " : "") << (k < n.size() ? n[k] : "?") << " = ", show(s, values), ++k), ...);
    return s.str();
}

}  // namespace inputs
}  // namespace checks

#define UNIT(x, unit) ::checks::with_unit((x), unit)

// One line, "inputs: name = value [unit]; ...", in the failure message of every check in scope.
#define INPUTS(...) INFO(::checks::inputs::line(#__VA_ARGS__, __VA_ARGS__))
