// The straight-line form of the specular scene's light-sampled MC
// (kernels/common/smc_lanes.inc, -DLB_SMC_RECT) against the general kernel, pixel by pixel: the LTC integral
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

// Bounds, per pixel relative with a floor of 1e-6 of the image's peak (pixels
// that see the light only at grazing angles). Double: 1e-12 (the same sums in
// the light's frame instead of the world's: measured below). Float: twice the
// general float kernel's own error against double, at least 1e-5.
TEST(SmcLanes, StraightLineFormEqualsGeneral)
{
    LB_REQUIRE_RUNTIME(rt);
    const bool fp64 = rt->fp64();
    auto t = photometry::synth("batwing");
    for (const std::string spec : {"mc:n=16", "mc:n=7,pattern=halton"}) {
        const std::string general = spec + ",specialize=none";
        double worstF = 0, worstD = 0;
        for (const Scene& s : scenes()) {
            const std::string what = spec + " " + s.describe();
            ASSERT_NE(methods::family("mc", SceneKind::Specular)
                          .sceneDefines(methods::parseSpec(spec, SceneKind::Specular), s, t)
                          .find("-DLB_SMC_RECT"),
                      std::string::npos)
                << what;
            Precision refP = fp64 ? Precision::Double : Precision::Float;
            Image ref = test::run(*rt, t, s, general, refP).image;
            double bound = 1e-5;
            if (fp64) {
                Image genF = test::run(*rt, t, s, general, Precision::Float).image;
                bound = std::max(bound, 2 * worstRel(ref, genF, 1.0, what + " general float", 1e-6));
                Image d = test::run(*rt, t, s, spec, Precision::Double).image;
                worstD = std::max(worstD, worstRel(ref, d, 1e-12, what + " double", 1e-6));
            }
            for (const char* lanes : {"lanes=1", "lanes=8"}) {
                Image f = test::run(*rt, t, s, spec + "," + lanes, Precision::Float).image;
                worstF = std::max(worstF, worstRel(ref, f, bound, what + " float " + lanes, 1e-6));
            }
            if (HasFailure()) return;
        }
        std::cout << spec << ": straight-line form against the general kernel: float " << worstF << ", double "
                  << worstD << "\n";
    }
}

// The rule: the straight-line form for sampling=light only.
TEST(SmcLanes, RuleAppliesToLightSamplingOnly)
{
    auto t = photometry::synth("batwing");
    const auto& fam = methods::family("mc", SceneKind::Specular);
    Scene s = specular(1.1, 3 * M_PI / 4, 0.25);
    auto has = [&](const std::string& spec) {
        return fam.sceneDefines(methods::parseSpec(spec, SceneKind::Specular), s, t).find("-DLB_SMC_RECT") !=
            std::string::npos;
    };
    EXPECT_TRUE(has("mc:n=8"));
    EXPECT_FALSE(has("mc:n=8,specialize=none"));
    EXPECT_FALSE(has("mc:n=8,sampling=vndf"));
    EXPECT_FALSE(has("mc:n=8,sampling=mis"));
}

}  // namespace
}  // namespace lb
