// The straight-line forms of the specular ltc (kernels/common/ltc_lanes.inc,
// -DLB_LTC_RECT: radiance=point and the cubature's fan) against the general kernel, pixel by pixel: the LTC integral
// with the horizon clip folded into the edge sum, and the view frame and table
// lookup per lane.
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
    auto t = photometry::synth("batwing");
    for (const char* spec : {"ltc:radiance=point", "ltc"})
        test::expectStraightLineEqualsGeneral(*rt, t, spec, "-DLB_LTC_RECT", {1e-10, 1e-4, 1e-5});
}

// The rule: the straight-line form for radiance=point and for the fan (the
// clip along u where the light crosses the floor), each with its own G.
TEST(LtcLanes, RuleAppliesToPointAndFan)
{
    auto t = photometry::synth("batwing");
    Scene s = specular(1.1, 3 * M_PI / 4, 0.25), crossing = specular(-0.2, 5 * M_PI / 8, 0.25);
    auto defines = [&](const std::string& spec, const Scene& sc) {
        return test::planDefines(methods::parseSpec(spec, SceneKind::Specular), sc, t);
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
