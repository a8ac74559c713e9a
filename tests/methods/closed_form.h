// closed_form.h -- test oracles for the reference: irradiance from a rectangle
// with I(gamma) = I0 cos^n(gamma) (one-sided: 0 behind the light).
//
// Derivation. Put the receiver x at the origin; a light point is
// p = (a u + b v + o_n n_L) with a in [a0, a1], b in [b0, b1] (o = the light's
// (-u,-v) corner relative to x) and D = |o_n|. The emission direction is
// d = -p / r, so cos(gamma) = -o_n / r (x lit only when o_n < 0), and
//   E = (1/A) int I0 (D/r)^n (n_x . p) / r^3 dA
//     = (I0 D^n / A) int_b int_a (alpha a + beta b + zeta o_n) / (a^2 + c^2)^k da db,
// alpha = n_x.u, beta = n_x.v, zeta = n_x.n_L, c^2 = b^2 + D^2, k = (n + 3)/2
// (valid when n_x . p >= 0 over the whole light, as in the normalized scene).
// The a-integral is closed:
//   int a / (a^2+c^2)^k da = -1 / (2 (k-1) (a^2+c^2)^(k-1)),
//   J_k = int da / (a^2+c^2)^k, J_1/2 = asinh(a/c), J_1 = atan(a/c)/c,
//   J_{k+1} = a / (2k c^2 (a^2+c^2)^k) + (2k-1) / (2k c^2) J_k,
// leaving one smooth 1D integral over b, done by adaptive Gauss-Legendre to
// 1e-13 relative in double -- a method independent of the kernel's cubature.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace lb::test {

inline double adaptiveGL(const std::function<double(double)>& f, double a, double b, double eps, int depth = 0)
{
    static const double x[5] = {-0.906179845938664, -0.538469310105683, 0.0, 0.538469310105683, 0.906179845938664};
    static const double w[5] = {0.236926885056189, 0.478628670499366, 0.568888888888889, 0.478628670499366,
                                0.236926885056189};
    auto gl = [&](double lo, double hi) {
        double m = 0.5 * (lo + hi), h = 0.5 * (hi - lo), s = 0;
        for (int i = 0; i < 5; ++i) s += w[i] * f(m + h * x[i]);
        return s * h;
    };
    double m = 0.5 * (a + b);
    double whole = gl(a, b), halves = gl(a, m) + gl(m, b);
    // eps is not halved per level (that would chase rounding noise): the
    // accepted intervals are few, and their summed error stays ~1e-13 relative.
    if (std::fabs(whole - halves) <= std::max(eps, 1e-15 * std::fabs(halves)) || depth > 30) return halves;
    return adaptiveGL(f, a, m, eps, depth + 1) + adaptiveGL(f, m, b, eps, depth + 1);
}

// E at receiver point x (normal nx) from the scene's light with I0 cos^n.
inline double cosnIrradiance(const Scene& sc, int n, double i0, glm::dvec3 x, glm::dvec3 nx = {0, 0, 1})
{
    glm::dvec3 u = sc.u(), v = sc.v(), nl = sc.n();
    glm::dvec3 o = sc.corners()[0] - x;
    double a0 = glm::dot(o, u), a1 = a0 + sc.width;
    double b0 = glm::dot(o, v), b1 = b0 + sc.length;
    double on = glm::dot(o, nl);
    if (!(on < 0)) return 0.0;  // x behind or in the light's plane
    double D = -on, alpha = glm::dot(nx, u), beta = glm::dot(nx, v), zeta = glm::dot(nx, nl);
    double k = 0.5 * (n + 3);
    auto inner = [&](double b) {
        double c2 = b * b + D * D, c = std::sqrt(c2);
        auto q = [&](double a, double kk) { return std::pow(a * a + c2, kk); };
        // Definite J by the recurrence from J_1/2 or J_1.
        double kk, J;
        if (n % 2 == 0) {
            kk = 0.5;
            J = std::asinh(a1 / c) - std::asinh(a0 / c);
        } else {
            kk = 1.0;
            J = (std::atan(a1 / c) - std::atan(a0 / c)) / c;
        }
        while (kk < k - 0.25) {
            J = (a1 / q(a1, kk) - a0 / q(a0, kk)) / (2 * kk * c2) + (2 * kk - 1) / (2 * kk * c2) * J;
            kk += 1.0;
        }
        double K = -(1.0 / q(a1, k - 1) - 1.0 / q(a0, k - 1)) / (2 * (k - 1));
        return alpha * K + (beta * b + zeta * on) * J;
    };
    // Scale for the absolute tolerance: a coarse midpoint sum.
    double scale = 0;
    for (int i = 0; i < 64; ++i) scale += std::fabs(inner(b0 + (i + 0.5) * (b1 - b0) / 64));
    scale *= (b1 - b0) / 64;
    double I = adaptiveGL(inner, b0, b1, 1e-13 * scale + 1e-300);
    return i0 * std::pow(D, n) / (sc.width * sc.length) * I;
}

}  // namespace lb::test
