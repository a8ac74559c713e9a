// Dynamic points and centroid of kernels/common/dynamic.h.
#include "math/kmath.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {
using namespace lb::f64;

// A light in the plane z = 1 facing down (n_L = -z), corners relative to the
// receiver at the origin, spanning [x0, x0 + 2] x [-1, 1].
lb_light downLight(double x0, real3* p)
{
    lb_light L;
    L.c = real3(x0 + 1, 0, 1);
    L.u = real3(1, 0, 0);
    L.n = real3(0, 0, -1);
    L.v = cross(L.u, L.n);
    L.w = 2;
    L.l = 2;
    lb_light_corners(L, p);
    return L;
}

TEST(Dynamic, CentroidOfRectangleAndTriangle)
{
    real3 p[LB_MAXV];
    downLight(0, p);
    real3 c = lb_polygon_centroid(p, 4);
    EXPECT_NEAR(c.x, 1, 1e-15);
    EXPECT_NEAR(c.y, 0, 1e-15);
    EXPECT_NEAR(c.z, 1, 1e-15);
    real3 t[3] = {real3(0, 0, 0), real3(3, 0, 0), real3(0, 3, 0)};
    c = lb_polygon_centroid(t, 3);  // (a + b + c) / 3
    EXPECT_NEAR(c.x, 1, 1e-15);
    EXPECT_NEAR(c.y, 1, 1e-15);
}

TEST(Dynamic, NormalPointHitsAndClamps)
{
    real3 p[LB_MAXV];
    // Head-on: the normal ray meets the plane at (0, 0, 1), inside the light.
    lb_light L = downLight(-1, p);
    real3 np = lb_normal_point(p, 4, L.n, real3(0, 0, 1), 0.1);
    EXPECT_NEAR(length(np - real3(0, 0, 1)), 0, 1e-15);
    // Light moved to x in [0.5, 2.5]: the hit (0, 0, 1) is clamped to the
    // nearest edge point (0.5, 0, 1).
    L = downLight(0.5, p);
    np = lb_normal_point(p, 4, L.n, real3(0, 0, 1), 0.1);
    EXPECT_NEAR(length(np - real3(0.5, 0, 1)), 0, 1e-15);
}

TEST(Dynamic, NormalPointSkewsWhenParallel)
{
    // Vertical light in the plane y = 1 facing the receiver (n_L = -y), x in
    // [-1, 1], z in [0, 20]; receiver normal +z is parallel to the plane. The
    // skewed direction (0, skew, 1) / norm meets y = 1 at z = 1 / skew.
    lb_light L;
    L.c = real3(0, 1, 10);
    L.u = real3(1, 0, 0);
    L.n = real3(0, -1, 0);
    L.v = cross(L.u, L.n);  // (0, 0, -1): the length axis is vertical
    L.w = 2;
    L.l = 20;
    real3 p[LB_MAXV];
    lb_light_corners(L, p);
    for (double skew : {0.1, 0.25}) {
        real3 np = lb_normal_point(p, 4, L.n, real3(0, 0, 1), skew);
        EXPECT_NEAR(np.x, 0, 1e-12);
        EXPECT_NEAR(np.y, 1, 1e-12);
        EXPECT_NEAR(np.z, 1 / skew, 1e-12);
    }
}

TEST(Dynamic, MrpBetweenClosestAndNormalPoint)
{
    real3 p[LB_MAXV];
    lb_light L = downLight(-1, p);
    // CP = NP = (0, 0, 1): the MRP is the same point.
    real3 a(0, 0, 1);
    EXPECT_NEAR(length(lb_mrp(p, 4, L.n, a, a) - a), 0, 1e-15);
    // CP (0,0,1) and NP (1,0,1) at 45 degrees: the half-vector meets z = 1 at
    // x = tan(22.5 deg) = sqrt(2) - 1.
    real3 m = lb_mrp(p, 4, L.n, a, real3(1, 0, 1));
    EXPECT_NEAR(m.x, std::sqrt(2.0) - 1, 1e-15);
    EXPECT_NEAR(m.z, 1, 1e-15);
}

TEST(Dynamic, RadianceOfLambertianLightIsConstant)
{
    // I = I0 cos(gamma) on an area A gives L_e = I0 / A in every direction.
    std::vector<float> lum = {2, 3, 0, 360, 0, 90, 180, 100, 0, 0, 100, 0, 0};
    // Bilinear between 0 and 90 degrees is not cos: use directions at gamma = 0.
    real3 p[LB_MAXV];
    lb_light L = downLight(-1, p);
    EXPECT_NEAR(lb_radiance_from(lum.data(), L, real3(0, 0, 1)), 100.0 / 4.0, 1e-12);
}

// The plane shift: a receiver nearer the light's plane than eps moves to eps
// on its side (s = 0 in front), the straight-line forms' height alike.
TEST(Dynamic, PlaneShiftMovesReceiversOffTheLightsPlane)
{
    real3 p[LB_MAXV];
    lb_light L = downLight(0, p);  // plane z = 1, n_L = -z, centre (1, 0, 1)
    const double eps = 1e-3;
    auto shifted = [&](double z) { return lb_plane_shift(L, real3(0.3, 0.2, z), eps); };
    // s = n_L . (x - c) = 1 - z
    EXPECT_DOUBLE_EQ(shifted(1).z, 1 - eps);  // in the plane: s = 0 counts as in front
    EXPECT_DOUBLE_EQ(shifted(1 + 0.5e-3).z, 1 + eps);  // behind: s < 0
    EXPECT_DOUBLE_EQ(shifted(1 - 0.5e-3).z, 1 - eps);
    EXPECT_DOUBLE_EQ(shifted(0.5).z, 0.5);  // farther than eps: unchanged
    EXPECT_DOUBLE_EQ(shifted(1).x, 0.3);  // along n_L only
    // h = n_L . (corner - x) = -s: -eps in front, +eps behind
    EXPECT_DOUBLE_EQ(lb_plane_shift_h(0.0, 0.0, eps), -eps);
    EXPECT_DOUBLE_EQ(lb_plane_shift_h(0.5e-3, -0.5e-3, eps), eps);
    EXPECT_DOUBLE_EQ(lb_plane_shift_h(-0.5, 0.5, eps), -0.5);
    // only on the light (the 2 x 2 box around (1, 0, 1), grown by eps)
    EXPECT_DOUBLE_EQ(lb_plane_shift_on_light(L, real3(0.3, 0.2, 1), eps).z, 1 - eps);
    EXPECT_DOUBLE_EQ(lb_plane_shift_on_light(L, real3(-0.5e-3, 0.2, 1), eps).z, 1 - eps);  // within eps of the edge
    EXPECT_DOUBLE_EQ(lb_plane_shift_on_light(L, real3(-0.3, 0.2, 1), eps).z, 1);  // beside the light: kept
    EXPECT_DOUBLE_EQ(lb_plane_shift_on_light(L, real3(0.3, 1.2, 1), eps).z, 1);
}

}  // namespace
