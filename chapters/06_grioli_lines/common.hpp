// What the Chapter 6 scenes share: the body options, the eigen-solver reference, and the
// printed forms of [P, Sect. 6] transcribed as printed (to measure them, never to use them).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "body.hpp"
#include "reference/inertia.hpp"
#include "rigid/inertia.hpp"
#include "scene.hpp"

namespace ch6 {

using rigid::BodyAtG;
using rigid::Mat3;
using rigid::Vec3;

// The body of the Chapter 6 scenes unless the options say otherwise.
inline constexpr BodyAtG default_body{1.0, 2.0, 2.5, 1.0};

// --Ag --Bg --Cg --mu bound to b (its values are the defaults), each a finite number > 0; the
// rules between them are checked by body().
inline void body_options(kit::Options& o, BodyAtG& b) {
    o.real("Ag", &b.A_g, "smallest principal moment at the centre of mass, A_g", kit::between(1e-6, 1e6))
        .real("Bg", &b.B_g, "intermediate principal moment at the centre of mass, B_g", kit::between(1e-6, 1e6))
        .real("Cg", &b.C_g, "largest principal moment at the centre of mass, C_g", kit::between(1e-6, 1e6))
        .real("mu", &b.mu, "total mass mu", kit::between(1e-6, 1e6));
}

// The body of the options, or BadInput naming the options and the rule they break.
inline BodyAtG body(const BodyAtG& b) {
    kit::require_moments(b.A_g, b.B_g, b.C_g, {"Ag", "Bg", "Cg"}, {kit::Order::increasing, kit::Triangle::strict});
    try {
        rigid::require_body(b);
    } catch (const std::invalid_argument& e) {
        throw kit::BadInput(std::string("--Ag, --Bg, --Cg, --mu: ") + e.what());
    }
    return b;
}

// The yardstick the graders use too (tests/include/reference/inertia.hpp): the tensor from (5.2)
// written out, Eigen's eigen-solver with the moments named as in (5.3), the body's size.
using inertia_reference::Crossing;
using inertia_reference::crossing_by_bisection;
using inertia_reference::eigen_moments;
using inertia_reference::EigenMoments;
using inertia_reference::size_of;
using inertia_reference::tensor_at;

inline double root(double x) { return std::sqrt(x); }
inline quadref::quad root(quadref::quad x) { return quadref::sqrt_q(x); }

// snippet: printed_forms
// [P, Sect. 6] as printed, with h = mu L^2 and z = (zA, 0, zC): the forms the workbook checks,
// in double (T = double) or in binary128 (T = quadref::quad, to tell a misprint from round-off).
template <class T>
struct Printed {
    T h, zA, zC;
    T Ag, Bg, Cg;
    T dplus() const { return Ag * zA * zA + Cg * zC * zC; }                               // (5.5)
    T D1() const { return (Ag + Cg + h) * (Ag + Cg + h) - 4 * (Ag * Cg + h * dplus()); }  // (5.4)
    T D2() const { return h * h + 2 * (Cg + Ag - 2 * dplus()) * h + (Cg - Ag) * (Cg - Ag); }
    T D3() const { return h * h + 2 * (Cg - Ag) * (zA * zA - zC * zC) * h + (Cg - Ag) * (Cg - Ag); }
    T C() const { return (Ag + Cg + h + root(D3())) / 2; }  // (5.3)
    T B() const { return Bg + h; }
    T A() const { return (Ag + Cg + h - root(D3())) / 2; }
    T alpha510() const { return -h + 2 * h * zA * zA + (Cg - Ag); }  // (5.10): not a frequency
    T D510() const { return alpha510() * alpha510() + 4 * h * h * zA * zA * zC * zC; }
    T vC_over_vA_first() const { return (Ag - A() + h * zC * zC) / (h * zA * zC); }  // (5.9)
    T vC_over_vA() const { return (root(D3()) - alpha510()) / (2 * h * zA * zC); }
    T cos2_511() const {  // (5.11) solved for cos^2
        const T s = root(D3()), t = 2 * h * zA * zA + s - alpha510();
        return zC * zC * t * t / (2 * s * (s - alpha510()));
    }
    T cos2_512() const {  // (5.12)
        const T c2g = zA * zA - zC * zC;
        return T(0.5) + (h + (Cg - Ag) * c2g) / (2 * root(h * h + 2 * h * (Cg - Ag) * c2g + (Cg - Ag) * (Cg - Ag)));
    }
    T ratio_513() const { return T(0.5) + (2 * Bg - Ag - Cg + h) / (2 * root(D3())); }  // (5.13)
    T h_crit_58() const { return -(Bg - Ag) * (Cg - Bg) / (Cg + Ag - Bg - dplus()); }   // (5.8)
};
// end snippet

inline Printed<double> printed(const BodyAtG& b, double L, const Vec3& z) {
    return {b.mu * L * L, z.x(), z.z(), b.A_g, b.B_g, b.C_g};
}

// The same in binary128: every double input converts exactly, and z is normalised there (a
// double z is a unit vector only to ~1e-16, which (5.11) would feel through sqrt(D) - alpha).
inline Printed<quadref::quad> printed_q(const BodyAtG& b, double L, const Vec3& z) {
    using q = quadref::quad;
    const q n = quadref::sqrt_q(q(z.x()) * z.x() + q(z.z()) * z.z());
    return {q(b.mu) * L * L, z.x() / n, z.z() / n, b.A_g, b.B_g, b.C_g};
}

}  // namespace ch6
