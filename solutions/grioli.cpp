// Chapter 5 reference solutions: Lemma 2 and Theorem 1. Contracts in rigid/grioli.hpp.
#include "rigid/grioli.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rigid/require.hpp"
#include "rigid/rotation.hpp"

namespace rigid {

namespace {

std::string number(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

double sigma(Sense s) { return s == Sense::ccw ? 1.0 : -1.0; }

void require_sense(Sense s) {
    if (s != Sense::ccw && s != Sense::cw) throw std::invalid_argument("sense must be ccw or cw");
}

// C - A as the sum of the gaps: no cancellation.
double C_minus_A(const Moments& m) { return m.B_minus_A + m.C_minus_B; }

// worst = max(worst, x), except that a NaN, once seen, stays.
void raise_to(double& worst, double x) {
    if (std::isnan(worst)) return;
    if (!(x <= worst)) worst = x;
}

}  // namespace

Moments moments(double A, double B, double C) {
    require_finite(A, "A");
    require_finite(B, "B");
    require_finite(C, "C");
    require_positive(A, "A");
    require_positive(B, "B");
    require_positive(C, "C");
    if (!(A < B))
        throw std::invalid_argument("the moments must satisfy A < B, got A = " + number(A) + ", B = " + number(B));
    if (!(B < C))
        throw std::invalid_argument("the moments must satisfy B < C, got B = " + number(B) + ", C = " + number(C));
    const double CB = C - B;
    if (!(CB <= A))
        throw std::invalid_argument("the moments must satisfy the triangle inequality A + B >= C, got A = " +
                                    number(A) + ", B = " + number(B) + ", C = " + number(C));
    return {A, B, C, B - A, CB};
}

Moments moments_from_gaps(double A, double B_minus_A, double C_minus_B) {
    require_finite(A, "A");
    require_finite(B_minus_A, "B - A");
    require_finite(C_minus_B, "C - B");
    require_positive(A, "A");
    if (!(B_minus_A > 0))
        throw std::invalid_argument("the moments must satisfy A < B: B - A must be > 0, got " + number(B_minus_A));
    if (!(C_minus_B > 0))
        throw std::invalid_argument("the moments must satisfy B < C: C - B must be > 0, got " + number(C_minus_B));
    if (!(C_minus_B <= A))
        throw std::invalid_argument("the moments must satisfy the triangle inequality A + B >= C: C - B = " +
                                    number(C_minus_B) + " must be <= A = " + number(A));
    const double B = A + B_minus_A;
    return {A, B, B + C_minus_B, B_minus_A, C_minus_B};
}

double grioli_root(const Moments& m) {
    // sqrt(x y) as sqrt(x) sqrt(y): no overflow or underflow in the product.
    return std::hypot(std::sqrt(m.C_minus_B) * std::sqrt(m.B_minus_A), m.A + m.C_minus_B);
}

double grioli_alpha(const Moments& m, double f) {
    require_positive(f, "f = g L mu");
    return std::sqrt(f / grioli_root(m));
}

double grioli_theta(const Moments& m) {
    return std::atan2(std::sqrt(m.C_minus_B) * std::sqrt(m.B_minus_A), m.A + m.C_minus_B);
}

Vec3 grioli_rotation_vector(const Moments& m) {
    const double CA = C_minus_A(m);
    return Vec3(std::sqrt(m.B_minus_A / CA), 0, -std::sqrt(m.C_minus_B / CA));
}

Vec3 grioli_vertical(const Moments& m) {
    const double S = grioli_root(m), CA = C_minus_A(m);
    return Vec3(m.C_minus_B * std::sqrt(m.B_minus_A / CA) / S, (m.A + m.C_minus_B) / S,
                m.B_minus_A * std::sqrt(m.C_minus_B / CA) / S);
}

GrioliPrecession grioli_precession(const Moments& m, double f, Sense sense) {
    require_sense(sense);
    const Vec3 a = grioli_rotation_vector(m);
    return {sense, f, grioli_alpha(m, f), grioli_theta(m), a, Vec3::UnitY(), grioli_vertical(m), a};
}

Mat3 grioli_rotation(const GrioliPrecession& g, double t) {
    const double phi = sigma(g.sense) * g.alpha * t;
    return rotation_about(g.b, phi) * rotation_about(g.a, phi);
}

Vec3 grioli_angular_velocity(const GrioliPrecession& g, double t) {
    const double s = sigma(g.sense);
    return s * g.alpha * (g.a + rotation_about(g.a, s * g.alpha * t).transpose() * g.b);
}

HeavyTop grioli_top(const Moments& m, const GrioliPrecession& g) {
    return heavy_top(Vec3(m.A, m.B, m.C).asDiagonal().toDenseMatrix(), g.f, g.k, g.z0);
}

BodyState grioli_initial_state(const GrioliPrecession& g) {
    return {grioli_angular_velocity(g, 0.0), Mat3::Identity()};
}

// At t = 0, G is level with O ((k, a) = 0) and Omega = sigma alpha (a + b); since J b = B b and
// (a, b) = 0, 2H = alpha^2 ((a, J a) + B), and (a, J a) = A a_A^2 + C a_C^2 = A + C - B, so
// H = alpha^2 (A + C) / 2 = f (A + C) / (2 S), with A + C a sum of positive numbers.
double grioli_energy(const Moments& m, double f) {
    require_positive(f, "f = g L mu");
    return 0.5 * f * ((m.A + m.A) + (m.B_minus_A + m.C_minus_B)) / grioli_root(m);
}

BodyState euler_poisson_rhs_gaps(const Moments& m, double f, const Vec3& k, const Vec3& z0, const BodyState& s) {
    const Vec3& W = s.Omega;
    const Vec3 torque = f * (s.R.transpose() * k).cross(z0);
    const double B_minus_C = -m.C_minus_B, C_minus_A = m.B_minus_A + m.C_minus_B, A_minus_B = -m.B_minus_A;
    const Vec3 W_dot((B_minus_C * W.y() * W.z() + torque.x()) / m.A,  //
                     (C_minus_A * W.z() * W.x() + torque.y()) / m.B,  //
                     (A_minus_B * W.x() * W.y() + torque.z()) / m.C);
    return {W_dot, s.R * hat(W)};
}

LabPlacement place_item_II(const Moments& m, double f, Sense sense, const Vec3& up, const Vec3& toward) {
    const GrioliPrecession g = grioli_precession(m, f, sense);
    const Vec3 k = require_axis(up, "vertical (up)");
    const Vec3 h = require_axis(k.cross(require_axis(toward, "tilt direction (toward)")),
                                "tilt axis [k, toward] (toward must not be along k)");
    // 1. R_B along k.
    Mat3 Q = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitY(), k).toRotationMatrix();
    // 2. Tilt by theta about the horizontal axis h: b = R_B, at the angle theta to k.
    Q = rotation_about(h, g.theta) * Q;
    const Vec3 b = Q.col(1);
    // 3. a along [b, k]; turn about b until z(0) points along +a.
    const Vec3 a = b.cross(k).normalized();
    const Vec3 z = Q * g.z0;
    Q = rotation_about(b, std::atan2(z.cross(a).dot(b), z.dot(a))) * Q;
    // 4. The rule; steps 1-3 obey it, but a placement with z(0) along -a would not.
    if (!item_II_rule_holds(m, Q, k)) Q = rotation_about(b, std::numbers::pi) * Q;
    LabPlacement p;
    p.sense = sense;
    p.alpha = g.alpha;
    p.theta = g.theta;
    p.R0 = Q;
    p.Omega0 = grioli_angular_velocity(g, 0.0);
    p.k = k;
    p.b = b;
    p.z0 = Q * g.z0;
    p.a = p.z0;  // the rotation vector is z(0) at t = 0, for both senses
    return p;
}

bool item_II_rule_holds(const Moments& m, const Mat3& R0, const Vec3& k) {
    const Vec3 kb = R0.transpose() * require_axis(k, "vertical k");  // k in the body frame
    const Vec3 z = grioli_rotation_vector(m);
    // z(0) = (z_A, 0, z_C) [P, (4.10)]. The axis R_A lies inside the right angle between z(0) and
    // k's projection when the two have components of the same sign on R_A and of opposite signs
    // on R_C: k_A z_A > 0 and k_C z_C < 0. (On the four placements of the contract k is
    // perpendicular to z(0), k_A z_A + k_C z_C = 0, so each half implies the other; both are
    // kept, as the rule reads.)
    return kb.x() * z.x() > 0 && kb.z() * z.z() < 0;
}

PrecessionCheck integrate_grioli(const Moments& m, const GrioliPrecession& g, double periods, int samples_per_period,
                                 const OdeSettings& settings) {
    require_positive(periods, "periods");
    if (samples_per_period < 1) throw std::invalid_argument("samples_per_period must be >= 1");
    const HeavyTop top = grioli_top(m, g);
    const double T = 2 * std::numbers::pi / g.alpha;
    const int n = static_cast<int>(std::ceil(periods * samples_per_period));
    const std::vector<double> times = linspace(0.0, periods * T, n);
    const BodyState s0 = grioli_initial_state(g);
    const double H0 = heavy_top_energy(top, s0);

    PrecessionCheck c{0, 0, 0, 0, {}};
    Mat3 R_last = s0.R;
    const OdeRhs rhs = [&m, &g](double, const VecX& y) {
        return pack(euler_poisson_rhs_gaps(m, g.f, g.k, g.z0, unpack(y)));
    };
    const OdeJacobian jac = [&top](double, const VecX& y) { return euler_poisson_jacobian(top, unpack(y)); };
    c.stats = integrate_gsl(
        rhs, pack(s0), times,
        [&](double t, const VecX& y) {
            const BodyState s = unpack(y);
            raise_to(c.max_rotation_error, geodesic_angle(s.R, grioli_rotation(g, t)));
            raise_to(c.max_omega_error, (s.Omega - grioli_angular_velocity(g, t)).norm() / g.alpha);
            raise_to(c.max_energy_drift, std::abs(heavy_top_energy(top, s) - H0) / g.f);
            R_last = s.R;
        },
        settings, gsl_method_needs_jacobian(settings.method) ? jac : OdeJacobian{});
    c.orthogonality = orthogonality_defect(R_last);
    return c;
}

}  // namespace rigid
