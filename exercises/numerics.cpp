// Chapter 7 exercises: geometric integrators. Contracts in rigid/numerics.hpp; hints in
// exercises/hints.md. Replace each todo(...) with your code.
#include "rigid/numerics.hpp"

#include "rigid/rotation.hpp"
#include "rigid/todo.hpp"

namespace rigid {

// TODO: Rodrigues' formula minus the identity, with 1 - cos x = 2 sin^2(x/2); zero for w = 0.
Mat3 expm1_so3(const Vec3& w) { todo("expm1_so3"); }

// TODO: v - u x v / 2 + c(|u|) u x (u x v), with the series of c below |u| = 1e-3.
Vec3 dexpinv(const Vec3& u, const Vec3& v) { todo("dexpinv"); }

// TODO: add the dOmega; E = E1 + E2 + E1 E2.
Increment combine(const Increment& first, const Increment& second) { todo("combine"); }

// TODO: four stages of RK4, the rotation part through theta, dexpinv and expm1_so3.
Increment rkmk4_step(const HeavyTop& top, const BodyState& s, double h) { todo("rkmk4_step"); }

// TODO: only Omega changes, by h J^-1 f [R^T k, z(0)].
Increment torque_kick(const HeavyTop& top, const BodyState& s, double h) { todo("torque_kick"); }

// TODO: rotate R by h Omega_i about e_i, and J Omega by the opposite angle; reject a bad axis.
Increment free_rotation(const HeavyTop& top, const BodyState& s, int axis, double h) { todo("free_rotation"); }

// TODO: kick h/2, rotations 1, 2 (h/2), 3 (h), 2, 1 (h/2), kick h/2, all combined.
Increment strang_step(const HeavyTop& top, const BodyState& s, double h) { todo("strang_step"); }

// TODO: three substeps g1 h, g2 h, g1 h, each from the state reached so far, combined.
Increment triple_jump(const IncrementStepper& step, const BodyState& s, double h) { todo("triple_jump"); }

// TODO: (derivation) apply one RK4 step to y' = i omega y by hand; |R(i x)|^2 is a polynomial.
double rk4_energy_loss(double x) { todo("rk4_energy_loss"); }

}  // namespace rigid
