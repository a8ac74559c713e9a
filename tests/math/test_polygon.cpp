// Clipping and closest point of kernels/common/polygon.h.
#include "math/kmath.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {
using namespace lb::f64;

void unitSquare(real3* p)
{
    p[0] = real3(0, 0, 0);
    p[1] = real3(1, 0, 0);
    p[2] = real3(1, 1, 0);
    p[3] = real3(0, 1, 0);
}

double area(const real3* p, int n) { return length(lb_polygon_vector_area(p, n)); }

TEST(Polygon, ClipKeepsHalfOfSquare)
{
    real3 p[LB_MAXV];
    unitSquare(p);
    int n = lb_clip_polygon(p, 4, real3(1, 0, 0), 0.5);
    EXPECT_EQ(n, 4);
    EXPECT_NEAR(area(p, n), 0.5, 1e-15);
    for (int i = 0; i < n; ++i) EXPECT_GE(p[i].x, 0.5);
}

TEST(Polygon, ClipDiagonalMakesTriangleOrPentagon)
{
    real3 p[LB_MAXV];
    unitSquare(p);
    // Keep x + y >= 1.5: a corner triangle of area 1/8.
    int n = lb_clip_polygon(p, 4, real3(1, 1, 0), 1.5);
    EXPECT_EQ(n, 3);
    EXPECT_NEAR(area(p, n), 0.125, 1e-15);
    unitSquare(p);
    n = lb_clip_polygon(p, 4, real3(-1, -1, 0), -1.5);  // the complement
    EXPECT_EQ(n, 5);
    EXPECT_NEAR(area(p, n), 0.875, 1e-15);
}

TEST(Polygon, ClipAllOrNothing)
{
    real3 p[LB_MAXV];
    unitSquare(p);
    EXPECT_EQ(lb_clip_polygon(p, 4, real3(0, 0, 1), -1.0), 4);  // everything kept
    EXPECT_EQ(lb_clip_polygon(p, 4, real3(0, 0, 1), 1.0), 0);  // nothing kept
}

TEST(Polygon, ClipThroughVerticesMakesNoDuplicates)
{
    real3 p[LB_MAXV];
    unitSquare(p);
    // The plane x = y passes through corners 0 and 2: a triangle, no repeated vertex.
    int n = lb_clip_polygon(p, 4, normalize(real3(1, -1, 0)), 0.0);
    ASSERT_EQ(n, 3);
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) EXPECT_GT(length(p[i] - p[j]), 0.5);
    EXPECT_NEAR(area(p, n), 0.5, 1e-15);
}

TEST(Polygon, ClosestPointThreeCases)
{
    real3 p[LB_MAXV];
    unitSquare(p);
    int where = -1;
    real3 n(0, 0, 1);
    real3 c = lb_closest_point_polygon(p, 4, n, real3(0.3, 0.6, 2.0), &where);
    EXPECT_EQ(where, 0);
    EXPECT_NEAR(length(c - real3(0.3, 0.6, 0)), 0, 1e-15);
    c = lb_closest_point_polygon(p, 4, n, real3(1.7, 0.25, -1.0), &where);
    EXPECT_EQ(where, 1);
    EXPECT_NEAR(length(c - real3(1, 0.25, 0)), 0, 1e-15);
    c = lb_closest_point_polygon(p, 4, n, real3(-0.5, 1.5, 0.3), &where);
    EXPECT_EQ(where, 2);
    EXPECT_NEAR(length(c - real3(0, 1, 0)), 0, 1e-15);
    // Reversed winding: same answers.
    real3 q[4] = {p[3], p[2], p[1], p[0]};
    c = lb_closest_point_polygon(q, 4, n, real3(0.3, 0.6, 2.0), &where);
    EXPECT_EQ(where, 0);
    c = lb_closest_point_polygon(q, 4, n, real3(1.7, 0.25, -1.0), &where);
    EXPECT_EQ(where, 1);
}

TEST(Polygon, ClosestPointIsClosestOverDenseSamples)
{
    // Brute force: no point of a dense grid on the clipped polygon is closer.
    real3 p[LB_MAXV];
    unitSquare(p);
    int n = lb_clip_polygon(p, 4, real3(1, 1, 0), 0.7);
    for (double qx : {-0.5, 0.2, 0.9, 1.4})
        for (double qy : {-0.3, 0.1, 0.8, 1.6}) {
            real3 q(qx, qy, 0.4);
            int where;
            real3 c = lb_closest_point_polygon(p, n, real3(0, 0, 1), q, &where);
            double best = 1e30;
            for (int i = 0; i <= 200; ++i)
                for (int j = 0; j <= 200; ++j) {
                    real3 y(i / 200.0, j / 200.0, 0);
                    if (y.x + y.y >= 0.7) best = std::fmin(best, length(y - q));
                }
            EXPECT_LE(length(c - q), best + 1e-12);
            EXPECT_GE(length(c - q), best - 0.01);  // the grid's spacing bounds the gap
        }
}

}  // namespace

namespace {

// Float: the corner-vs-edge decision is made by tests linear in the target,
// so a target 2 m outside edge x = 1 whose projection is 1e-4 before the
// corner (1, 1) gives the edge point, case 1. Comparing squared distances
// cannot: edge 4, corner 4 + 1e-8, and ulp(4) = 4.8e-7 in float. The edge
// point is exact to the float rounding of the inputs (1e-4 carries 4e-12
// relative error in its representation, |q| = 3: a few ulp, 1e-6).
TEST(Polygon, ClosestPointCornerVersusEdgeInFloat)
{
    namespace F = lb::f32;
    F::real3 p[LB_MAXV] = {F::real3(0, 0, 0), F::real3(1, 0, 0), F::real3(1, 1, 0), F::real3(0, 1, 0)};
    for (float s : {1.0f - 1e-4f, 1.0f - 1e-3f, 0.5f, 1e-4f}) {
        int where = -1;
        F::real3 c = F::lb_closest_point_polygon(p, 4, F::real3(0, 0, 1), F::real3(3.0f, s, 0.7f), &where);
        EXPECT_EQ(where, 1) << s;
        EXPECT_NEAR(c.x, 1.0f, 1e-6f) << s;
        EXPECT_NEAR(c.y, s, 1e-6f) << s;
        EXPECT_EQ(c.z, 0.0f);
    }
    // Just past the corner (projection beyond the edge's end): the vertex.
    int where = -1;
    F::real3 c = F::lb_closest_point_polygon(p, 4, F::real3(0, 0, 1), F::real3(3.0f, 1.0f + 1e-4f, 0), &where);
    EXPECT_EQ(where, 2);
    EXPECT_EQ(c, F::real3(1, 1, 0));
    // Far targets (NP of a grazing normal, 1e3 m): still the edge, to 1e3 ulp.
    c = F::lb_closest_point_polygon(p, 4, F::real3(0, 0, 1), F::real3(1e3f, 0.25f, 0), &where);
    EXPECT_EQ(where, 1);
    EXPECT_NEAR(c.y, 0.25f, 1e3f * 1.2e-7f);
}

}  // namespace
