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
    if (!a.allFinite())
        throw std::invalid_argument(name + " must be a finite vector, got " + describe(a));
    const double n = a.stableNorm();
    if (!(n > 0))
        throw std::invalid_argument(name + " must be a non-zero vector, got " + describe(a));
    return a / n;
}

}  // namespace rigid
