// kernels/common/sh.h (the integral of zonal lobes over a spherical polygon)
// against brute-force quadrature of the same function, in float and double,
// and the host side of `sh` (methods/sh_fit.h): real SH and the lobes.
#include "math/kmath.h"
#include "methods/sh_fit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace lb {
namespace {

// q(u) = sum_l sum_j b_lj P_l(w_j . u) from the kernel's layout (sh.h).
double lobesAt(const std::vector<double>& zc, int nb, int nd, glm::dvec3 u)
{
    double q = 0;
    for (int j = 0; j < nd; ++j) {
        const double x = glm::dot(glm::dvec3(zc[3 * j], zc[3 * j + 1], zc[3 * j + 2]), u);
        double p0 = 1, p1 = x;
        for (int l = 0; l < nb; ++l) {
            const double pl = l == 0 ? 1 : p1;
            q += zc[3 * nd + l * nd + j] * (l ? double(l) * (l + 1) : 1) * pl;
            if (l >= 1) {
                const double p2 = ((2 * l + 1) * x * p1 - l * p0) / (l + 1);
                p0 = p1;
                p1 = p2;
            }
        }
    }
    return q;
}

// int over the planar convex polygon p (relative to the viewing point) of
// f(u) d omega = f(x / |x|) |n . x| / |x|^3 dA: a fan of triangles, each by
// a k x k Gauss-Legendre rule on the collapsed square, in s x s pieces.
// Returns {integral, integral of |f|}.
template <class F>
std::pair<double, double> bruteForce(const std::vector<glm::dvec3>& p, F f, int s = 12)
{
    static const double x[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
    static const double w[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    glm::dvec3 nrm = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    double sum = 0, asum = 0;
    for (size_t t = 1; t + 1 < p.size(); ++t) {
        const glm::dvec3 a = p[0], e1 = p[t] - p[0], e2 = p[t + 1] - p[t];
        const double jac = glm::length(glm::cross(e1, e2));
        for (int i = 0; i < s; ++i)
            for (int k = 0; k < s; ++k)
                for (int qi = 0; qi < 8; ++qi)
                    for (int qk = 0; qk < 8; ++qk) {
                        const double uu = (i + 0.5 + 0.5 * x[qi]) / s, vv = (k + 0.5 + 0.5 * x[qk]) / s;
                        const glm::dvec3 pt = a + uu * e1 + uu * vv * e2;
                        const double r = glm::length(pt);
                        const double val = f(pt / r) * std::fabs(glm::dot(nrm, pt)) / (r * r * r);
                        const double wt = w[qi] * w[qk] * 0.25 / (s * s) * jac * uu;
                        sum += wt * val;
                        asum += wt * std::fabs(val);
                    }
    }
    return {sum, asum};
}

// lb_sh_polygon of kernels/common/sh.h in double and in float.
double kernelIntegral64(const std::vector<glm::dvec3>& p, const std::vector<double>& zc, int nb, int nd)
{
    return f64::lb_sh_polygon(p.data(), int(p.size()), zc.data(), nb, nd);
}

double kernelIntegral32(const std::vector<glm::dvec3>& p, const std::vector<double>& zc, int nb, int nd)
{
    std::vector<glm::vec3> q(p.begin(), p.end());
    std::vector<float> z(zc.begin(), zc.end());
    return f32::lb_sh_polygon(q.data(), int(q.size()), z.data(), nb, nd);
}

// Random lobes of nb bands over nd Fibonacci directions (coefficients of one
// size in every band, the kernel's l (l + 1) division applied).
std::vector<double> randomLobes(int nb, int nd, std::mt19937& rng)
{
    std::uniform_real_distribution<double> uni(-1, 1);
    std::vector<double> zc;
    for (auto w : methods::fibonacciDirs(nd)) zc.insert(zc.end(), {w.x, w.y, w.z});
    for (int l = 0; l < nb; ++l)
        for (int j = 0; j < nd; ++j) zc.push_back(uni(rng) / (l ? double(l) * (l + 1) : 1));
    zc[3 * nd] += 3 * nd;  // a positive mean, so the integral is not a cancellation
    return zc;
}

// Polygons of the scenes: a rectangle in front of, beside and far from the
// viewing point, both windings, and a pentagon (a rectangle cut by a plane).
std::vector<std::vector<glm::dvec3>> polygons()
{
    auto rect = [](glm::dvec3 c, glm::dvec3 u, glm::dvec3 v) {
        return std::vector<glm::dvec3>{c - u - v, c + u - v, c + u + v, c - u + v};
    };
    std::vector<std::vector<glm::dvec3>> ps = {
        rect({0, 0, 0.6}, {0.5, 0, 0}, {0, 0.5, 0}),  // head-on, large
        rect({0.3, 1.2, 0.4}, {0.5, 0, 0}, {0, 0.35, 0.35}),  // tilted, off axis
        rect({2.5, 2.5, 1.1}, {0.5, 0, 0}, {0, 0, 0.5}),  // vertical, far, grazing
    };
    auto rev = ps[1];
    std::reverse(rev.begin(), rev.end());
    ps.push_back(rev);
    ps.push_back({{-0.5, -0.5, 0.1}, {0.5, -0.5, 0.1}, {0.5, 0.2, 0.8}, {0.1, 0.5, 1.1}, {-0.5, 0.5, 1.1}});
    return ps;
}

// The integral against the brute force, every degree to 17 (L = 16 and the
// cosine): double to 1e-10 and float to 1e-5, relative to the integral of
// |q| (the scale of the terms the lobes' sum adds: a relative error of the
// signed integral alone would measure cancellation, not the method). The
// brute force converges to ~1e-14 here (12 x 12 pieces of 8 x 8 nodes on a
// smooth integrand of degree <= 17 seen from >= 0.1 m); measured worsts are
// printed.
TEST(ShIntegral, MatchesBruteForceToDegree17FloatAndDouble)
{
    std::mt19937 rng(7);
    double worstD = 0, worstF = 0;
    for (int nb : {1, 2, 5, 10, 18}) {
        const int nd = 2 * nb - 1 + 2;
        std::vector<double> zc = randomLobes(nb, nd, rng);
        for (const auto& p : polygons()) {
            auto [want, scale] = bruteForce(p, [&](glm::dvec3 u) { return lobesAt(zc, nb, nd, u); });
            const double d = kernelIntegral64(p, zc, nb, nd);
            const double f = kernelIntegral32(p, zc, nb, nd);
            worstD = std::max(worstD, std::fabs(d - want) / scale);
            worstF = std::max(worstF, std::fabs(f - want) / scale);
            EXPECT_LT(std::fabs(d - want) / scale, 1e-10) << "bands " << nb;
            EXPECT_LT(std::fabs(f - want) / scale, 1e-5) << "bands " << nb << " float";
        }
    }
    std::printf("sh integral: worst relative %.3g double, %.3g float\n", worstD, worstF);
}

// Real SH: orthonormal on the sphere (a product of degree <= 32 by the 17 x 34
// Gauss x uniform rule, exact), to rounding.
TEST(ShFit, RealShAreOrthonormal)
{
    const int L = 16, n = (L + 1) * (L + 1);
    std::vector<double> G(n * n, 0);
    const int nz = 17, nphi = 34;
    std::vector<double> z, wz;  // the 17 Gauss-Legendre nodes in z
    methods::gaussLegendre(nz, -1, 1, z, wz);
    for (int i = 0; i < nz; ++i)
        for (int k = 0; k < nphi; ++k) {
            const double phi = 2 * M_PI * k / nphi, st = std::sqrt(1 - z[i] * z[i]);
            auto y = methods::realSh(L, {st * std::cos(phi), st * std::sin(phi), z[i]});
            for (int a = 0; a < n; ++a)
                for (int b = 0; b < n; ++b) G[a * n + b] += wz[i] * 2 * M_PI / nphi * y[a] * y[b];
        }
    double worst = 0;
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) worst = std::max(worst, std::fabs(G[a * n + b] - (a == b ? 1.0 : 0.0)));
    EXPECT_LT(worst, 1e-12);  // the rule is exact; what is left is rounding of ~300 terms
}

// The lobes represent the SH expansion they were made from: at random
// directions, sum_lm c_lm Y_lm(u) against the lobes' q(u), degree 17, to 1e-11
// relative to the largest value (the least-norm solve per band in double).
TEST(ShFit, LobesReproduceTheirExpansion)
{
    const int N = 17, n = (N + 1) * (N + 1);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> uni(-1, 1);
    std::vector<double> c(n);
    for (auto& v : c) v = uni(rng);
    auto zc = methods::shToLobes(c, N, methods::fibonacciDirs(methods::shDirs(N - 1)));
    double worst = 0, peak = 0;
    for (int k = 0; k < 200; ++k) {
        glm::dvec3 u = glm::normalize(glm::dvec3(uni(rng), uni(rng), uni(rng)));
        auto y = methods::realSh(N, u);
        double want = 0;
        for (int a = 0; a < n; ++a) want += c[a] * y[a];
        peak = std::max(peak, std::fabs(want));
        worst = std::max(worst, std::fabs(lobesAt(zc, N + 1, methods::shDirs(N - 1), u) - want));
    }
    EXPECT_LT(worst / peak, 1e-11);
}

}  // namespace
}  // namespace lb
