// The straight-line form of the specular scene's light-sampled MC
// (kernels/common/smc_lanes.inc, -DLB_SMC_RECT) against the general kernel,
// pixel by pixel: the sums in the light's frame, the view frame and the GGX
// BRDF per lane.
#include "methods/render.h"
#include "methods/render_helpers.h"
#include "specular/lanes_helpers.h"
#include "photometry/synth.h"
#include "testutil.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace lb {
namespace {

using methods::Precision;
using test::specular;
using test::worstRel;

// Bounds, per pixel relative with a floor of 1e-6 of the image's peak (pixels
// that see the light only at grazing angles). Double: 1e-12 (the same sums in
// the light's frame instead of the world's: measured below). Float: twice the
// general float kernel's own error against double, at least 1e-5.
TEST(SmcLanes, StraightLineFormEqualsGeneral)
{
    LB_REQUIRE_RUNTIME(rt);
    auto t = photometry::synth("batwing");
    for (const char* spec : {"mc:n=16", "mc:n=7,pattern=halton"})
        test::expectStraightLineEqualsGeneral(*rt, t, spec, "-DLB_SMC_RECT", {1e-12, 1e-6, 1e-6});
}

// The rule: the straight-line form for sampling=light only.
TEST(SmcLanes, RuleAppliesToLightSamplingOnly)
{
    auto t = photometry::synth("batwing");
    Scene s = specular(1.1, 3 * M_PI / 4, 0.25);
    auto has = [&](const std::string& spec) {
        return test::planDefines(methods::parseSpec(spec, SceneKind::Specular), s, t).find("-DLB_SMC_RECT") !=
            std::string::npos;
    };
    EXPECT_TRUE(has("mc:n=8"));
    EXPECT_FALSE(has("mc:n=8,specialize=none"));
    EXPECT_FALSE(has("mc:n=8,sampling=vndf"));
    EXPECT_FALSE(has("mc:n=8,sampling=mis"));
}

}  // namespace
}  // namespace lb
