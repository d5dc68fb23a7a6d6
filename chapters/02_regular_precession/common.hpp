// What the Chapter 2 scenes share: dR/dt of a regular precession from R(t) alone.
#pragma once

#include "rigid/precession.hpp"

namespace ch2 {

// snippet: omega_from_rotations
// dR/dt at t from R(t) alone: Chapter 1's eighth-order central difference.
inline rigid::Mat3 rotation_rate(const rigid::RegularPrecession& p, double t, double h) {
    static const double w[4] = {4. / 5, -1. / 5, 4. / 105, -1. / 280};
    rigid::Mat3 R_dot = rigid::Mat3::Zero();
    for (int j = 1; j <= 4; ++j)
        R_dot += w[j - 1] * (rigid::precession_rotation(p, t + j * h) - rigid::precession_rotation(p, t - j * h));
    return R_dot / h;
}
// end snippet

}  // namespace ch2
