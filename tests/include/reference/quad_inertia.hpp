// A reference for the moments and axes at a shifted suspension point, in binary128
// (GCC's __float128: 113-bit significand, eps ~ 1e-34), independent of rigid/inertia.hpp.
//
// Used by the Chapter 6 graders and scenes. Every double input converts to binary128 exactly,
// and a product of two doubles is exact in binary128. The printed forms of [P, (5.3), (5.4)]
// lose digits in proportion to h / C_g, up to 1e12 in the graders: in binary128 that leaves
// 1e-22 relative, far below double precision. The two quantities that printed forms would lose
// entirely (C - B on a Grioli line far out, and sin^2 phi there) are taken from the expanded
// determinant and from the eigenvector equation, as the comments say.
#pragma once

#include <cmath>

namespace quadref {

__extension__ typedef __float128 quad;

// sqrt by Newton's method from a long double start (64 bits); two steps reach 113 bits.
inline quad sqrt_q(quad x) {
    if (!(x > 0)) return 0;
    quad y = std::sqrt(static_cast<long double>(x));
    for (int i = 0; i < 3; ++i) y = (y + x / y) / 2;
    return y;
}

inline quad abs_q(quad x) { return x < 0 ? -x : x; }

// The moments and the tilt of the smallest axis at O = G + L z, z = (zA, 0, zC) unit, for
// the body diag(a, b, c) at G with mass mu; all in binary128.
struct Moments {
    quad A, B, C, CmA, CmB, BmA;  // C - A, C - B, B - A
    quad cos2, sin2;              // of the angle between the smallest axis and z
};

inline Moments moments(quad a, quad b, quad c, quad mu, quad L, quad zA, quad zC) {
    Moments m;
    const quad h = mu * L * L;
    const quad norm = sqrt_q(zA * zA + zC * zC);  // a double z is unit only to ~1e-16
    zA /= norm;
    zC /= norm;
    const quad zA2 = zA * zA, zC2 = zC * zC;
    // (5.3) with D from (5.4), printed form: fine in binary128.
    const quad D = h * h + 2 * (c - a) * (zA2 - zC2) * h + (c - a) * (c - a);
    const quad sqrtD = sqrt_q(D);
    m.C = (a + c + h + sqrtD) / 2;
    m.A = (a + c + h - sqrtD) / 2;
    m.B = b + h;
    m.CmA = sqrtD;
    m.BmA = m.B - m.A;
    // C - B from the determinant of the (x_A, x_C) block minus B, expanded by hand:
    //   (a - b - h zA2)(c - b - h zC2) - h^2 zA2 zC2 = -(b - a)(c - b) - h [(c - b) zA2 - (b - a) zC2]
    // is -(C - B)(B - A); B - A has no cancellation.
    const quad P = (b - a) * (c - b) + h * ((c - b) * zA2 - (b - a) * zC2);
    m.CmB = P / m.BmA;
    // The smallest axis from the eigenvector equation (M - C) v_A = 0 [P, (5.9)]: the columns of
    // M - C are multiples of v_A: column 1 is (a + h zC2 - C, -h zA zC), column 2 is
    // (-h zA zC, c + h zA2 - C). Take the longer; sin^2 = (v x z)^2 / |v|^2, cos^2 = (v . z)^2 / |v|^2.
    const quad v1a = a + h * zC2 - m.C, v1c = -h * zA * zC;
    const quad v2a = -h * zA * zC, v2c = c + h * zA2 - m.C;
    const quad n1 = v1a * v1a + v1c * v1c, n2 = v2a * v2a + v2c * v2c;
    const quad va = n1 >= n2 ? v1a : v2a, vc = n1 >= n2 ? v1c : v2c, n = n1 >= n2 ? n1 : n2;
    const quad cross = va * zC - vc * zA, dot = va * zA + vc * zC;
    m.sin2 = cross * cross / n;
    m.cos2 = dot * dot / n;
    return m;
}

// The exact Grioli line's direction, in binary128: zA^2 = (b - a)/(c - a).
inline void grioli_line(quad a, quad b, quad c, int sign, quad& zA, quad& zC) {
    zA = sqrt_q((b - a) / (c - a));
    zC = sign * sqrt_q((c - b) / (c - a));
}

// |x - ref| / |ref| in double, with ref == 0 giving |x|.
inline double rel_err(double x, quad ref) {
    const quad d = abs_q(static_cast<quad>(x) - ref);
    return static_cast<double>(ref == 0 ? d : d / abs_q(ref));
}

}  // namespace quadref
