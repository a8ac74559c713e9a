// Closed-form checks of kernels/common/spherical.h, in float and double.
#include "math/kmath.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

// Solid angle of an a x b rectangle seen from distance d on its central axis.
double rectSolidAngle(double a, double b, double d)
{
    return 4.0 * std::asin(a * b / std::sqrt((a * a + 4 * d * d) * (b * b + 4 * d * d)));
}

// Form factor from a differential area to a parallel X*c x Y*c rectangle whose
// corner lies on the normal at distance c (Howell's catalogue, C-12).
double cornerFormFactor(double X, double Y)
{
    double a = std::sqrt(1 + X * X), b = std::sqrt(1 + Y * Y);
    return 1.0 / (2 * kPi) * (X / a * std::atan(Y / a) + Y / b * std::atan(X / b));
}

template <class NS, class V>
std::vector<V> rect(double cx, double cy, double a, double b, double d)
{
    using T = typename V::value_type;
    return {V(T(cx - a / 2), T(cy - b / 2), T(d)), V(T(cx + a / 2), T(cy - b / 2), T(d)),
            V(T(cx + a / 2), T(cy + b / 2), T(d)), V(T(cx - a / 2), T(cy + b / 2), T(d))};
}

TEST(Spherical, OctantIsPiOverTwo)
{
    using namespace lb::f64;
    EXPECT_NEAR(lb_tri_solid_angle(real3(1, 0, 0), real3(0, 1, 0), real3(0, 0, 1)), kPi / 2, 1e-15);
    // Reversed winding flips the sign; scaling the vectors changes nothing.
    EXPECT_NEAR(lb_tri_solid_angle(real3(0, 1, 0), real3(3, 0, 0), real3(0, 0, 0.2)), -kPi / 2, 1e-15);
}

TEST(Spherical, RectangleSolidAngleDouble)
{
    using namespace lb::f64;
    for (double d : {1e-3, 0.1, 1.0, 10.0, 1000.0}) {
        auto p = rect<void, real3>(0, 0, 1.0, 0.5, d);
        double exact = rectSolidAngle(1.0, 0.5, d);
        // 1e-12 relative: a handful of double operations on O(1) numbers.
        EXPECT_NEAR(lb_polygon_solid_angle(p.data(), 4), exact, 1e-12 * exact) << "d=" << d;
    }
}

TEST(Spherical, RectangleSolidAngleFloat)
{
    using namespace lb::f32;
    for (double d : {1e-2, 0.1, 1.0, 10.0, 100.0}) {
        auto p = rect<void, real3>(0, 0, 1.0, 0.5, d);
        double exact = rectSolidAngle(1.0, 0.5, d);
        // 2e-5 relative: float epsilon 6e-8 times the ~1/(solid angle) condition
        // of the atan2 form, which loses about 2 digits at d = 100.
        EXPECT_NEAR(lb_polygon_solid_angle(p.data(), 4), exact, 2e-5 * exact) << "d=" << d;
    }
}

TEST(Spherical, DegenerateTriangleConvergesToZero)
{
    using namespace lb::f32;
    real3 a(0.3f, 0.2f, 1.0f), b(-0.4f, 0.1f, 1.0f);
    // Two equal vertices: a . (a x b) is zero up to float rounding of O(1) terms.
    EXPECT_NEAR(lb_tri_solid_angle(a, a, b), 0.0f, 1e-7f);
    // A sliver whose third vertex approaches the edge: area falls linearly.
    for (float eps : {1e-2f, 1e-4f, 1e-6f}) {
        real3 c = 0.5f * (a + b) + real3(0, eps, 0);
        float s = std::fabs(lb_tri_solid_angle(a, b, c));
        EXPECT_LT(s, 1.0f * eps) << eps;
        EXPECT_TRUE(std::isfinite(s));
    }
}

TEST(Spherical, LambertParallelRectangleMatchesFormFactor)
{
    // Unit radiance: E = pi * F.  Corner of the rectangle above the receiver.
    for (double c : {0.01, 0.3, 1.0, 5.0}) {
        double X = 0.7 / c, Y = 1.3 / c;
        double exact = kPi * cornerFormFactor(X, Y);
        {
            using namespace lb::f64;
            auto p = rect<void, real3>(0.35, 0.65, 0.7, 1.3, c);
            EXPECT_NEAR(lb_polygon_irradiance_lambert(p.data(), 4, real3(0, 0, 1)), exact, 1e-12 * exact) << c;
        }
        {
            using namespace lb::f32;
            auto p = rect<void, real3>(0.35, 0.65, 0.7, 1.3, c);
            // 1e-5 relative: float rounding in a sum of four O(1) terms.
            EXPECT_NEAR(lb_polygon_irradiance_lambert(p.data(), 4, real3(0, 0, 1)), exact, 1e-5 * exact) << c;
        }
    }
}

TEST(Spherical, LambertHugePolygonApproachesPi)
{
    using namespace lb::f64;
    auto p = rect<void, real3>(0, 0, 2e6, 2e6, 1.0);
    // The whole hemisphere but a sliver of 1e-6 rad at the horizon: E = pi (1 - O(1e-6)).
    EXPECT_NEAR(lb_polygon_irradiance_lambert(p.data(), 4, real3(0, 0, 1)), kPi, 1e-5);
}

TEST(Spherical, LambertTiltedMatchesQuadrature)
{
    // A rectangle tilted by 60 degrees, away from the normal: compare with a
    // 200 x 200 Gauss-free midpoint integration of cos cos' / (pi r^2), whose
    // error for this smooth integrand is ~1e-6 relative.
    using namespace lb::f64;
    real3 c(0.4, -0.2, 1.5), u(1, 0, 0), v(0, std::cos(kPi / 3), std::sin(kPi / 3));
    real3 nl = normalize(cross(u, v));
    double W = 0.8, L = 0.6;
    std::vector<real3> p = {c - 0.5 * W * u - 0.5 * L * v, c + 0.5 * W * u - 0.5 * L * v, c + 0.5 * W * u + 0.5 * L * v,
                            c - 0.5 * W * u + 0.5 * L * v};
    double E = lb_polygon_irradiance_lambert(p.data(), 4, real3(0, 0, 1));
    int n = 200;
    double s = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            real3 y = c + ((i + 0.5) / n - 0.5) * W * u + ((j + 0.5) / n - 0.5) * L * v;
            double r2 = dot(y, y);
            real3 w = y / std::sqrt(r2);
            s += w.z * std::fabs(dot(w, nl)) / r2;
        }
    s *= W * L / (n * n);
    EXPECT_NEAR(E, s, 1e-5 * s);
}

}  // namespace

namespace {

// lb_atan2_poly (cubature_lanes.inc) in float against std::atan2 in double:
// every octant, the axes, tiny and huge ratios, both signs. Cephes quotes
// ~2 ulp for its atanf polynomial; the reduction adds one division and one
// addition of pi/4, pi/2 or pi. Bound: 2.5e-7 relative or 1.5e-7 absolute
// (whichever is larger: near the octant boundaries pi/2 - a and pi - a cancel).
TEST(Spherical, Atan2PolyFloat)
{
    double worstRel = 0, worstAbs = 0;
    auto check = [&](float y, float x) {
        double a = lb::f32::lb_atan2_poly(y, x);
        double e = std::atan2(double(y), double(x));
        double err = std::fabs(a - e);
        ASSERT_LE(err, std::max(2.5e-7 * std::fabs(e), 1.5e-7)) << y << ", " << x;
        if (e != 0) worstRel = std::max(worstRel, err / std::fabs(e));
        worstAbs = std::max(worstAbs, err);
    };
    for (int i = 0; i <= 20000; ++i) {
        double t = 2 * kPi * i / 20000;
        for (double r : {1e-30, 1e-3, 1.0, 7.5, 1e20}) check(float(r * std::sin(t)), float(r * std::cos(t)));
    }
    for (float s : {1e-8f, 1e-4f, 0.4142135f, 0.41421357f, 1.0f, 2.4142137f, 1e4f, 1e8f})
        for (float sy : {-1.0f, 1.0f})
            for (float sx : {-1.0f, 1.0f}) check(sy * s, sx * 1.0f);
    check(0.0f, 1.0f);
    check(1.0f, 0.0f);
    check(0.0f, -1.0f);
    check(-1.0f, 0.0f);
    EXPECT_EQ(lb::f32::lb_atan2_poly(0.0f, 0.0f), 0.0f);
    // double kernels call atan2 itself
    EXPECT_EQ(lb::f64::lb_atan2_poly(0.3, -0.7), std::atan2(0.3, -0.7));
    std::printf("lb_atan2_poly float: worst %.3g relative, %.3g absolute\n", worstRel, worstAbs);
}

}  // namespace
