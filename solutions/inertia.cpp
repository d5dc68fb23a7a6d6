// Chapter 6 reference solutions: the Grioli lines. Contracts in rigid/inertia.hpp.
#include "rigid/inertia.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rigid/require.hpp"

namespace rigid {

namespace {

void require_distance(double L) { require_positive(L, "the distance L"); }

// z must be a unit vector in the plane of x_A and x_C.
void require_plane_direction(const Vec3& z) {
    if (!z.allFinite()) throw std::invalid_argument("the direction z must be a finite vector, got " + describe(z));
    if (!(std::abs(z.norm() - 1) <= 1e-12))
        throw std::invalid_argument("the direction z must be a unit vector, got " + describe(z));
    if (!(std::abs(z.y()) <= 1e-12))
        throw std::invalid_argument(
            "the direction z must lie in the plane of the smallest and largest axes at G (z_B = 0), got " +
            describe(z));
}

void require_symmetric(const Mat3& I, const std::string& name) {
    if (!I.allFinite()) throw std::invalid_argument(name + " must have finite entries");
    if (!((I - I.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * I.cwiseAbs().maxCoeff()))
        throw std::invalid_argument(name + " must be symmetric");
}

// The geometry of a line through G in the principal plane, with the combinations the closed
// forms need, each formed without cancellation where it can be.
struct Line {
    double zA, zC;    // the unit direction
    double zA2, zC2;  // its squares
    double k;         // z_A^2 - z_C^2 = cos 2phi_g
    double s2;        // 2 z_A z_C     = sin 2phi_g
    double delta;     // (C_g - B_g) z_A^2 - (B_g - A_g) z_C^2 = Delta_- - B_g
};

Line line_of(const BodyAtG& b, const Vec3& z) {
    Line l;
    l.zA = z.x();
    l.zC = z.z();
    l.zA2 = l.zA * l.zA;
    l.zC2 = l.zC * l.zC;
    l.k = (l.zA - l.zC) * (l.zA + l.zC);
    l.s2 = 2 * l.zA * l.zC;
    l.delta = (b.C_g - b.B_g) * l.zA2 - (b.B_g - b.A_g) * l.zC2;
    return l;
}

// The exact Grioli line: cos^2 phi_g = (B_g - A_g)/(C_g - A_g), delta = 0 by construction.
Line grioli_line(const BodyAtG& b, int sign) {
    const double dBA = b.B_g - b.A_g, dCB = b.C_g - b.B_g, dCA = b.C_g - b.A_g;
    Line l;
    l.zA2 = dBA / dCA;
    l.zC2 = dCB / dCA;
    l.zA = std::sqrt(l.zA2);
    l.zC = sign * std::sqrt(l.zC2);
    l.k = (dBA - dCB) / dCA;
    l.s2 = 2 * sign * std::sqrt(dBA * dCB) / dCA;
    l.delta = 0;
    return l;
}

ShiftedMoments moments_on(const BodyAtG& b, double h, const Line& l) {
    const double dBA = b.B_g - b.A_g, dCB = b.C_g - b.B_g, dCA = b.C_g - b.A_g;
    ShiftedMoments m;
    // sqrt(D) as the length of (h + (C_g - A_g) cos 2phi_g, (C_g - A_g) sin 2phi_g): (5.10) with
    // the roles of h and C_g - A_g exchanged; a sum of squares cannot cancel.
    const double sqrtD = std::hypot(h + dCA * l.k, dCA * l.s2);
    m.C_minus_A = sqrtD;
    m.C = 0.5 * (b.A_g + b.C_g + h + sqrtD);
    m.A = (b.A_g * b.C_g + h * (b.A_g * l.zA2 + b.C_g * l.zC2)) / m.C;  // det / C, (5.4) first form
    m.B = b.B_g + h;
    // C - B and B - A are the roots of mu^2 - sqrt(D) mu + P = 0 shifted: their sum is sqrt(D),
    // their product P = (B_g - A_g)(C_g - B_g) + h delta. With hs = h + 2B_g - A_g - C_g,
    // B - A = (hs + sqrt(D))/2 and C - B = (sqrt(D) - hs)/2: take the one that does not cancel.
    const double hs = h + (dBA - dCB);
    const double P = dBA * dCB + h * l.delta;
    if (hs >= 0) {
        m.B_minus_A = 0.5 * (hs + sqrtD);
        m.C_minus_B = P / m.B_minus_A;
    } else {
        m.C_minus_B = 0.5 * (sqrtD - hs);
        m.B_minus_A = P / m.C_minus_B;
    }
    return m;
}

Cos2Sin2 tilt_on(const BodyAtG& b, double h, const Line& l) {
    const double dCA = b.C_g - b.A_g;
    const double u = h + dCA * l.k, w = dCA * l.s2;
    const double sqrtD = std::hypot(u, w);
    if (sqrtD == 0) return {l.zA2, l.zC2};  // A = C: R_A taken as x_A
    // cos^2 = (sqrtD + u)/(2 sqrtD), sin^2 = (sqrtD - u)/(2 sqrtD), and their product is
    // w^2 / (4 D): the one that would cancel comes from the other.
    const double big = 0.5 * (sqrtD + std::abs(u)) / sqrtD;
    const double small = (w / sqrtD) * (w / (2 * (sqrtD + std::abs(u))));
    return u >= 0 ? Cos2Sin2{big, small} : Cos2Sin2{small, big};
}

PrincipalFrame frame_on(const BodyAtG& b, double h, const Line& l, const Vec3& z) {
    PrincipalFrame f;
    f.I = Vec3(b.A_g, b.B_g, b.C_g).asDiagonal();
    f.I += h * (Mat3::Identity() - z * z.transpose());
    f.moments = moments_on(b, h, l);
    const double dCA = b.C_g - b.A_g;
    const double theta = 0.5 * std::atan2(h * l.s2, dCA + h * l.k);  // in (-pi/2, pi/2]
    const double c = std::cos(theta), s = std::sin(theta);
    f.R << c, 0, -s,  //
        0, 1, 0,      //
        s, 0, c;
    return f;
}

}  // namespace

Mat3 inertia_tensor(const std::vector<PointMass>& points, const Vec3& origin) {
    if (points.empty()) throw std::invalid_argument("inertia_tensor needs at least one point mass");
    if (!origin.allFinite()) throw std::invalid_argument("the origin must be a finite vector, got " + describe(origin));
    Mat3 I = Mat3::Zero();
    for (const auto& p : points) {
        require_positive(p.m, "a point mass");
        if (!p.x.allFinite()) throw std::invalid_argument("a point position must be finite, got " + describe(p.x));
        const Vec3 x = p.x - origin;
        I += p.m * (x.squaredNorm() * Mat3::Identity() - x * x.transpose());
    }
    return I;
}

std::vector<PointMass> six_point_body(const BodyAtG& body) {
    require_body(body);
    const double m = body.mu / 6;
    const double S[3] = {0.5 * (body.B_g + body.C_g - body.A_g), 0.5 * (body.C_g + body.A_g - body.B_g),
                         0.5 * (body.A_g + body.B_g - body.C_g)};
    std::vector<PointMass> points;
    for (int i = 0; i < 3; ++i) {
        const double s = std::sqrt(S[i] / (2 * m));
        points.push_back({m, s * Vec3::Unit(i)});
        points.push_back({m, -s * Vec3::Unit(i)});
    }
    return points;
}

Mat3 shifted_inertia(const Mat3& I_G, double mu, const Vec3& r) {
    require_symmetric(I_G, "the inertia tensor at G");
    require_positive(mu, "the mass mu");
    if (!r.allFinite()) throw std::invalid_argument("the shift r must be a finite vector, got " + describe(r));
    return I_G + mu * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
}

ShiftedMoments printed_moments(const BodyAtG& body, double L, const Vec3& z) {
    require_body(body);
    require_distance(L);
    require_plane_direction(z);
    const double h = body.mu * L * L, dCA = body.C_g - body.A_g;
    const double D = h * h + 2 * dCA * (z.x() * z.x() - z.z() * z.z()) * h + dCA * dCA;
    ShiftedMoments m;
    m.C = 0.5 * (body.A_g + body.C_g + h + std::sqrt(D));
    m.B = body.B_g + h;
    m.A = 0.5 * (body.A_g + body.C_g + h - std::sqrt(D));
    m.C_minus_A = m.C - m.A;
    m.C_minus_B = m.C - m.B;
    m.B_minus_A = m.B - m.A;
    return m;
}

ShiftedMoments shifted_moments(const BodyAtG& body, double L, const Vec3& z) {
    require_body(body);
    require_distance(L);
    require_plane_direction(z);
    return moments_on(body, body.mu * L * L, line_of(body, z));
}

double critical_cos2(const BodyAtG& body) {
    require_body(body);
    return (body.B_g - body.A_g) / (body.C_g - body.A_g);
}

double hyperbola_lhs(const BodyAtG& body, double x_A, double x_C) {
    require_body(body);
    require_finite(x_A, "x_A");
    require_finite(x_C, "x_C");
    return body.mu * (x_C * x_C / (body.C_g - body.B_g) - x_A * x_A / (body.B_g - body.A_g));
}

double critical_h(const BodyAtG& body, const Vec3& z) {
    require_body(body);
    require_plane_direction(z);
    const Line l = line_of(body, z);
    // The denominator of (5.8) is B_g - Delta_- = -delta.
    if (!(l.delta < 0)) return std::numeric_limits<double>::infinity();
    return (body.B_g - body.A_g) * (body.C_g - body.B_g) / -l.delta;
}

int region(const BodyAtG& body, double x_A, double x_C) {
    require_body(body);
    require_finite(x_A, "x_A");
    require_finite(x_C, "x_C");
    const double dBA = body.B_g - body.A_g, dCB = body.C_g - body.B_g;
    // L^2 delta: > 0 beyond the asymptotes (around x_A), < 0 between them (around x_C).
    const double s = dCB * x_A * x_A - dBA * x_C * x_C;
    if (s > 0) return x_A > 0 ? 1 : 2;
    if (!(s < 0)) return 0;
    // (C - B)(B - A) = dBA dCB + mu s: positive short of the hyperbola, negative past it.
    const double P = dBA * dCB + body.mu * s;
    if (P > 0) return x_C > 0 ? 3 : 4;
    if (P < 0) return x_C > 0 ? 5 : 6;
    return 0;
}

Cos2Sin2 smallest_axis_tilt(const BodyAtG& body, double L, const Vec3& z) {
    require_body(body);
    require_distance(L);
    require_plane_direction(z);
    return tilt_on(body, body.mu * L * L, line_of(body, z));
}

Cos2Sin2 grioli_ratio(const ShiftedMoments& m) { return {m.B_minus_A / m.C_minus_A, m.C_minus_B / m.C_minus_A}; }

PrincipalFrame principal_frame(const BodyAtG& body, double L, const Vec3& z) {
    require_body(body);
    require_distance(L);
    require_plane_direction(z);
    return frame_on(body, body.mu * L * L, line_of(body, z), z);
}

Vec3 grioli_direction(const BodyAtG& body, int sign) {
    require_body(body);
    if (sign != 1 && sign != -1)
        throw std::invalid_argument("the sign of a Grioli line must be +1 or -1, got " + std::to_string(sign));
    const Line l = grioli_line(body, sign);
    return Vec3(l.zA, 0, l.zC);
}

GrioliSuspension grioli_suspension(const BodyAtG& body, double L, int sign) {
    GrioliSuspension g;
    g.z = grioli_direction(body, sign);
    require_distance(L);
    const Line l = grioli_line(body, sign);
    const double h = body.mu * L * L;
    g.O = L * g.z;
    g.frame = frame_on(body, h, l, g.z);
    g.z0 = g.frame.R.transpose() * (-g.z);
    g.tilt = tilt_on(body, h, l);
    g.expected = grioli_ratio(g.frame.moments);
    return g;
}

std::array<Vec3, 2> circular_section_normals(const Mat3& I) {
    require_symmetric(I, "the inertia tensor");
    Eigen::SelfAdjointEigenSolver<Mat3> eig(I);
    const Vec3 lambda = eig.eigenvalues();  // increasing
    if (!(lambda(0) > 0 && lambda(0) < lambda(1) && lambda(1) < lambda(2)))
        throw std::invalid_argument("the inertia tensor must have three distinct positive eigenvalues");
    auto fixed_sign = [](Vec3 u) {
        Eigen::Index i;
        u.cwiseAbs().maxCoeff(&i);
        return u(i) < 0 ? Vec3(-u) : u;
    };
    const Vec3 uA = fixed_sign(eig.eigenvectors().col(0)), uC = fixed_sign(eig.eigenvectors().col(2));
    const double cA = std::sqrt((lambda(1) - lambda(0)) / (lambda(2) - lambda(0)));
    const double cC = std::sqrt((lambda(2) - lambda(1)) / (lambda(2) - lambda(0)));
    return {cA * uA + cC * uC, cA * uA - cC * uC};
}

// (z, I' z) = (z, I_G z) + h ((z, z) - (z, z)^2) = A_g z_A^2 + C_g z_C^2 with z_A^2 = (B_g - A_g)/(C_g - A_g)
// and z_C^2 = (C_g - B_g)/(C_g - A_g): [A_g (B_g - A_g) + C_g (C_g - B_g)] / (C_g - A_g) = A_g + C_g - B_g.
// The shift drops out because it adds h to every moment about a line through O orthogonal to
// z and nothing about z itself. Formed as A_g + (C_g - B_g): no cancellation.
double grioli_line_axial_moment(const BodyAtG& body) {
    require_body(body);
    return body.A_g + (body.C_g - body.B_g);
}

}  // namespace rigid
