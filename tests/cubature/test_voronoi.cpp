// Voronoi-cell weights of thesis 5.1 (kernels/common/voronoi.h).
#include "math/kmath.h"

#include <gtest/gtest.h>

#include <random>

namespace {
using namespace lb::f64;

// With p at the barycentre of a unit square the cells are closed forms: the
// centre's cell is the diamond |x| + |y| <= 1/2 (area 1/2), shared by the
// two coincident samples (1/4 each), each corner 1/8.
TEST(Voronoi, CentreOfSquareClosedForm)
{
    real f[LB_VOR_SITES];
    lb_voronoi_fractions(real2(0, 0), 1, 1, f);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(f[i], 0.125, 1e-14);
    EXPECT_NEAR(f[4], 0.25, 1e-14);
    EXPECT_NEAR(f[5], 0.25, 1e-14);
}

// p on corner 0 of a 2 x 1 light: the corner's cell is its quadrant box
// [-1, 0] x [-0.5, 0] (area 1/2) less the trapezoid beyond the bisector with
// the centre, x + y/2 > -5/8 (widths 5/8 at y = 0 and 3/8 at y = -1/2: area
// 1/4), so 1/4 of the light's 2: fraction 1/8, shared with p: 1/16 each.
// And mirrored positions of p give mirrored weights.
TEST(Voronoi, SymmetryAndSharing)
{
    real f[LB_VOR_SITES], g[LB_VOR_SITES];
    lb_voronoi_fractions(real2(-1, -0.5), 2, 1, f);
    EXPECT_NEAR(f[0], 1.0 / 16, 1e-14);
    EXPECT_NEAR(f[5], 1.0 / 16, 1e-14);
    std::mt19937 r(3);
    std::uniform_real_distribution<double> U(-1, 1);
    for (int it = 0; it < 200; ++it) {
        real2 p(U(r), 0.5 * U(r));
        lb_voronoi_fractions(p, 2, 1, f);
        lb_voronoi_fractions(real2(-p.x, p.y), 2, 1, g); // mirror at x = 0: corners 0<->1, 2<->3
        EXPECT_NEAR(f[0], g[1], 1e-12);
        EXPECT_NEAR(f[3], g[2], 1e-12);
        EXPECT_NEAR(f[4], g[4], 1e-12);
        EXPECT_NEAR(f[5], g[5], 1e-12);
    }
}

// The cells partition the light: fractions sum to 1, none negative, for p
// anywhere on it (interior, edges, corners, near the barycentre).
TEST(Voronoi, FractionsPartitionTheLight)
{
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 40; ++j) {
            real2 p(-0.5 + i / 40.0, -0.75 + 1.5 * j / 40.0);
            real f[LB_VOR_SITES];
            lb_voronoi_fractions(p, 1, 1.5, f);
            double sum = 0;
            for (double x : f) {
                EXPECT_GE(x, 0);
                sum += x;
            }
            // exact partition up to rounding of the clipped areas
            EXPECT_NEAR(sum, 1, 1e-12) << p.x << " " << p.y;
        }
}

} // namespace
