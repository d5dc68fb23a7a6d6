// The one R(t) of a regular precession the scenes compare integrated motions with:
//
//   R(t) = R^b(beta t) R^a(alpha t)                                                  [P, (1.4)]
//
// for any finite frequencies (a negative pair is the same precession run backwards, the
// clockwise sense of Theorem 1, or Omega(0) scaled by a negative lambda). The student's
// rigid::precession_rotation (Chapter 2) is the same product but takes alpha, beta > 0 only, and
// rigid::grioli_rotation (Chapter 5) is it with beta = alpha = sigma alpha: both are exercises,
// written by the student, so the scenes do not lean on them for a reference.
#pragma once

#include "rigid/precession.hpp"
#include "rigid/rotation.hpp"

namespace kit {

inline rigid::Mat3 precession_rotation(const rigid::RegularPrecession& p, double t) {
    return rigid::rotation_about(p.b, p.beta * t) * rigid::rotation_about(p.a, p.alpha * t);
}

}  // namespace kit
