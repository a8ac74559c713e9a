// The area form of the cubature (kernels/common/cubature_lanes.inc
// lb_area_gauss_rect, lb_area_weight) and the `robust` method built on it.
#include "methods/analytic.h"
#include "methods/closed_form.h"
#include "methods/registry.h"
#include "methods/render_helpers.h"
#include "testutil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace lb {
namespace {

using methods::Precision;

// Worst relative error of `spec` against the closed form of a Lambertian
// light (I = 1000 cos(gamma)) over every pixel of sc.
double worstAgainstLambert(ocl::Runtime& rt, const photometry::Table& t, const Scene& sc, const std::string& spec,
                           Precision p)
{
    auto img = test::run(rt, t, sc, spec, p).image;
    double worst = 0;
    for (int row = 0; row < sc.res; ++row)
        for (int col = 0; col < sc.res; ++col) {
            double e = test::cosnIrradiance(sc, 1, 1000.0, sc.pixel(row, col));
            worst = std::max(worst, std::fabs(img.px[row * sc.res + col] / e - 1));
        }
    return worst;
}

// The n x n Gauss-Legendre rule of the area form against the closed form,
// under a horizontal 1 m light (R = pi) at z = 1.1 and 2.2 m (h = 0.6, 1.7),
// 9 x 9 pixels over 1 m: the rule alone (area_q = 0.1: the cubature only
// within 5 cm of the light; area_sin = 0).
//
// Bound, derived: the Lambertian integrand is D (n_x . p) / r^4 = D^2 /
// (rho^2 + a^2 + b^2)^2 under the light, whose 2m-th a-derivative at 0 is
// (2m)! (m + 1) / rho^(2m + 4). The n-point rule's error on a side of length
// a, relative to the integral, is then (a/rho)^(2n) (n!)^4 (n + 1) / ((2n + 1)
// ((2n)!)^2): 1/60 (a/rho)^4 for n = 2, 1/700 (a/rho)^6 for n = 3; the two
// axes add (leading order), largest under the light's centre (rho = z). So
// 2 x, with the table's own interpolation (0.5-degree cos table, exact
// bilinear lookup: <= 1e-5) on top; and halving 1/z must shrink the 2 x 2
// rule's error by 2^4 = 16 (here >= 10: the next term is (a/z)^2 smaller).
TEST(AreaForm, GaussRulesMeetTheirDerivedBoundsAndOrder)
{
    LB_REQUIRE_RUNTIME(rt);
    const Precision p = rt->fp64() ? Precision::Double : Precision::Float;
    const double floor = p == Precision::Double ? 1e-5 : 3e-5;  // table (and float rounding)
    auto t = methods::loadLuminaire("analytic:cos1");
    double e2[2], e3[2];
    const double zs[2] = {1.1, 2.2};
    for (int k = 0; k < 2; ++k) {
        Scene sc = test::scene(zs[k] - 0.5, M_PI, 9);
        sc.extent = 1.0;
        e2[k] = worstAgainstLambert(*rt, t, sc, "cubature:area=gauss2,area_q=0.1,area_sin=0,lookup=exact", p);
        e3[k] = worstAgainstLambert(*rt, t, sc, "cubature:area=gauss3,area_q=0.1,area_sin=0,lookup=exact", p);
        double q = 1.0 / zs[k];
        std::printf("[ area form ] z = %g: gauss2 %.3g (bound %.3g), gauss3 %.3g (bound %.3g)\n", zs[k], e2[k],
                    2 * std::pow(q, 4) / 60 + floor, e3[k], 2 * std::pow(q, 6) / 700 + floor);
        EXPECT_LE(e2[k], 2 * std::pow(q, 4) / 60 + floor) << "z = " << zs[k];
        EXPECT_LE(e3[k], 2 * std::pow(q, 6) / 700 + floor) << "z = " << zs[k];
    }
    EXPECT_GE(e2[0] / e2[1], 10.0);
    EXPECT_LT(e3[0], e2[0] / 5);  // the higher order pays at a/z = 0.9 already
}

// In the light's own plane (a pixel row exactly at y = 0 of a vertical light,
// R = pi/2) the solid-angle form has L_e = I / (A cos) = I / 0; the area form
// is regular: with the area rule alone there (area_sin > 0) every pixel is
// finite, the row in the plane is lit by a gamma-90 emitter, and it is within
// the rule's bound of the reference.
TEST(AreaForm, LightsTheLightsOwnPlane)
{
    LB_REQUIRE_RUNTIME(rt);
    auto t = methods::loadLuminaire("diffuse");  // 0.55 + 0.45 cos(gamma): emits at gamma 90
    Scene sc = test::scene(1.0, M_PI / 2, 15);  // odd: row 7 lies at y = 0
    auto ref = test::run(*rt, t, sc, "reference", Precision::Float).image;
    auto img = test::run(*rt, t, sc, "robust", Precision::Float).image;
    double worst = 0;
    for (int col = 0; col < sc.res; ++col) {
        double r = ref.px[7 * sc.res + col], e = img.px[7 * sc.res + col];
        ASSERT_TRUE(std::isfinite(e));
        ASSERT_GT(r, 0);
        worst = std::max(worst, std::fabs(e / r - 1));
    }
    // rho >= 1 m from a 1 m light: robust's 3 x 3 rule's bound 2/700
    // (a/rho)^6 (above) is 0.29 %; the reference's own tolerance (1e-3) on top.
    std::printf("[ area form ] in the light's plane: worst %.3g\n", worst);
    EXPECT_LT(worst, 2.0 / 700 + 1e-3);
}

// robust is the cubature family with other defaults: the same parameters, its
// own name in records, the area form on.
TEST(Robust, IsTheCubatureWithTheAreaFormOn)
{
    const auto& r = methods::family("robust");
    const auto& c = methods::family("cubature");
    ASSERT_EQ(r.params.size(), c.params.size());
    EXPECT_EQ(r.file, c.file);
    auto s = methods::parseSpec("robust");
    EXPECT_NE(s.str("area"), "none");
    EXPECT_EQ(methods::parseSpec("robust:area_q=2").num("area_q"), 2.0);
    EXPECT_EQ(methods::parseSpec("cubature").str("area"), "none");
}

}  // namespace
}  // namespace lb
