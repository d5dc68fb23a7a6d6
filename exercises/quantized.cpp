// Chapter 8 exercises: the level oscillator (6.1) and the aligning spin (6.2). Contracts,
// conventions and equation numbers are in rigid/quantized.hpp; hints in exercises/hints.md.
// Replace each todo(...) with your code.
#include "rigid/quantized.hpp"

#include "rigid/require.hpp"
#include "rigid/rotation.hpp"
#include "rigid/todo.hpp"

namespace rigid {

// TODO: [P, (6.1)] m q'^2 / 2 + omega^2 q^2 / 2, after require_oscillator(osc).
double oscillator_energy(const Oscillator& osc, double q, double q_dot) { todo("oscillator_energy"); }

// TODO: kappa |sin(pi E / E0)|^power, after require_friction(k).
double level_friction(const LevelFriction& k, double E) { todo("level_friction"); }

// TODO: the largest n E0 <= E; reject a negative or non-finite E.
double level_below(const LevelFriction& k, double E) { todo("level_below"); }

// TODO: [P, (6.1)] f(t, (q, q')) = (q', -(omega^2 q + k(E) q') / m); check osc and k first.
OdeRhs oscillator_equations(const Oscillator& osc, const LevelFriction& k) { todo("oscillator_equations"); }

// TODO: dE/dt = -k(E) q'^2.
double energy_rate(const Oscillator& osc, const LevelFriction& k, double q, double q_dot) { todo("energy_rate"); }

// TODO: [P, (6.2)] -(e/mc) B x S + beta (B . S) S^ x (B^ x S^); 0 at S = 0.
Vec3 spin_rhs(const SpinField& field, const Vec3& S) { todo("spin_rhs"); }

// TODO: check the field, then return f(t, y) = spin_rhs(field, y) for y = S.
OdeRhs spin_equations(const SpinField& field) { todo("spin_equations"); }

// TODO: beta |B| (S . B^) sin^2(theta); 0 at S = 0.
double spin_projection_rate(const SpinField& field, const Vec3& S) { todo("spin_projection_rate"); }

// TODO: atan2(|S x B|, S . B), after checking both vectors.
double spin_angle(const Vec3& B, const Vec3& S) { todo("spin_angle"); }

// TODO: (derivation) differentiate |S| cos(theta) = S . B^ and use what (6.2) does to each side.
double spin_angle_rate(const SpinField& field, const Vec3& S) { todo("spin_angle_rate"); }

// TODO: turn normalize(S_par + exp(-beta |B| t) S_perp) |S0| about B by -(e/mc) |B| t.
Vec3 spin_exact(const SpinField& field, const Vec3& S0, double t) { todo("spin_exact"); }

}  // namespace rigid
