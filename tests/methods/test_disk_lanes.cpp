// The disk's straight-line cubature (kernels/common/disk_lanes.inc, one and
// eight pixels per work-item) against its general one-pixel kernel
// (kernels/common/disk.h, specialize=none): the same method, so they differ
// by rounding only.
#include "methods/registry.h"
#include "methods/render.h"
#include "methods/specialize.h"
#include "render_helpers.h"
#include "test_tables.h"
#include "testutil.h"

#include <fmt/format.h>

#include <cmath>
#include <iostream>

namespace lb::methods {
namespace {

// A disk (or ellipse, W x L) at height h, rotation R, res x res pixels.
Scene diskScene(double h, double R, double w, double l, int res = 45)
{
    Scene s = test::scene(h, R, res);
    s.width = w;
    s.length = l;
    s.shape = LightShape::Disk;
    return s;
}

RenderResult renderOnce(ocl::Runtime& rt, const photometry::Table& t, const Scene& s, const std::string& spec,
                        Precision p)
{
    RenderOptions opt;
    opt.reps = 1;
    opt.useCache = false;
    return render(rt, t, s, parseSpec(spec), p, opt);
}

// The scenes: a disk facing down, tilted, beside and crossing the receiver
// plane (the horizon clips it), a long thin ellipse on both axes, a large disk
// close above the receiver; 45 x 45 pixels, so the last 8-lane work-item of a
// row holds 5 pixels.
std::vector<Scene> diskScenes()
{
    return {diskScene(1.0, M_PI, 1, 1),
            diskScene(0.1, M_PI / 2, 1, 1),
            diskScene(1.0, 3 * M_PI / 4, 1, 1),
            diskScene(-0.3, 3 * M_PI / 4, 1, 1),
            diskScene(-0.4, 5 * M_PI / 8, 1, 1),
            diskScene(0.3, 5 * M_PI / 8, 1.6, 0.2),
            diskScene(-0.2, 9 * M_PI / 16, 0.2, 1.6),
            diskScene(0.05, M_PI, 3, 3)};
}

const char* const kSpecs[] = {"cubature", "robust", "cubature:area=gauss2", "robust:area_q=0.5,area_sin=0.3", "tuned"};

TEST(DiskLanes, StraightLineFormEqualsTheGeneralKernel)
{
    LB_REQUIRE_RUNTIME(rt);
    auto t = test_tables::asymmetric();
    // Double: both forms compute the same sums in another order (the light's
    // frame instead of world vectors, the arc's ends by rotation instead of
    // atan2 and sincos): 1e-10 relative per pixel (measured 3.3e-13), floor
    // 1e-9 of the image's peak where the horizon leaves a sliver of the disk
    // (E -> 0 there, its relative rounding without bound).
    // Float: both are float code held to the double general kernel, at 2e-5
    // or at twice the general float kernel's own worst error on that scene
    // and spec where that is larger (floor 1e-4 of the peak): the form must be
    // no less accurate than the general code. Float rounding is largest where
    // the horizon cuts the disk and at grazing receivers (the rim's and the
    // clip's 32-bit coordinates): measured on PoCL the general float kernel
    // up to 3.8e-4 off its double result (h -0.3, R 3pi/4, cubature), the
    // straight-line form 2.5e-4 there; on a facing disk 3.6e-6 and 3.1e-6.
    // Without double on the device: float against float, 1e-3 (the sum of
    // both forms' worst error against double, 6.3e-4, with margin).
    double worstF = 0, worstG = 0, worstD = 0;
    for (const Scene& s : diskScenes())
        for (const char* spec : kSpecs) {
            const std::string what = fmt::format("{} {}", spec, s.describe());
            const std::string general =
                std::string(spec) + (std::string(spec).find(':') == std::string::npos ? ":" : ",") + "specialize=none";
            const std::string straight = general.substr(0, general.size() - std::string("specialize=none").size());
            if (!rt->fp64()) {
                auto gf = renderOnce(*rt, t, s, general, Precision::Float);
                for (const char* lanes : {"1", "8"})
                    worstF = std::max(worstF,
                                      test::worstRelDiff(
                                          gf.image.px,
                                          renderOnce(*rt, t, s, straight + "lanes=" + lanes, Precision::Float).image.px,
                                          1e-4, 1e-3, what + " lanes=" + lanes));
                continue;
            }
            auto gd = renderOnce(*rt, t, s, general, Precision::Double);
            auto gf = renderOnce(*rt, t, s, general, Precision::Float);
            const double g = test::worstRelDiff(gd.image.px, gf.image.px, 1e-4, HUGE_VAL, what + " general float");
            worstG = std::max(worstG, g);
            for (const char* lanes : {"1", "8"}) {
                auto sf = renderOnce(*rt, t, s, straight + "lanes=" + lanes, Precision::Float);
                EXPECT_EQ(sf.stats.value("form", ""), "straight-line") << what;
                worstF = std::max(worstF,
                                  test::worstRelDiff(gd.image.px, sf.image.px, 1e-4, std::max(2e-5, 2 * g),
                                                     what + " lanes=" + lanes));
                EXPECT_EQ(sf.stats["triangles_per_pixel"], gf.stats["triangles_per_pixel"]) << what;
            }
            auto sd = renderOnce(*rt, t, s, straight + "lanes=1", Precision::Double);
            worstD = std::max(worstD, test::worstRelDiff(gd.image.px, sd.image.px, 1e-9, 1e-10, what + " double"));
            if (HasFailure()) return;
        }
    std::cout << "disk straight-line form (float, 1 and 8 lanes) against the double general kernel: worst " << worstF
              << " (general float kernel: " << worstG << "); double: " << worstD << "\n";
}

TEST(DiskLanes, HostPicksTheFormAndItsLanes)
{
    LB_REQUIRE_RUNTIME(rt);
    auto t = test_tables::asymmetric();
    const Scene s = diskScene(1.0, M_PI, 1, 1, 8);
    auto defines = [&](const std::string& spec, Precision p) {
        return renderOnce(*rt, t, s, spec, p).stats.value("defines", "");
    };
    auto has = [](const std::string& d, const std::string& what) { return d.find(what) != std::string::npos; };
    EXPECT_EQ(renderOnce(*rt, t, s, "cubature", Precision::Float).stats.value("form", ""), "straight-line");
    EXPECT_EQ(renderOnce(*rt, t, s, "robust:specialize=none", Precision::Float).stats.value("form", ""), "general");
    EXPECT_FALSE(has(defines("robust:specialize=none", Precision::Float), kDiskStraightDefine));
    // eight lanes in float with the LUT only
    EXPECT_TRUE(has(defines("cubature:lanes=8", Precision::Float), "-DLB_LANES=8"));
    EXPECT_FALSE(has(defines("cubature:lanes=1", Precision::Float), "-DLB_LANES"));
    EXPECT_FALSE(has(defines("cubature:lanes=8,lookup=exact", Precision::Float), "-DLB_LANES"));
    EXPECT_TRUE(has(defines("cubature:lanes=8,lookup=exact", Precision::Float), kDiskStraightDefine));
    if (rt->fp64()) {
        EXPECT_FALSE(has(defines("cubature:lanes=8", Precision::Double), "-DLB_LANES"));
    }
    EXPECT_EQ(kernelForm(family("cubature"), std::string(" -DLB_CUB_DISK ") + kDiskStraightDefine), "straight-line");
}

}  // namespace
}  // namespace lb::methods
