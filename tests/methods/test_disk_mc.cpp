// Solid-angle sampling of the disk light (kernels/common/disk_sample.h) on the
// host: the sampler's weight is its inverse density in solid angle, so its
// mean over [0,1)^2 is the disk's solid angle and the mean of weight x
// r^3 / h its area; both against independent closed forms, and the weight's
// spread (how far from uniform the tabulated angular density leaves it).
#include "math/kmath.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lb {
namespace {

// Solid angle of the ellipse centred at (cx, cy) with semi-axes a, b in the
// plane z = -h, seen from the origin: a fan of Van Oosterom-Strackee
// triangles over the inscribed k-gon scaled to the ellipse's area (relative
// error ~ (2 pi / k)^4 / 360, ~2e-13 at k = 4096, as test_disk.cpp's polygon).
double ellipseSolidAngle(double cx, double cy, double h, double a, double b, int k = 4096)
{
    const double scale = std::sqrt(2 * M_PI / (k * std::sin(2 * M_PI / k)));
    const glm::dvec3 c(cx, cy, -h);
    double s = 0;
    for (int i = 0; i < k; ++i) {
        double p0 = 2 * M_PI * i / k, p1 = 2 * M_PI * (i + 1) / k;
        glm::dvec3 q0 = c + scale * glm::dvec3(a * std::cos(p0), b * std::sin(p0), 0);
        glm::dvec3 q1 = c + scale * glm::dvec3(a * std::cos(p1), b * std::sin(p1), 0);
        s += f64::lb_tri_solid_angle(c, q0, q1);
    }
    return std::fabs(s);
}

struct Ellipse {
    double cx, cy, h, a, b;
};

// Inside (centred, off-centre, an ellipse), just inside and just outside the
// rim, outside near and far, and a grazing view (h 0.02, 1.5 radii away).
const Ellipse kCases[] = {{0, 0, 0.1, 0.5, 0.5},    {0.3, -0.1, 0.1, 0.5, 0.5}, {0.2, 0.1, 1.1, 0.5, 0.2},
                          {0.49, 0, 0.1, 0.5, 0.5}, {0.51, 0, 0.1, 0.5, 0.5},   {-0.4, 0.9, 0.3, 0.5, 0.3},
                          {3, -2, 1.1, 0.5, 0.5},   {0.75, 0, 0.02, 0.5, 0.5}};

// Midpoint-rule means over a g x g grid of (u0, u1): the weight (-> Omega),
// weight r^3 / h (-> area), the weight's square, and how far a sample lies
// outside the ellipse.
struct GridMeans {
    double omega = 0, area = 0, w2 = 0, outside = 0;
};

GridMeans gridMeans(const Ellipse& e, int g0, int g1)
{
    f64::lb_mc_sphdisk q;
    f64::lb_mc_sphdisk_setup(e.cx, e.cy, e.h, e.a, e.b, &q);
    GridMeans m;
    const double n = double(g0) * g1;
    for (int i = 0; i < g0; ++i)
        for (int j = 0; j < g1; ++j) {
            double x, y;
            double w = f64::lb_mc_sphdisk_sample(&q, (i + 0.5) / g0, (j + 0.5) / g1, &x, &y);
            double r2 = x * x + y * y + e.h * e.h;
            double ex = (x - e.cx) / e.a, ey = (y - e.cy) / e.b;
            m.outside = std::max(m.outside, ex * ex + ey * ey - 1);
            m.omega += w / n;
            m.area += w * r2 * std::sqrt(r2) / e.h / n;
            m.w2 += w * w / n;
        }
    return m;
}

TEST(DiskMc, SolidAngleSamplerIntegratesToTheSolidAngleAndTheArea)
{
    for (const Ellipse& e : kCases) {
        const double omega = ellipseSolidAngle(e.cx, e.cy, e.h, e.a, e.b), area = M_PI * e.a * e.b;
        GridMeans m = gridMeans(e, 2048, 2048);
        // the weight depends on u0 alone: its mean on a fine 1D grid
        f64::lb_mc_sphdisk q;
        f64::lb_mc_sphdisk_setup(e.cx, e.cy, e.h, e.a, e.b, &q);
        const int g1 = 1 << 16;
        double omega1 = 0;
        for (int i = 0; i < g1; ++i) {
            double x, y;
            omega1 += f64::lb_mc_sphdisk_sample(&q, (i + 0.5) / g1, 0.5, &x, &y) / g1;
        }
        // Every sample on the ellipse: to rounding of the quadratic's roots.
        EXPECT_LT(m.outside, 1e-9) << e.cx << " " << e.cy;
        // The weight integrates G(t) over t exactly (by the substitution
        // u0 -> t); what is left is the midpoint rule's error in u0: the
        // tangent cells' t(u0) ~ sqrt(u0) makes it O(g^-1.5), and just inside
        // the rim G has a dip ~0.003 wide in u0 (2.8e-4 relative at g = 1024,
        // 1.6e-6 at 16384). Measured worst at g = 2^16: 3.5e-7; 1e-5 still
        // catches a density off by a cell's interpolation error (~1e-2).
        EXPECT_NEAR(omega1, omega, 1e-5 * omega) << e.cx << " " << e.cy << " h " << e.h;
        // dA = r^3 / h d(omega): the area from the 2D grid's samples
        // (2048^2 grid; measured worst 7.9e-5: the grid's error where the
        // narrow tangent cells make t(u0) steep)
        EXPECT_NEAR(m.area, area, 2e-4 * area) << e.cx << " " << e.cy << " h " << e.h;
        // Near-uniform: the weight is 1 / the density in solid angle, Omega
        // everywhere for the exact uniform one; its relative spread is the
        // Lambertian estimate's relative error per sample before the
        // receiver cosine's. K = 8 cells (measured: 0 centred, 0.012
        // inside, 0.05-0.075 with F outside, 0.24 just inside the rim (a
        // narrow dip of G); with equidistant nodes also outside 0.075-0.081,
        // at K = 16 0.003-0.09).
        const double cv = std::sqrt(std::max(0.0, m.w2 - m.omega * m.omega)) / m.omega;
        std::printf("cx %5.2f cy %5.2f h %4.2f a %.2f b %.2f: Omega %.6g (error %.2g), area error %.2g, "
                    "weight's relative spread %.4f\n",
                    e.cx, e.cy, e.h, e.a, e.b, omega, omega1 / omega - 1, m.area / area - 1, cv);
        EXPECT_LT(cv, e.cx == 0.49 ? 0.3 : 0.1) << e.cx << " " << e.cy << " h " << e.h;
    }
}

TEST(DiskMc, SolidAngleSamplerIsUniformInSolidAngle)
{
    // A histogram over directions: the disk centred above the receiver
    // split into 8 sectors about its centre x 4 rings of equal area; each
    // cell's solid angle is the integral of 1 over it, so the weighted
    // count E[w 1_cell] equals it. Cells' solid angles by the midpoint rule
    // on a fine polar grid of the cell (h 0.3, radius 0.5: smooth integrand
    // h / r^3; 400 x 400 nodes per cell, relative error < 1e-6).
    const Ellipse e{0.2, -0.1, 0.3, 0.5, 0.5};
    f64::lb_mc_sphdisk q;
    f64::lb_mc_sphdisk_setup(e.cx, e.cy, e.h, e.a, e.b, &q);
    const int ns = 8, nr = 4, g = 1024;
    double got[ns][nr] = {}, want[ns][nr] = {};
    auto cell = [&](double x, double y, int* is, int* ir) {
        double dx = x - e.cx, dy = y - e.cy;
        double phi = std::atan2(dy, dx) + M_PI;
        *is = std::min(ns - 1, int(phi / (2 * M_PI) * ns));
        *ir = std::min(nr - 1, int((dx * dx + dy * dy) / (e.a * e.a) * nr));
    };
    for (int i = 0; i < g; ++i)
        for (int j = 0; j < g; ++j) {
            double x, y;
            double w = f64::lb_mc_sphdisk_sample(&q, (i + 0.5) / g, (j + 0.5) / g, &x, &y);
            int is, ir;
            cell(x, y, &is, &ir);
            got[is][ir] += w / (double(g) * g);
        }
    const int m = 400;
    for (int is = 0; is < ns; ++is)
        for (int ir = 0; ir < nr; ++ir)
            for (int a = 0; a < m; ++a)
                for (int b = 0; b < m; ++b) {
                    // polar about the disk's centre, rho^2 uniform in the ring
                    double phi = 2 * M_PI * (is + (a + 0.5) / m) / ns - M_PI;
                    double rho2 = e.a * e.a * (ir + (b + 0.5) / m) / nr;
                    double x = e.cx + std::sqrt(rho2) * std::cos(phi), y = e.cy + std::sqrt(rho2) * std::sin(phi);
                    double r2 = x * x + y * y + e.h * e.h;
                    // dA = pi a^2 / (ns nr) per cell, split over m^2 nodes
                    want[is][ir] += e.h / (r2 * std::sqrt(r2)) * M_PI * e.a * e.a / (ns * nr) / (m * m);
                }
    double worst = 0;
    for (int is = 0; is < ns; ++is)
        for (int ir = 0; ir < nr; ++ir) worst = std::max(worst, std::fabs(got[is][ir] / want[is][ir] - 1));
    std::printf("weighted histogram over 32 cells: worst relative error %.3g\n", worst);
    // The sampled points' count in a cell is a midpoint rule over a
    // region with a curved boundary in [0,1)^2: O(1/g) per cell (~1e-3 at
    // g = 1024; measured 1.5e-3); a density off by the table's error (1e-2
    // and more) fails.
    EXPECT_LT(worst, 3e-3);
}

}  // namespace
}  // namespace lb
