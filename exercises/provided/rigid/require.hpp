// Input checks shared by solutions and students: each throws std::invalid_argument with a
// message that names the value and the rule it breaks. Provided, not an exercise.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rigid/types.hpp"

namespace rigid {

inline std::string describe(const Vec3& v) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
    return s.str();
}

// x must be a finite number.
inline void require_finite(double x, const std::string& name) {
    if (!std::isfinite(x)) {
        std::ostringstream s;
        s << name << " must be a finite number, got " << x;
        throw std::invalid_argument(s.str());
    }
}

// x must be finite and > 0.
inline void require_positive(double x, const std::string& name) {
    require_finite(x, name);
    if (!(x > 0)) {
        std::ostringstream s;
        s.precision(17);
        s << name << " must be > 0, got " << x;
        throw std::invalid_argument(s.str());
    }
}

// a must be finite and non-zero; returns a / |a| (stableNorm: no overflow or underflow).
inline Vec3 require_axis(const Vec3& a, const std::string& name) {
    if (!a.allFinite()) throw std::invalid_argument(name + " must be a finite vector, got " + describe(a));
    const double n = a.stableNorm();
    if (!(n > 0)) throw std::invalid_argument(name + " must be a non-zero vector, got " + describe(a));
    return a / n;
}

// Principal moments of inertia I = (I1, I2, I3), in any order: each finite and > 0, and each
// at most the sum of the other two (the triangle inequality of a real mass distribution;
// equality is a flat body, and is allowed, with a relative slack of 8 ulp for rounding).
inline void require_principal_moments(const Vec3& I, const std::string& name = "principal moments") {
    for (int i = 0; i < 3; ++i) {
        const std::string which = name + " I" + std::to_string(i + 1);
        require_finite(I(i), which);
        if (!(I(i) > 0)) {
            std::ostringstream s;
            s.precision(17);
            s << which << " must be > 0, got " << I(i);
            throw std::invalid_argument(s.str());
        }
    }
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        if (I(k) > (I(i) + I(j)) * (1 + 8 * 2.220446049250313e-16)) {
            std::ostringstream s;
            s.precision(17);
            s << name << " " << describe(I) << " break the triangle inequality: I" << i + 1 << " + I" << j + 1 << " = "
              << I(i) + I(j) << " < I" << k + 1 << " = " << I(k)
              << " (each moment must be at most the sum of the other two)";
            throw std::invalid_argument(s.str());
        }
    }
}

}  // namespace rigid
