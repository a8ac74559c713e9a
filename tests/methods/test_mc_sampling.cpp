// The Monte Carlo sampling math of kernels/common/mc_sample.h on the host:
// the sequences' net properties, and each map from [0,1)^2 to the light held
// to a closed form (areas, solid angles, Lambert's formula).
#include "math/kmath.h"
#include "methods/mc_table.h"
#include "photometry/table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace lb {
namespace {

using f64::lb_u32;

// Whether the 2^m points (x, y) (32-bit fractions) form a (0, m, 2)-net in
// base 2: every box of 2^a x 2^(m-a) elementary intervals holds one point.
bool isNet(const std::vector<std::pair<lb_u32, lb_u32>>& pts, int m)
{
    for (int a = 0; a <= m; ++a) {
        std::set<std::pair<lb_u32, lb_u32>> boxes;
        for (auto [x, y] : pts) boxes.insert({a ? x >> (32 - a) : 0U, m - a ? y >> (32 - (m - a)) : 0U});
        if (static_cast<int>(boxes.size()) != (1 << m)) return false;
    }
    return true;
}

TEST(McSampling, SobolPrefixesAreNetsAlsoOwenScrambled)
{
    for (int m = 1; m <= 8; ++m) {
        std::vector<std::pair<lb_u32, lb_u32>> plain, owen;
        for (lb_u32 i = 0; i < (1U << m); ++i) {
            plain.push_back({f64::lb_mc_sobol0(i), f64::lb_mc_sobol1(i)});
            owen.push_back({f64::lb_mc_owen(f64::lb_mc_sobol0(i), 0x1234567U + m),
                            f64::lb_mc_owen(f64::lb_mc_sobol1(i), 0x89abcdeU * m)});
        }
        EXPECT_TRUE(isNet(plain, m)) << m;
        EXPECT_TRUE(isNet(owen, m)) << m;
    }
    // the second dimension's first values (natural order): 0, 1/2, 3/4, 1/4, 5/8
    const double want[5] = {0, 0.5, 0.75, 0.25, 0.625};
    for (lb_u32 i = 0; i < 5; ++i) EXPECT_EQ(f64::lb_mc_unit(f64::lb_mc_sobol1(i)), want[i]) << i;
    // a scramble that did nothing would pass the net tests: it moves points
    EXPECT_NE(f64::lb_mc_owen(0x80000000U, 7U), 0x80000000U);
}

// The loop-free second Sobol dimension against its definition: direction
// numbers v_1 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1), x = xor of v_{b+1} over
// the index's set bits b; every bit of 2^16 indices and of 10^5 hashed ones.
TEST(McSampling, SobolSecondDimensionEqualsItsDirectionNumbers)
{
    auto byDefinition = [](lb_u32 i) {
        lb_u32 v = 0x80000000U, x = 0U;
        for (int b = 0; b < 32; ++b, v ^= v >> 1) x ^= ((i >> b) & 1U) ? v : 0U;
        return x;
    };
    for (lb_u32 i = 0; i < (1U << 16); ++i) ASSERT_EQ(f64::lb_mc_sobol1(i), byDefinition(i)) << i;
    for (lb_u32 k = 0; k < 100000; ++k) {
        lb_u32 i = f64::lb_mc_hash(k);
        ASSERT_EQ(f64::lb_mc_sobol1(i), byDefinition(i)) << i;
    }
}

// The float kernels' polynomial sin / cos (OpenCL float has no inlinable
// built-in): within 2e-7 of the double values over [-8 pi, 8 pi] (Cephes'
// polynomials are within ~1 ulp on [-pi/4, pi/4]; the reduction by the
// three-part pi/2 adds below 1 ulp there; measured 9.2e-8). Evaluated in
// float, as the kernels do.
TEST(McSampling, PolynomialSinCosIsWithin2e7)
{
    double worst = 0;
    for (int k = -400000; k <= 400000; ++k) {
        float x = static_cast<float>(k) * 6.2832e-5f;
        float c = 0;
        float s = f32::lb_mc_sincos_poly(x, &c);
        worst = std::max(
            {worst, std::fabs(s - std::sin(static_cast<double>(x))), std::fabs(c - std::cos(static_cast<double>(x)))});
    }
    EXPECT_LT(worst, 2e-7);
    EXPECT_GT(worst, 1e-9);  // float arithmetic: a test of the double path would not reach here
}

TEST(McSampling, Perm4GivesAll24Permutations)
{
    std::set<std::vector<lb_u32>> perms;
    for (lb_u32 h = 0; h < 24; ++h) {
        std::vector<lb_u32> p;
        for (lb_u32 d = 0; d < 4; ++d) p.push_back(f64::lb_mc_perm4(d, h));
        std::vector<lb_u32> sorted = p;
        std::sort(sorted.begin(), sorted.end());
        EXPECT_EQ(sorted, (std::vector<lb_u32>{0, 1, 2, 3})) << h;
        perms.insert(p);
    }
    EXPECT_EQ(perms.size(), 24u);
}

// ZSobol: each pixel's 2^lg samples are one aligned block of Sobol indices
// (so a (0, lg, 2)-net), and the image's blocks are disjoint (a permutation
// of all indices), for even and odd lg.
TEST(McSampling, ZSobolPixelsTakeDisjointAlignedBlocks)
{
    const int res = 8, rb = 3;
    for (int lg : {2, 3}) {
        const int digits = rb + (lg + 1) / 2;
        std::set<lb_u32> all;
        for (int row = 0; row < res; ++row)
            for (int col = 0; col < res; ++col) {
                std::set<lb_u32> block;
                std::vector<std::pair<lb_u32, lb_u32>> pts;
                for (lb_u32 i = 0; i < (1U << lg); ++i) {
                    lb_u32 idx = f64::lb_mc_zsobol_index(col, row, i, lg, digits, 99U);
                    block.insert(idx >> lg);
                    all.insert(idx);
                    pts.push_back({f64::lb_mc_sobol0(idx), f64::lb_mc_sobol1(idx)});
                }
                EXPECT_EQ(block.size(), 1u) << col << "," << row;
                EXPECT_TRUE(isNet(pts, lg)) << col << "," << row;
            }
        EXPECT_EQ(all.size(), static_cast<size_t>(res * res) << lg);
        EXPECT_EQ(*all.rbegin(), (static_cast<lb_u32>(res * res) << lg) - 1);
    }
}

// A midpoint grid of g x g points over [0,1)^2 (a smooth integrand's
// quadrature to O(1/g^2)).
template <class F>
double gridMean(int g, F f)
{
    double s = 0;
    for (int i = 0; i < g; ++i)
        for (int j = 0; j < g; ++j) s += f((i + 0.5) / g, (j + 0.5) / g);
    return s / (double(g) * g);
}

// Uniform in solid angle: dA = r^3 / |z| d(omega), so Omega E[r^3 / |z|] is
// the rectangle's area, and Omega E[1] = Omega from Van Oosterom-Strackee.
TEST(McSampling, SphericalRectangleIsUniformInSolidAngle)
{
    struct R {
        double x0, y0, z0, ex, ey;
    };
    for (R r : {R{-0.5, -0.5, -1.0, 1.0, 1.0}, R{0.3, -2.0, -0.4, 0.7, 0.9}, R{-3.0, 1.0, 0.8, 1.0, 0.2},
                R{-0.2, 0.1, -0.3, 0.4, 2.0}}) {
        auto q = f64::lb_mc_sphrect_setup(r.x0, r.y0, r.z0, r.ex, r.ey);
        glm::dvec3 c0(r.x0, r.y0, r.z0), c1(r.x0 + r.ex, r.y0, r.z0), c2(r.x0 + r.ex, r.y0 + r.ey, r.z0),
            c3(r.x0, r.y0 + r.ey, r.z0);
        double omega = std::fabs(f64::lb_tri_solid_angle(c0, c1, c2) + f64::lb_tri_solid_angle(c0, c2, c3));
        // the sampler's own solid angle (the excess as one argument)
        EXPECT_NEAR(q.s, omega, 1e-12 * omega);
        auto areaAt = [&](int g) {
            return omega * gridMean(g, [&](double u0, double u1) {
                       double x, y;
                       f64::lb_mc_sphrect_sample(&q, u0, u1, &x, &y);
                       EXPECT_TRUE(x >= r.x0 && x <= r.x0 + r.ex && y >= r.y0 && y <= r.y0 + r.ey);
                       double r2 = x * x + y * y + r.z0 * r.z0;
                       return r2 * std::sqrt(r2) / std::fabs(r.z0);
                   });
        };
        // the midpoint rule's O(1/g^2) error (measured: 6e-4 relative at 400^2
        // for the last rectangle, falling 4x per doubling) removed by one
        // Richardson step; what is left is O(1/g^4), below 1e-5
        double area = (4 * areaAt(800) - areaAt(400)) / 3;
        EXPECT_NEAR(area, r.ex * r.ey, 1e-5 * r.ex * r.ey) << r.x0 << " " << r.y0;
    }
}

// The sampler's solid angle in float is Van Oosterom-Strackee's on the edge
// vectors (common/mc_lanes.inc), not the sum of the four interior angles less
// 2 pi: for a 1 mm light 2.4 m off to the side at 1 m (7e-8 sr) the angles'
// float error of ~1e-7 rad each was 60 % of the excess. Against the double-
// precision solid angle of the same float rectangle, relative: the
// select-only atan2's 2.5e-7 and a few roundings: measured <= 8e-8, and
// 3.8e-6 for a light 0.1 mm above the receiver's plane and 1 cm to the side,
// so 1e-5; near a hemisphere (a 4 x 6 m light 1 mm above, 100 x 100 m 1 cm
// above) the two triangles' atan2 near pi lose more: 1.6e-4, so 5e-4.
TEST(McSampling, SphericalRectangleExcessIsAccurateInFloat)
{
    struct R {
        double x0, y0, z0, ex, ey;
    };
    for (R r : {R{-0.5, -0.5, -1.0, 1.0, 1.0}, R{0.3, -2.0, -0.4, 0.7, 0.9}, R{1.0, 2.0, -1.0, 1e-3, 1e-3},
                R{-5e-4, -5e-4, -1.0, 1e-3, 1e-3}, R{40.0, 3.0, -2.0, 1e-3, 2e-3}, R{-2.0, -3.0, -1e-3, 4.0, 6.0},
                R{-50.0, -50.0, -0.01, 100.0, 100.0}, R{0.01, -0.5, -1e-4, 1.0, 1.0}}) {
        const float x0 = float(r.x0), y0 = float(r.y0), z0 = float(r.z0), ex = float(r.ex), ey = float(r.ey);
        auto q = f32::lb_mc_sphrect_setup(x0, y0, z0, ex, ey);
        // the rectangle as the float caller has it (x0 + ex rounded)
        const double x1 = double(x0 + ex), y1 = double(y0 + ey);
        glm::dvec3 c0(x0, y0, z0), c1(x1, y0, z0), c2(x1, y1, z0), c3(x0, y1, z0);
        double omega = std::fabs(f64::lb_tri_solid_angle(c0, c1, c2) + f64::lb_tri_solid_angle(c0, c2, c3));
        double tol = omega > 6 ? 5e-4 * omega : 1e-5 * omega;
        EXPECT_NEAR(q.s, omega, tol) << r.x0 << " " << r.y0 << " " << r.z0 << " " << r.ex;
        std::printf("excess %.6g: float relative error %.2g\n", omega, std::fabs(q.s - omega) / omega);
    }
}

// The table sampler (common/mc_table.h on host/methods/mc_table.cpp's
// buffer): every sample's density is what lb_mc_tab_pdf gives at its
// direction, every direction towards the rectangle has a density (E[hit /
// pdf] over the window is the rectangle's solid angle, Van Oosterom-
// Strackee), on a foot inside the rectangle (every azimuth), windows that
// cross C = 0, a light seen from behind its plane (gamma > 90) and a thin
// one far off (a window of one cell column).
TEST(McSampling, TableSamplerDensityCoversTheRectangle)
{
    const double d = M_PI / 180;
    auto t = photometry::tabulate(
        [&](double c, double g) {
            return 1000 * std::exp(-0.5 * std::pow(g / 8, 2)) * (1 + 0.5 * std::cos(c * d)) + (g < 90 ? 5 : 1);
        },
        25, 73);
    const std::vector<float> tab = methods::mcTableSampler(t);
    struct Rc {
        double x0, y0, on, w, ey;
    };
    for (Rc r : {Rc{-0.5, -0.5, -1.0, 1.0, 1.0}, Rc{0.3, -2.0, -0.4, 0.7, 0.9}, Rc{-1.5, -0.3, -1.0, 1.0, 0.6},
                 Rc{-3.0, 1.0, 0.8, 1.0, 0.2}, Rc{4.0, -0.05, -0.3, 0.2, 0.1}}) {
        f64::lb_mc_tabwin tw;
        f64::lb_mc_tabwin_setup(tab.data(), r.x0, r.y0, r.on, r.w, r.ey, &tw);
        glm::dvec3 c0(r.x0, r.y0, r.on), c1(r.x0 + r.w, r.y0, r.on), c2(r.x0 + r.w, r.y0 + r.ey, r.on),
            c3(r.x0, r.y0 + r.ey, r.on);
        double omega = std::fabs(f64::lb_tri_solid_angle(c0, c1, c2) + f64::lb_tri_solid_angle(c0, c2, c3));
        double worst = 0, hits = 0;
        double est = gridMean(1000, [&](double u0, double u1) {
            double dx, dy, dz;
            double p = f64::lb_mc_tab_sample(&tw, u0, u1, &dx, &dy, &dz);
            worst = std::max(worst, std::fabs(p - f64::lb_mc_tab_pdf(&tw, dx, dy, dz)) / p);
            double sc = dz != 0 ? r.on / dz : 0, pu = dx * sc, pv = dy * sc;
            bool hit = sc < 0 && pu >= r.x0 && pu <= r.x0 + r.w && pv >= r.y0 && pv <= r.y0 + r.ey;
            hits += hit;
            return hit ? 1 / p : 0.0;
        });
        std::printf("table window cells %d x %d, hits %.0f: E[hit / pdf] / omega - 1 = %.2e, pdf mismatch %.1e\n",
                    tw.i1 - tw.i0 + 1, tw.j1 - tw.j0 + 1, hits, est / omega - 1, worst);
        // a sample's cell and its remainders found again from its direction:
        // rounding only (double)
        EXPECT_LE(worst, 1e-9) << r.x0;
        // the midpoint rule over 1000^2 points of a piecewise smooth
        // integrand with the rectangle's edges as discontinuities: the grid
        // points along the edges carry the error, relative ~ 1 / sqrt(hits)
        // for a compact hit region, more for a thin one (measured 1.1e-6 ..
        // 2.0e-4 with 2.2e5 - 9.8e5 hits, 2.7e-3 with the thin light's 2.3e4
        // in a thin strip); a direction without density, or a density off by
        // its cell's share, is an error of the order of a cell's share of the
        // window (1/2160 .. 1/2 here)
        EXPECT_NEAR(est, omega, std::max(1e-3, 1 / std::sqrt(hits)) * omega) << r.x0;
    }
}

// The bilinear warp's returned density: E[h / pdf] = the integral of h.
TEST(McSampling, BilinearWarpDensityIsExact)
{
    const double w[4] = {0.2, 1.0, 0.05, 0.6};
    double mean1 = gridMean(400, [&](double u0, double u1) {
        double x = u0, y = u1;
        double pdf = f64::lb_mc_bilinear(&x, &y, w[0], w[1], w[2], w[3]);
        return x * y * y / pdf;  // integral over [0,1]^2: 1/6
    });
    // the warp's pdf / h ratio is smooth: midpoint error O(1/400^2)
    EXPECT_NEAR(mean1, 1.0 / 6, 1e-5);
    // and it is a warp: corners map to corners, the density there is the weight's share
    double x = 0, y = 0;
    EXPECT_NEAR(f64::lb_mc_bilinear(&x, &y, w[0], w[1], w[2], w[3]), 4 * w[0] / (w[0] + w[1] + w[2] + w[3]), 1e-12);
}

// Polygons in the receiver frame: zenith inside, zenith outside, one edge on
// the horizon (the clipped light), a thin one near the horizon.
std::vector<std::vector<glm::dvec3>> polygons()
{
    return {{{-0.5, -0.5, 1}, {0.5, -0.5, 1}, {0.5, 0.5, 1}, {-0.5, 0.5, 1}},
            {{0.3, 0.2, 1.0}, {1.3, 0.2, 0.8}, {1.3, 0.9, 0.6}, {0.3, 0.9, 0.8}},
            {{-0.5, 0.4, 0.0}, {0.5, 0.4, 0.0}, {0.5, 1.0, 0.7}, {-0.5, 1.0, 0.7}},
            {{-0.5, 2.0, 0.05}, {-0.5, 3.0, 0.02}, {0.5, 3.0, 0.02}, {0.5, 2.0, 0.05}},
            {{2.0, -0.3, 0.5}, {2.0, 0.3, 0.5}, {-0.1, 0.3, 0.5}, {-0.1, -0.3, 0.5}}};
}

// The integral of cos^2 over the parallelogram poly[0], poly[1], poly[3] +
// poly[1] - poly[0], ...: cos^2 theta |n_L . w| / r^2 dA by the midpoint rule
// in its (s, t) (a smooth integrand, also where an edge lies on the horizon).
double cos2Integral(const std::vector<glm::dvec3>& poly, int g)
{
    glm::dvec3 e1 = poly[1] - poly[0], e2 = poly[3] - poly[0];
    glm::dvec3 c = glm::cross(e1, e2);
    double jac = glm::length(c);
    glm::dvec3 nl = c / jac;
    return jac * gridMean(g, [&](double s, double t) {
               glm::dvec3 p = poly[0] + s * e1 + t * e2;
               double r2 = glm::dot(p, p), r = std::sqrt(r2);
               return (p.z / r) * (p.z / r) * std::fabs(glm::dot(nl, p) / r) / r2;
           });
}

// The projected solid angle equals Lambert's formula, and the directions are
// distributed by cos / area: area E[cos] is the integral of cos^2 over the
// polygon, and every direction lies inside the polygon's cone.
TEST(McSampling, ProjectedSolidAngleSamplingIsCosineDistributed)
{
    for (auto& poly : polygons()) {
        double qx[4], qy[4], qz[4];
        for (int k = 0; k < 4; ++k) qx[k] = poly[k].x, qy[k] = poly[k].y, qz[k] = poly[k].z;
        auto p = f64::lb_mc_proj_setup(qx, qy, qz);
        double lambert = f64::lb_polygon_irradiance_lambert(poly.data(), 4, {0, 0, 1});
        EXPECT_NEAR(p.area, lambert, 1e-12 * std::max(1.0, lambert)) << poly[1].x;
        double worst = 0;
        double est = p.area * gridMean(300, [&](double u0, double u1) {
                         glm::dvec3 d;
                         f64::lb_mc_proj_sample(&p, u0, u1, &d.x, &d.y, &d.z);
                         for (int k = 0; k < 4; ++k) {
                             glm::dvec3 nk = glm::normalize(glm::cross(poly[k], poly[(k + 1) % 4]));
                             double side = glm::dot(nk, d) * glm::sign(glm::dot(nk, poly[(k + 2) % 4]));
                             worst = std::min(worst, side);
                         }
                         return d.z;
                     });
        // inside the cone up to the inversion's rounding
        EXPECT_GE(worst, -1e-9) << poly[1].x;
        double want = cos2Integral(poly, 1000);
        // both midpoint sums of bounded integrands with a few kinks (measured
        // worst 1.5e-4, the thin grazing polygon; others <= 3e-5); a wrong
        // arc weight or azimuth range moves the sum by percents
        EXPECT_NEAR(est, want, 5e-4 * want) << poly[1].x;
    }
}

}  // namespace
}  // namespace lb
