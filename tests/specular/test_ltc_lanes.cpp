// The straight-line forms of the specular ltc (kernels/common/ltc_lanes.inc,
// -DLB_LTC_RECT: radiance=point and the cubature's fan) against the general kernel, pixel by pixel: the LTC integral
// with the horizon clip folded into the edge sum, and the view frame and table
// lookup per lane.
#include "methods/render.h"
#include "methods/render_helpers.h"
#include "photometry/synth.h"
#include "testutil.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace lb {
namespace {

using methods::Precision;

Scene specular(double h, double R, double alpha, glm::dvec3 eye = {0, 4, 2})
{
    Scene s = test::scene(h, R, 45);  // odd: a column of pixels on x = 0
    s.kind = SceneKind::Specular;
    s.alpha = alpha;
    s.eye = eye;
    return s;
}

// Worst per-pixel difference of `test` from `ref`, relative to the pixel (floor
// 1e-9 of the image's peak: pixels where the lobe misses the light are 0 in
// both up to rounding); EXPECTs it within `bound`.
double worstRel(const Image& ref, const Image& test, double bound, const std::string& what, double floor = 1e-9)
{
    double peak = 0, worst = 0;
    for (double v : ref.px) peak = std::max(peak, std::fabs(v));
    EXPECT_GT(peak, 0) << what;
    for (size_t i = 0; i < ref.px.size(); ++i) {
        double d = std::fabs(ref.px[i] - test.px[i]) / std::max(std::fabs(ref.px[i]), floor * peak);
        worst = std::max(worst, d);
        EXPECT_LE(d, bound) << what << " pixel " << i << ": " << ref.px[i] << " vs " << test.px[i];
        if (d > bound) break;
    }
    return worst;
}

// Scenes: light close to and far from the floor, every published rotation's
// kind (facing down, tilted, edge-on at R = pi/2), a grazing eye (the lobe
// leans towards the horizon: the transformed quad crosses z = 0), an eye above
// the centre pixel (w_o along n there: lb_view_frame's fallback frame), and
// alpha from narrow to Lambert-like.
std::vector<Scene> scenes()
{
    std::vector<Scene> v;
    for (double alpha : {0.05, 0.25, 1.0}) {
        v.push_back(specular(1.1, 3 * M_PI / 4, alpha));
        v.push_back(specular(0.1, M_PI / 2, alpha));
        v.push_back(specular(2.5, M_PI, alpha));
    }
    v.push_back(specular(0.5, 5 * M_PI / 8, 0.1, {0, 4, 0.05}));
    v.push_back(specular(1.1, 7 * M_PI / 8, 0.5, {0, 0, 3}));
    v.push_back(specular(-0.2, 5 * M_PI / 8, 0.25));  // the light crosses the floor: the fan's clip along u
    v.push_back(specular(0.0, M_PI, 0.25));  // the light lying on the floor: the plane shift
    return v;
}

// Bounds, per pixel relative with a floor: where the lobe misses the light the
// LTC integral is a sum of Lambert terms of the peak's size that cancel to a
// tiny value, so every code carries an absolute error of some ulps of the
// peak there (measured: the general code's own double result moves by up to
// 1e-9 relative at pixels of 1e-10 when the quad's starting vertex changes).
// Double: 1e-10 relative, floor 1e-4 of the peak (measured 2.0e-12: the two
// differ in the order of the sums, the clip's form and the small-polygon
// split's first edge). Float: floor 1e-5 of the peak (some hundred ulps),
// twice the general float kernel's own error against double, at least 1e-5
// (measured worst 6.7e-3 where the general float kernel errs by up to 3.4e-3
// or more: the select-only atan2 errs up to 2.5e-7 relative per edge against
// the library's ~1.2e-7).
TEST(LtcLanes, StraightLineFormEqualsGeneral)
{
    LB_REQUIRE_RUNTIME(rt);
    const bool fp64 = rt->fp64();
    auto t = photometry::synth("batwing");
    for (const std::string spec : {"ltc:radiance=point", "ltc"}) {
        const std::string sep = spec.find(':') == std::string::npos ? ":" : ",";
        const std::string general = spec + sep + "specialize=none";
        double worstF = 0, worstD = 0;
        for (const Scene& s : scenes()) {
            const std::string what = spec + " " + s.describe();
            ASSERT_NE(methods::family("ltc", SceneKind::Specular)
                          .sceneDefines(methods::parseSpec(spec, SceneKind::Specular), s, t)
                          .find("-DLB_LTC_RECT"),
                      std::string::npos)
                << what;
            Precision refP = fp64 ? Precision::Double : Precision::Float;
            Image ref = test::run(*rt, t, s, general, refP).image;
            double bound = 1e-5;
            if (fp64) {
                Image genF = test::run(*rt, t, s, general, Precision::Float).image;
                bound = std::max(bound, 2 * worstRel(ref, genF, 1.0, what + " general float", 1e-5));
                Image d = test::run(*rt, t, s, spec, Precision::Double).image;
                worstD = std::max(worstD, worstRel(ref, d, 1e-10, what + " double", 1e-4));
            }
            for (const char* lanes : {"lanes=1", "lanes=8"}) {
                Image f = test::run(*rt, t, s, spec + sep + lanes, Precision::Float).image;
                worstF = std::max(worstF, worstRel(ref, f, bound, what + " float " + lanes, 1e-5));
            }
            if (HasFailure()) return;
        }
        std::cout << spec << ": straight-line form against the general kernel: float " << worstF << ", double "
                  << worstD << "\n";
    }
}

// The rule: the straight-line form for radiance=point and for the fan (the
// clip along u where the light crosses the floor), each with its own G.
TEST(LtcLanes, RuleAppliesToPointAndFan)
{
    auto t = photometry::synth("batwing");
    const auto& fam = methods::family("ltc", SceneKind::Specular);
    Scene s = specular(1.1, 3 * M_PI / 4, 0.25), crossing = specular(-0.2, 5 * M_PI / 8, 0.25);
    auto defines = [&](const std::string& spec, const Scene& sc) {
        return fam.sceneDefines(methods::parseSpec(spec, SceneKind::Specular), sc, t);
    };
    auto has = [](const std::string& d, const char* what) { return d.find(what) != std::string::npos; };
    EXPECT_TRUE(has(defines("ltc:radiance=point", s), "-DLB_LTC_RECT"));
    EXPECT_TRUE(has(defines("ltc", s), "-DLB_LTC_RECT"));
    EXPECT_FALSE(has(defines("ltc", s), "-DLB_CUB_RECT_CLIP"));
    EXPECT_TRUE(has(defines("ltc", crossing), "-DLB_CUB_RECT_CLIP"));
    EXPECT_FALSE(has(defines("ltc:radiance=point", crossing), "-DLB_CUB_RECT_CLIP"));
    EXPECT_FALSE(has(defines("ltc:radiance=point,specialize=none", s), "-DLB_LTC_RECT"));
    EXPECT_FALSE(has(defines("ltc:radiance=point,g_omega=exact", s), "-DLB_LTC_RECT"));
    EXPECT_FALSE(has(defines("ltc:g_omega=exact", s), "-DLB_LTC_RECT"));
    EXPECT_FALSE(has(defines("ltc:triangulation=delaunay", s), "-DLB_LTC_RECT"));
    EXPECT_FALSE(has(defines("ltc:radiance=structured", s), "-DLB_LTC_RECT"));
}

}  // namespace
}  // namespace lb
