// The straight-line form of mc's extended path (kernels/mc.cl, LB_MC_STRAIGHT:
// eight pixels per work-item in float on PoCL, one in double) renders what the
// general path (specialize=none) renders, for every domain, sequence and
// output it takes.
#include "methods/render.h"
#include "methods/render_helpers.h"
#include "photometry/table.h"
#include "test_tables.h"
#include "testutil.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lb {
namespace {

using methods::Precision;
using test::run;
using test::scene;

using methods::test_tables::lumpy;

// The keys the straight-line form takes (min_solid=0: no pixel sits at the
// switch to area sampling, where the two solid-angle formulas' last bits
// could pick different branches); res 27 leaves a partial last work-item.
const char* kStraightSpecs[] = {
    "mc:n=5,domain=solid,sequence=sobol,min_solid=0",
    "mc:n=3,domain=solid,sequence=random,min_solid=0",
    "mc:n=6,domain=solid,sequence=shared,pattern=halton,shift=1,min_solid=0",
    "mc:n=4,domain=area,sequence=sobol",
    "mc:n=4,domain=area,sequence=random",
    "mc:n=4,domain=area,sequence=shared,pattern=stratified,shift=1",
    "mc:n=4,domain=solid,sequence=sobol,min_solid=0,denoise=atrous",
    "mc:n=3,domain=solid,sequence=zsobol,min_solid=0",
    "mc:n=4,domain=solid,sequence=sobol,cosine_warp=1,min_solid=0",
    "mc:n=4,domain=area,sequence=zsobol",
    "mc:n=5,domain=projected,sequence=sobol",
    "mc:n=3,domain=projected,sequence=random",
    "mc:n=4,domain=projected,sequence=zsobol,denoise=atrous",
    "mc:n=6,domain=mis,sequence=sobol",
    "mc:n=5,domain=mis,sequence=shared,pattern=stratified,shift=1,mis_split=0.4",
};

// The worst relative pixel difference of the straight-line form against the
// general path over the specs and scenes (h, R) at res pixels per side, of
// area and solid angle (first) and of the projected samplers (second, bound
// 10 tol); checks which form each took (lanes: 8 on CPU devices in float,
// else none).
std::pair<double, double> worstAgainstGeneral(ocl::Runtime& rt, Precision p,
                                              std::initializer_list<std::pair<double, double>> scenes, int res,
                                              double tol)
{
    const auto t = lumpy();
    std::pair<double, double> worst{0, 0};
    for (auto [h, R] : scenes)
        for (const char* spec : kStraightSpecs) {
            Scene sc = scene(h, R, res);
            auto gen = run(rt, t, sc, std::string(spec) + ",specialize=none", p);
            auto st = run(rt, t, sc, spec, p);
            const std::string defs = st.stats["defines"].get<std::string>();
            EXPECT_NE(defs.find("LB_MC_STRAIGHT"), std::string::npos) << spec;
            const bool eight = p == Precision::Float && rt.info().type == "CPU";
            EXPECT_EQ(defs.find("LB_LANES=8") != std::string::npos, eight) << spec;
            EXPECT_EQ(gen.stats["defines"].get<std::string>().find("LB_MC_STRAIGHT"), std::string::npos);
            // relative to the pixel, or to 1e-6 of the peak where it is darker
            const bool proj = methods::test_tables::samplesProjected(spec);
            const double d = test::worstRelDiff(gen.image.px, st.image.px, 1e-6, proj ? 10 * tol : tol,
                                                fmt::format("{} h {} R {}", spec, h, R));
            double& w = proj ? worst.second : worst.first;
            w = std::max(w, d);
        }
    return worst;
}

// Float, eight lanes against the general path. The sequences' integers,
// the sampler's set-up and sample and the estimate are the same code
// (common/mc_lanes.inc, the lanes' instances); what differs is the
// compiler's order of the float operations in the two kernels: a few ulp
// per sample. Measured worst 1.1e-6 over the 33 cases of area and solid
// angle (1e-5 is 10x that and far below one sample's noise, ~1e-1), and
// 1.7e-5 over the 15 of projected and mis (at h 0.1 R 3pi/4; bound 1e-4).
TEST(McStraight, EightLanesEqualTheGeneralPathInFloat)
{
    LB_REQUIRE_RUNTIME(rt);
    auto [w, wp] =
        worstAgainstGeneral(*rt, Precision::Float, {{0.1, 3 * M_PI / 4}, {1.1, M_PI / 2}, {0.3, M_PI}}, 27, 1e-5);
    std::printf("straight vs general, float: worst relative pixel difference %.3g, projected %.3g\n", w, wp);
}

// Double runs the one-pixel instance of the same code (the form GPUs take):
// measured within 6.7e-16; 1e-12 allows a compiler's reassociation.
TEST(McStraight, OnePixelFormEqualsTheGeneralPathInDouble)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "no fp64";
    auto [w, wp] = worstAgainstGeneral(*rt, Precision::Double, {{0.1, 3 * M_PI / 4}, {1.1, M_PI / 2}}, 19, 1e-12);
    std::printf("straight vs general, double: worst relative pixel difference %.3g, projected %.3g\n", w, wp);
}

// What the straight-line form does not take stays on the general path.
TEST(McStraight, OtherKeysKeepTheGeneralPath)
{
    LB_REQUIRE_RUNTIME(rt);
    const auto t = lumpy();
    Scene sc = scene(1.1, M_PI / 2, 8);
    for (const char* spec : {"mc:n=2,domain=table,sequence=sobol", "mc:n=2,domain=mis_table,sequence=sobol",
                             "mc:n=2,domain=mis_table_solid,sequence=sobol",
                             "mc:n=2,domain=solid,sequence=sobol,lookup=exact", "mc:n=2"}) {
        auto r = run(*rt, t, sc, spec, Precision::Float);
        EXPECT_EQ(r.stats["defines"].get<std::string>().find("LB_MC_STRAIGHT"), std::string::npos) << spec;
    }
}

}  // namespace
}  // namespace lb
