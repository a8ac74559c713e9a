// Regressions of the fixes lumibench stability led to, on the host through
// kmath.h (the kernels compile the same headers).
#include "math/kmath.h"
#include "stability/stability.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

// Solid angle of a 1 mm square 1 m away, off axis and tilted, in float
// against double. Before the fix the Van Oosterom determinant a . (b x c)
// cancelled to a relative error ~ eps (d/s)^2 = 6e-8 * 1e6 ~ 0.06 (the tiny
// and far-field float failures, 2.3 % in the stability run). Now the only
// error left is the rounding of the float vertices themselves, relative
// eps d / s ~ 6e-5 of the shape: 1e-3 leaves a margin of 15 and still fails
// the old form by a factor of 20+.
TEST(StabilityFixes, TinyFarSolidAngleInFloat)
{
    const double s = 1e-3;
    glm::dvec3 c(0.3, 0.2, 1.0), u = glm::normalize(glm::dvec3(1, 0.2, 0.1));
    glm::dvec3 v = glm::normalize(glm::cross(glm::dvec3(0.1, -0.3, 1), u));
    glm::dvec3 pd[4] = {c - u * (s / 2) - v * (s / 2), c + u * (s / 2) - v * (s / 2), c + u * (s / 2) + v * (s / 2),
                        c - u * (s / 2) + v * (s / 2)};
    glm::vec3 pf[4];
    for (int k = 0; k < 4; ++k) pf[k] = glm::vec3(pd[k]);
    // Double from the float vertices, so that only the arithmetic differs.
    glm::dvec3 pfd[4];
    for (int k = 0; k < 4; ++k) pfd[k] = glm::dvec3(pf[k]);
    double ref = lb::f64::lb_polygon_solid_angle(pfd, 4);
    double got = lb::f32::lb_polygon_solid_angle(pf, 4);
    ASSERT_GT(ref, 0);
    // Closed form of the small-light limit: s^2 cos(theta) / d^2 (to (s/d)^2).
    double d = glm::length(c);
    EXPECT_NEAR(ref, s * s * std::fabs(glm::dot(glm::cross(u, v), c)) / (d * d * d), 1e-5 * ref);
    EXPECT_NEAR(got, ref, 1e-3 * ref);
}

// Receiver point exactly in the light's plane, luminaire emitting at gamma = 90
// (diffuse: 0.55 + 0.45 cos): L_e = I / (A |n_L . d|) was I / 0 = inf, and the
// estimators' Omega_L * L_e = 0 * inf = NaN. Now an exactly in-plane
// direction has radiance 0 (finite), the product with the (zero) solid angle
// of the in-plane light is 0, and a direction just off the plane keeps its
// (large, finite) radiance I / (A |n_L . d|).
template <class T, class V, class Fns>
void inPlane(Fns fns)
{
    auto table = lb::stability::luminaire("diffuse");
    auto lum = table.packed();
    typename Fns::lb_light L;
    L.c = V(0, 0, 1);
    L.u = V(1, 0, 0);
    L.n = V(0, 1, 0);
    L.v = glm::cross(L.u, L.n);  // (0, 0, 1): the light spans z in [0.5, 1.5] in the plane y = 0
    L.w = 1;
    L.l = 1;
    V p[LB_MAXV];
    fns.corners(L, p);  // relative to the receiver point at the origin, also in y = 0
    V cen = L.c;
    T le = fns.radiance(lum.data(), L, cen);
    EXPECT_EQ(le, T(0));
    // 1e-6 off the plane: I(gamma ~ 90) = 0.55 I0 of diffuse over A |n_L . d|.
    V off = cen + V(0, 1e-6, 0);
    T le2 = fns.radiance(lum.data(), L, off);
    double expect = table.intensity(90, 90) / (1e-6 / glm::length(glm::dvec3(off)));
    EXPECT_NEAR(le2, expect, 1e-3 * expect);  // float: direction and lookup to ~1e-6, margin 1000
    T omega = fns.omega(p, 4);
    EXPECT_EQ(omega, T(0));
    EXPECT_EQ(omega * le, T(0));
}

struct F32 {
    using lb_light = lb::f32::lb_light;
    void corners(lb_light L, glm::vec3* p) { lb::f32::lb_light_corners(L, p); }
    float radiance(const float* lum, lb_light L, glm::vec3 p) { return lb::f32::lb_radiance_from(lum, L, p); }
    float omega(const glm::vec3* p, int n) { return lb::f32::lb_polygon_solid_angle(p, n); }
};
struct F64 {
    using lb_light = lb::f64::lb_light;
    void corners(lb_light L, glm::dvec3* p) { lb::f64::lb_light_corners(L, p); }
    double radiance(const float* lum, lb_light L, glm::dvec3 p) { return lb::f64::lb_radiance_from(lum, L, p); }
    double omega(const glm::dvec3* p, int n) { return lb::f64::lb_polygon_solid_angle(p, n); }
};

TEST(StabilityFixes, InPlaneRadianceIsFinite)
{
    inPlane<float, glm::vec3>(F32{});
    inPlane<double, glm::dvec3>(F64{});
}

}  // namespace

namespace {

// Lambert/Baum irradiance of a 1 mm square 1.3 m away in float against double
// (both from the same float vertices). The plain edge sum cancelled to a
// relative error ~ eps (d/s)^2 ~ 0.1 (5 % seen: cubature normalize=formfactor,
// case `tiny`); the split form is accurate to ~ eps d/s ~ 1e-4: bound 2e-3.
// The small-light closed form s^2 cos_x cos_L / d^2 checks the double value.
TEST(StabilityFixes, TinyFarLambertIrradianceInFloat)
{
    const double s = 1e-3;
    glm::dvec3 c(0.4, -0.3, 1.2), u(1, 0, 0), v = glm::normalize(glm::dvec3(0, 1, 0.4));
    glm::dvec3 pd[4] = {c - u * (s / 2) - v * (s / 2), c + u * (s / 2) - v * (s / 2), c + u * (s / 2) + v * (s / 2),
                        c - u * (s / 2) + v * (s / 2)};
    glm::vec3 pf[4];
    glm::dvec3 pfd[4];
    for (int k = 0; k < 4; ++k) {
        pf[k] = glm::vec3(pd[k]);
        pfd[k] = glm::dvec3(pf[k]);
    }
    double ref = lb::f64::lb_polygon_irradiance_lambert(pfd, 4, glm::dvec3(0, 0, 1));
    double d = glm::length(c);
    glm::dvec3 nL = glm::normalize(glm::cross(u, v));
    double approx = s * s * (c.z / d) * std::fabs(glm::dot(nL, c) / d) / (d * d);
    // Small-light limit: O((s/d)^2) ~ 1e-6 relative, but the vertices are
    // rounded to float (6e-8 on a 1e-3 side: up to ~1e-4 of the area): 3e-4.
    EXPECT_NEAR(ref, approx, 3e-4 * approx);
    double got = lb::f32::lb_polygon_irradiance_lambert(pf, 4, glm::vec3(0, 0, 1));
    EXPECT_NEAR(got, ref, 2e-3 * ref);
}

}  // namespace
