// Scene specialisation (methods/specialize.h): the analysis rules, and every
// specialised MC kernel against the general one (<= 1e-6 relative per pixel),
// float and double.
#include "kernel_args.h"
#include "methods/analytic.h"
#include "methods/render.h"
#include "methods/specialize.h"
#include "photometry/load.h"
#include "photometry/lut.h"
#include "test_tables.h"
#include "testutil.h"

#include <fmt/format.h>

#include <cmath>
#include <iostream>

namespace lb::methods {
namespace {

Scene scene(double h, double rot, int res = 40)
{
    Scene s;
    s.height = h;
    s.rotation = rot;
    s.res = res;
    return s;
}

using test_tables::asymmetric;
using test_tables::frontLobe;

TEST(Specialize, AnalysisRules)
{
    auto a = analyse(scene(1.0, 3 * M_PI / 4), frontLobe(), true);
    EXPECT_TRUE(a.has(Rule::Lut) && a.has(Rule::Lut1d) && a.has(Rule::NoHorizon) && a.has(Rule::NoBack));
    EXPECT_EQ(a.defines(), " -DLB_LUT -DLB_LUT_1D -DLB_NO_HORIZON -DLB_NO_BACK");
    auto b = analyse(scene(1.0, M_PI), asymmetric(), true);
    EXPECT_TRUE(b.has(Rule::NoHorizon));
    EXPECT_FALSE(b.has(Rule::Lut1d) || b.has(Rule::NoBack));
    // h = 0 at R = pi/2: the lower edge touches the receiver plane, so the
    // light is not strictly above every horizon.
    EXPECT_FALSE(lightAboveEveryHorizon(scene(0.0, M_PI / 2)));
    EXPECT_TRUE(lightAboveEveryHorizon(scene(0.01, M_PI / 2)));
    // specialize = false: the general kernel, only the lookup choice.
    EXPECT_EQ(analyse(scene(1.0, 3 * M_PI / 4), frontLobe(), true, false).defines(), " -DLB_LUT");
    EXPECT_EQ(analyse(scene(1.0, 3 * M_PI / 4), frontLobe(), false, false).defines(), "");
}

// Renders `spec` with and without specialisation; per-pixel relative 1e-6.
// The kernels differ only by dropped work whose result is 0 (pixels behind a
// front-only light, max(0, cos) of positive cosines) or the identity (a 1D
// table read instead of two equal columns mixed), so they agree to a few ulp;
// 1e-6 is ~8 float ulp.
void expectSame(ocl::Runtime& rt, const photometry::Table& t, const Scene& s, const std::string& spec, Precision p,
                const std::string& expectDefines)
{
    RenderOptions opt;
    opt.reps = 1;
    ASSERT_EQ(analyse(s, t, spec.find("lookup=exact") == std::string::npos).defines(), expectDefines);
    auto gen = render(rt, t, s, parseSpec(spec + ",specialize=none"), p, opt);
    auto sp = render(rt, t, s, parseSpec(spec), p, opt);
    double peak = 0;
    for (double v : gen.image.px) peak = std::max(peak, std::fabs(v));
    ASSERT_GT(peak, 0);
    int nonzero = 0;
    for (size_t i = 0; i < gen.image.px.size(); ++i) {
        double a = gen.image.px[i], b = sp.image.px[i];
        // Floor 1e-12 of the peak for pixels that are 0 in both.
        ASSERT_LE(std::fabs(a - b), 1e-6 * std::max(std::fabs(a), 1e-12 * peak)) << spec << " pixel " << i;
        nonzero += a != 0;
    }
    EXPECT_GT(nonzero, 0);
}

TEST(Specialize, SpecialisedMcEqualsGeneral)
{
    LB_REQUIRE_RUNTIME(rt);
    auto front = frontLobe();
    auto asym = asymmetric();
    // R = pi/2: half the image lies behind the light's plane (noBack matters).
    for (auto p : {Precision::Float, Precision::Double}) {
        if (p == Precision::Double && !rt->fp64()) continue;
        expectSame(*rt, front, scene(0.1, M_PI / 2), "mc:n=16", p,
                   " -DLB_LUT -DLB_LUT_1D -DLB_NO_HORIZON -DLB_NO_BACK");
        expectSame(*rt, asym, scene(1.0, 5 * M_PI / 8), "mc:n=16", p, " -DLB_LUT -DLB_NO_HORIZON");
    }
    expectSame(*rt, front, scene(0.1, M_PI / 2), "mc:n=16,lookup=exact", Precision::Float,
               " -DLB_NO_HORIZON -DLB_NO_BACK");
}

TEST(Specialize, BackPixelsAreZeroForFrontOnlyLight)
{
    // The rule's premise, checked on the exact general kernel: at R = pi/2
    // the light's plane is y = 0 and n_L = (0, 1, 0), so every pixel with
    // y < 0 (bottom half, rows >= res/2) gets nothing from a front-only lobe.
    LB_REQUIRE_RUNTIME(rt);
    RenderOptions opt;
    opt.reps = 1;
    Scene s = scene(0.1, M_PI / 2);
    auto r = render(*rt, frontLobe(), s, parseSpec("mc:n=16,lookup=exact,specialize=none"), Precision::Float, opt);
    for (int row = s.res / 2; row < s.res; ++row)
        for (int col = 0; col < s.res; ++col) ASSERT_EQ(r.image.px[row * s.res + col], 0.0) << row << "," << col;
    EXPECT_GT(r.image.px[(s.res / 4) * s.res + s.res / 2], 0.0);
}

TEST(Specialize, LutMcCloseToExactMc)
{
    // The LUT's lookup error (tests/photometry/test_lut.cpp) carried into an
    // image. E = (1/N) sum I_i g_i with g_i >= 0, so |dE| <= eps (1/N) sum g_i
    // <= (eps / I_min) E per pixel, eps = the LUT's error bound (cd) and I_min
    // the smallest intensity (here >= 100 - 80 = 20 cd); 1e-5 for float
    // rounding of the two kernels.
    LB_REQUIRE_RUNTIME(rt);
    RenderOptions opt;
    opt.reps = 1;
    auto t = asymmetric();
    auto lut = photometry::buildLut(t);
    Scene s = scene(1.0, 3 * M_PI / 4);
    auto a = render(*rt, t, s, parseSpec("mc:n=16,lookup=exact"), Precision::Float, opt);
    auto b = render(*rt, t, s, parseSpec("mc:n=16"), Precision::Float, opt);
    double worst = 0;
    for (size_t i = 0; i < a.image.px.size(); ++i) {
        ASSERT_GT(a.image.px[i], 0);
        worst = std::max(worst, std::fabs(a.image.px[i] - b.image.px[i]) / a.image.px[i]);
    }
    EXPECT_LE(worst, lut.errorBound / 20 + 1e-5);
    EXPECT_GT(worst, 0) << "the LUT is really used";
}

// ---- The cubature's straight-line rectangle fan (rule rectFan) ----

// The form a record names (stats.form): straight-line where the family's
// define is in the build options (whole word), general where the family has
// a straight-line form but this build is not it, nothing for one-form families.
TEST(Specialize, KernelFormNamesStraightLineAndGeneralBuilds)
{
    EXPECT_EQ(kernelForm(family("cubature"), " -DLB_LUT -DLB_CUB_RECT_FAN -DLB_LANES=8"), "straight-line");
    EXPECT_EQ(kernelForm(family("cubature"), " -DLB_CUB_TRI=1 -DLB_CUB_RECT_DEL"), "straight-line");
    EXPECT_EQ(kernelForm(family("cubature"), " -DLB_CUB_TRI=1 -DLB_CUB_DYNAMIC=15 -DLB_LUT"), "general");
    EXPECT_EQ(kernelForm(family("voronoi"), " -DLB_VOR_RECT"), "straight-line");
    EXPECT_EQ(kernelForm(family("voronoi"), " -DLB_VOR_RECTANGLE"), "general");
    EXPECT_EQ(kernelForm(family("mc"), " -DLB_LUT"), "");
    LB_REQUIRE_RUNTIME(rt);
    RenderOptions opt;
    opt.reps = 1;
    Scene s = scene(1.0, 3 * M_PI / 4, 16);
    auto t = asymmetric();
    EXPECT_EQ(render(*rt, t, s, parseSpec("cubature"), Precision::Float, opt).stats.value("form", ""), "straight-line");
    EXPECT_EQ(render(*rt, t, s, parseSpec("cubature:specialize=none"), Precision::Float, opt).stats.value("form", ""),
              "general");
    EXPECT_FALSE(render(*rt, t, s, parseSpec("mc:n=2"), Precision::Float, opt).stats.contains("form"));
}

TEST(Specialize, CubatureRectFanRule)
{
    auto t = asymmetric();
    auto opts = [](const std::string& kv) {
        return CubatureOptions::parse(parseSpec("cubature" + (kv.empty() ? "" : ":" + kv)).values);
    };
    auto fan = [&](const Scene& s, const std::string& kv) {
        return analyseCubature(s, t, opts(kv)).form == "rect_fan";
    };
    Scene s = scene(1.0, 3 * M_PI / 4);
    EXPECT_TRUE(fan(s, ""));
    EXPECT_EQ(analyseCubature(s, t, opts("")).defines(), " -DLB_LUT -DLB_CUB_RECT_FAN");
    EXPECT_TRUE(fan(s, "dynamic=none"));
    EXPECT_TRUE(fan(s, "weighting=dotout,corner_inset=0.3,dyn_weight=2"));
    // Delaunay over corners + CP never flips there: the fan around CP
    EXPECT_TRUE(fan(s, "triangulation=delaunay"));
    EXPECT_TRUE(fan(s, "triangulation=delaunay,dynamic=cp"));
    EXPECT_FALSE(fan(s, "triangulation=delaunay,dynamic=none"));
    EXPECT_FALSE(fan(scene(-0.1, M_PI / 2), "triangulation=delaunay,dynamic=np"));
    EXPECT_TRUE(fan(s, "normalize=formfactor"));
    EXPECT_FALSE(fan(s, "dynamic=np"));
    EXPECT_FALSE(fan(s, "specialize=none"));
    // the image corners lie about 3.7 m from the light's centre at h = 1: the
    // blend is part of the straight-line code where some pixel reaches it
    EXPECT_TRUE(fan(s, "blend_dist=3"));
    EXPECT_EQ(analyseCubature(s, t, opts("blend_dist=3")).defines(), " -DLB_LUT -DLB_CUB_RECT_FAN -DLB_CUB_BLEND");
    EXPECT_TRUE(fan(s, "blend_dist=4"));
    EXPECT_FALSE(analyseCubature(s, t, opts("blend_dist=4")).has(Rule::Blend));
    // R = pi/2, h = 0.1: the lower edge is 0.1 m above the receiver; the clip
    // at horizon_eps + plane_eps decides
    Scene v = scene(0.1, M_PI / 2);
    EXPECT_TRUE(fan(v, "plane_eps=0.001,horizon_eps=0.05"));
    // Clipped: the straight-line forms on what the horizon leaves (rule
    // rectClip; the normalized scene's receiver normal is perpendicular to u)
    auto clip = [&](const Scene& sc, const std::string& kv) {
        auto a = analyseCubature(sc, t, opts(kv));
        return (a.form == "rect_fan" || a.form == "rect_del") && a.has(Rule::RectClip);
    };
    EXPECT_TRUE(horizonAlongU(v));
    EXPECT_TRUE(fan(v, "plane_eps=0.001,horizon_eps=0.1"));
    EXPECT_TRUE(clip(v, "plane_eps=0.001,horizon_eps=0.1"));
    EXPECT_FALSE(clip(v, "plane_eps=0.001,horizon_eps=0.05"));
    EXPECT_TRUE(clip(v, "plane_eps=0.1"));
    EXPECT_FALSE(fan(v, "plane_eps=0.1,normalize=formfactor"));  // formfactor: general where clipped
    EXPECT_TRUE(clip(scene(0.0, M_PI / 2), ""));  // touching
    EXPECT_TRUE(clip(scene(-0.1, M_PI / 2), ""));  // through the receiver plane
    EXPECT_EQ(analyseCubature(scene(-0.1, M_PI / 2), t, opts("")).defines(),
              " -DLB_LUT -DLB_CUB_RECT_FAN -DLB_CUB_RECT_CLIP");
    EXPECT_FALSE(fan(scene(-0.1, M_PI / 2), "dynamic=none"));  // fans from the clip's first vertex
    EXPECT_FALSE(fan(scene(-0.1, M_PI / 2), "specialize=none"));
    EXPECT_FALSE(clip(s, ""));
    // lanes: 8 on CPU devices in float with the LUT, else 1
    auto a = analyseCubature(s, t, opts(""));
    EXPECT_EQ(cubatureLanes(a, opts(""), "CPU", false), 8);
    EXPECT_EQ(cubatureLanes(a, opts(""), "GPU", false), 1);
    EXPECT_EQ(cubatureLanes(a, opts(""), "CPU", true), 1);
    EXPECT_EQ(cubatureLanes(a, opts("lanes=1"), "CPU", false), 1);
    EXPECT_EQ(cubatureLanes(a, opts("lanes=8"), "GPU", false), 8);
    EXPECT_EQ(cubatureLanes(analyseCubature(s, t, opts("lookup=exact")), opts("lookup=exact"), "CPU", false), 1);
    EXPECT_EQ(cubatureLanes(analyseCubature(s, t, opts("triangulation=delaunay,dynamic=np")), opts(""), "CPU", false),
              1);
    // Delaunay over corners + CP + barycentre: the same scene conditions
    auto del = [&](const Scene& sc, const std::string& kv) {
        return analyseCubature(sc, t, opts(kv)).form == "rect_del";
    };
    const std::string cb = "triangulation=delaunay,dynamic=cp+barycentre";
    EXPECT_TRUE(del(s, cb));
    EXPECT_EQ(analyseCubature(s, t, opts(cb)).defines(), " -DLB_LUT -DLB_CUB_RECT_DEL");
    EXPECT_FALSE(fan(s, cb));
    EXPECT_FALSE(del(s, ""));
    EXPECT_FALSE(del(s, "triangulation=delaunay"));
    EXPECT_FALSE(del(s, "triangulation=delaunay,dynamic=cp+np+mrp+barycentre"));
    EXPECT_FALSE(del(s, cb + ",specialize=none"));
    EXPECT_TRUE(del(s, cb + ",blend_dist=3"));
    EXPECT_TRUE(clip(v, cb + ",horizon_eps=0.1"));
    EXPECT_EQ(cubatureLanes(analyseCubature(s, t, opts(cb)), opts(cb), "CPU", false), 8);
}

// `spec` rendered by the rectangle fan with `lanes` (1 or 8) in precision p,
// against the general kernel in precision `ref`; per pixel within `rel` of
// the general value (floor 1e-12 of the peak). Returns the worst relative
// difference.
double cubatureDiff(ocl::Runtime& rt, const photometry::Table& t, const Scene& s, const std::string& spec, Precision p,
                    const std::string& lanes, Precision ref, double rel)
{
    RenderOptions opt;
    opt.reps = 1;
    auto o = CubatureOptions::parse(parseSpec(spec).values);
    auto a = analyseCubature(s, t, o);
    EXPECT_TRUE(a.form == "rect_fan" || a.form == "rect_del") << spec << " " << s.describe();
    std::string sep = spec.find(':') == std::string::npos ? ":" : ",";
    auto gen = render(rt, t, s, parseSpec(spec + sep + "specialize=none"), ref, opt);
    auto sp = render(rt, t, s, parseSpec(spec + sep + "lanes=" + lanes), p, opt);
    double worst =
        test::worstRelDiff(gen.image.px, sp.image.px, 1e-12, rel, spec + " lanes=" + lanes + " " + s.describe());
    // The statistics (triangles and flips per pixel) follow the general code's
    // cases, in the same precision (float and double may decide a flip at a
    // near-cocircular quadrilateral differently).
    if (p != ref) gen = render(rt, t, s, parseSpec(spec + sep + "specialize=none"), p, opt);
    EXPECT_EQ(gen.stats["triangles_per_pixel"], sp.stats["triangles_per_pixel"]) << spec << " " << s.describe();
    EXPECT_EQ(gen.stats["flips_per_pixel"], sp.stats["flips_per_pixel"]) << spec << " " << s.describe();
    return worst;
}

// Worst relative error of the general (specialize=none) float kernel of
// `spec` against its own double result: the float bound's reference.
double generalFloatError(ocl::Runtime& rt, const photometry::Table& t, const Scene& s, const std::string& spec)
{
    RenderOptions opt;
    opt.reps = 1;
    auto general = parseSpec(spec + (spec.find(':') == std::string::npos ? ":" : ",") + "specialize=none");
    auto gf = render(rt, t, s, general, Precision::Float, opt);
    auto gd = render(rt, t, s, general, Precision::Double, opt);
    return test::worstRelDiff(gd.image.px, gf.image.px, 1e-12, HUGE_VAL, spec + " general float " + s.describe());
}

TEST(Specialize, CubatureRectFanEqualsGeneral)
{
    LB_REQUIRE_RUNTIME(rt);
    // The fan differs from the general code only by rounding: the polynomial
    // atan2 in float (<= 2.5e-7 relative per triangle, tests/math),
    // native_sqrt, the order of the sums, and the general code's 3D float
    // vectors. So the float fan is held to the double general kernel at
    // 1e-6 (the bound), or at twice the general float kernel's own
    // worst error on that scene where that is larger (as the straight-line
    // forms below): how far float rounding goes depends on the device's
    // native_sqrt and contractions. Measured on PoCL: fan <= 8e-7, the
    // general float kernel itself up to 8.7e-6 off its double result; on
    // NVIDIA (H100) the fan reached 1.1e-6 on one pixel. In double fan and
    // general agree to 1e-12 (measured 4e-14).
    // 45 x 45 pixels: the last work-item of a row holds 5 pixels of 8.
    auto asym = asymmetric();
    auto front = frontLobe();
    std::vector<Scene> scenes = {scene(1.0, 3 * M_PI / 4, 45), scene(0.1, M_PI / 2, 45), scene(0.05, M_PI, 45),
                                 scene(2.5, 5 * M_PI / 8, 45)};
    const char* specs[] = {"cubature",
                           "cubature:weighting=sample",
                           "cubature:weighting=dotout",
                           "cubature:dynamic=none",
                           "cubature:corner_inset=0.3,dyn_weight=2",
                           "cubature:plane_eps=0.05",
                           "cubature:normalize=formfactor",
                           "cubature:normalize=formfactor,weighting=dotout,dynamic=none,corner_inset=0.2",
                           "cubature:blend_dist=1.5",
                           "cubature:blend_dist=0.6,weighting=sample,corner_inset=0.3",
                           "cubature:triangulation=delaunay",
                           "cubature:triangulation=delaunay,weighting=dotout,normalize=formfactor,dyn_weight=2",
                           "cubature:area=gauss2",
                           "cubature:area=gauss3,area_q=0.5,weighting=sample",
                           "cubature:area=gauss2,blend_dist=1.5",  // both blends, in the general kernel's order
                           "robust"};
    // Without double on the device: float against float, 2e-5 (the general
    // float kernel's own error, 8.7e-6, plus the fan's, with margin).
    Precision ref = rt->fp64() ? Precision::Double : Precision::Float;
    double rel = rt->fp64() ? 1e-6 : 2e-5;
    // normalize=formfactor multiplies by the rectangle's Lambert irradiance,
    // whose float edge sum is ill-conditioned where the light is seen at a
    // grazing angle (its terms cancel): the general float kernel itself is
    // up to 3.2e-5 off its double result here (host: 3.2e-5 general, 4.7e-5
    // fan, both against double). So formfactor is held per pixel to 1e-4,
    // and its worst pixel to twice the general float kernel's worst (+1e-6):
    // the fan is no less accurate than the general code. Double: 1e-12 below.
    double worst = 0, worstGeneral = 0, worstFf = 0, worstFfGeneral = 0;
    for (const auto& s : scenes)
        for (const char* spec : specs) {
            bool ff = std::string(spec).find("formfactor") != std::string::npos;
            double g = rt->fp64() ? generalFloatError(*rt, asym, s, spec) : 0;
            (ff ? worstFfGeneral : worstGeneral) = std::max(ff ? worstFfGeneral : worstGeneral, g);
            for (const char* lanes : {"1", "8"}) {
                double d =
                    cubatureDiff(*rt, asym, s, spec, Precision::Float, lanes, ref, ff ? 1e-4 : std::max(rel, 2 * g));
                (ff ? worstFf : worst) = std::max(ff ? worstFf : worst, d);
                if (HasFailure()) return;
            }
        }
    if (rt->fp64()) {
        EXPECT_LE(worstFf, 2 * worstFfGeneral + 1e-6);
    }
    std::cout << "rectangle fan (float) against the double general kernel: worst relative difference " << worst
              << " (general float kernel: " << worstGeneral << ")\n";
    std::cout << "formfactor (float), worst relative difference to the double general kernel: rectangle fan " << worstFf
              << ", general kernel " << worstFfGeneral << "\n";

    // 1D table, and the exact lookup (one pixel per work-item only). Here
    // the float direction's rounding (~1e-7 rad) meets steep intensities:
    // the cos^3 lobe's relative slope 3 tan(gamma) grows without bound
    // towards its zero at 90 deg, and the exact lookup's acos/atan2 in float
    // sit on the coarse 15 deg C grid. Measured (PoCL) 6.0e-6 for the 1D table
    // and 7.9e-7 for the exact lookup; bound 1e-5.
    double steep = 1e-5;
    double worst1d = cubatureDiff(*rt, front, scenes[0], "cubature", Precision::Float, "8", ref, steep);
    double worstExact = cubatureDiff(*rt, asym, scenes[1], "cubature:lookup=exact", Precision::Float, "8", ref, steep);
    std::cout << "rectangle fan (float), 1D table " << worst1d << ", exact lookup " << worstExact << "\n";
    if (!rt->fp64()) return;
    double worstD = 0;
    for (const auto& s : scenes)
        for (const char* spec : specs)
            worstD =
                std::max(worstD, cubatureDiff(*rt, asym, s, spec, Precision::Double, "1", Precision::Double, 1e-12));
    std::cout << "rectangle fan (double) against the general kernel: worst relative difference " << worstD << "\n";
}

// The straight-line forms of voronoi (any scene: the method never clips) and
// of point (any scene), cp, np, mrp and structured (nothing clipped) against their
// general kernels (methods/straight.h), as the cubature's fan above: double
// within 1e-12; float within 1e-6 of the double general kernel, or twice the
// general float kernel's own worst error where that is larger: next to the
// light crossing the receiver plane (h = -0.2, 22000 lux) the general float
// voronoi kernel itself is 3.6e-6 off its double result (the straight-line
// form 3.9e-6). 45 x 45 pixels: the last 8-lane work-item of a row is partial.
TEST(Specialize, StraightLineFormsEqualGeneral)
{
    LB_REQUIRE_RUNTIME(rt);
    auto asym = asymmetric();
    auto front = frontLobe();
    std::vector<Scene> unclipped = {scene(1.0, 3 * M_PI / 4, 45), scene(0.1, M_PI / 2, 45), scene(0.05, M_PI, 45),
                                    scene(2.5, 5 * M_PI / 8, 45)};
    Scene crossing = scene(-0.2, 5 * M_PI / 8, 45);
    RenderOptions opt;
    opt.reps = 1;
    Precision ref = rt->fp64() ? Precision::Double : Precision::Float;
    const double rel = rt->fp64() ? 1e-6 : 1e-5;
    // worst relative difference of `spec` in precision p from the general kernel in pr
    auto diff = [&](const photometry::Table& t, const Scene& s, const std::string& spec, Precision p, Precision pr,
                    double bound) {
        std::string sep = spec.find(':') == std::string::npos ? ":" : ",";
        std::string general = spec.find("specialize") != std::string::npos ? spec : spec + sep + "specialize=none";
        auto gen = render(*rt, t, s, parseSpec(general), pr, opt);
        auto sp = render(*rt, t, s, parseSpec(spec), p, opt);
        return test::worstRelDiff(gen.image.px, sp.image.px, 1e-12, bound, spec + " " + s.describe());
    };
    struct Case {
        std::string name, define;
        bool anyScene;
    };
    double worst = 0, worstD = 0;
    for (const Case& c : {Case{"voronoi", "-DLB_VOR_RECT", true}, Case{"point", "-DLB_DYN_RECT", true},
                          Case{"cp", "-DLB_DYN_RECT", false}, Case{"np", "-DLB_DYN_RECT", false},
                          Case{"mrp", "-DLB_DYN_RECT", false}, Case{"structured", "-DLB_STRUCT_RECT", false}}) {
        std::vector<Scene> scenes = unclipped;
        if (c.anyScene) scenes.push_back(crossing);
        // the rule: the straight-line form where it holds, and only there
        EXPECT_NE(test::planDefines(parseSpec(c.name), unclipped[0], asym).find(c.define), std::string::npos) << c.name;
        EXPECT_EQ(test::planDefines(parseSpec(c.name + ":specialize=none"), unclipped[0], asym).find(c.define),
                  std::string::npos)
            << c.name;
        EXPECT_EQ(test::planDefines(parseSpec(c.name), crossing, asym).find(c.define) != std::string::npos, c.anyScene)
            << c.name;
        for (const auto& s : scenes) {
            double bound = rel;
            if (rt->fp64())
                bound = std::max(rel, 2 * diff(asym, s, c.name + ":specialize=none", Precision::Float, ref, 1.0));
            for (const char* lanes : {"lanes=1", "lanes=8"})
                worst = std::max(worst, diff(asym, s, c.name + ":" + lanes, Precision::Float, ref, bound));
            if (rt->fp64())
                worstD = std::max(worstD, diff(asym, s, c.name, Precision::Double, Precision::Double, 1e-12));
            if (HasFailure()) return;
        }
        // 1D table: the cos^3 lobe's steep fall to 0 at 90 deg (see the cubature's bound), or
        // twice the general float kernel's own error (point: pixels of 3e-3 lux at the cut-off)
        double steep = 1e-5;
        if (rt->fp64())
            steep =
                std::max(steep, 2 * diff(front, unclipped[0], c.name + ":specialize=none", Precision::Float, ref, 1.0));
        worst = std::max(worst, diff(front, unclipped[0], c.name + ":lanes=8", Precision::Float, ref, steep));
    }
    worst = std::max(
        worst, diff(asym, unclipped[1], "voronoi:lanes=8,table_res=9,plane_eps=0.05", Precision::Float, ref, rel));
    // np and mrp with a larger skew (the normal tilts for more pixels)
    for (const char* spec : {"np:lanes=8,skew=0.9", "mrp:lanes=8,skew=0.9"})
        for (const auto& s : unclipped) worst = std::max(worst, diff(asym, s, spec, Precision::Float, ref, rel));
    if (rt->fp64())
        for (const char* spec : {"np:skew=0.9", "mrp:skew=0.9"})
            for (const auto& s : unclipped)
                worstD = std::max(worstD, diff(asym, s, spec, Precision::Double, Precision::Double, 1e-12));
    std::cout << "straight-line forms against the general kernels: float " << worst << ", double " << worstD << "\n";
}

// The Delaunay forms' scenes (45 x 45 pixels, odd: a column on u = 0): R = pi
// puts pixels on the light's diagonals and centre, a 2 x 0.5 m light makes
// unequal quadrants, and a 1.5 m extent (pixels every 1/30 m) puts many under
// the light, on its diagonals and edges.
std::vector<Scene> delaunayScenes()
{
    Scene wide = scene(0.3, 3 * M_PI / 4, 45);
    wide.width = 2;
    wide.length = 0.5;
    Scene flat = scene(0.2, M_PI, 45);
    flat.extent = 1.5;
    return {scene(1.0, 3 * M_PI / 4, 45),
            scene(0.1, M_PI / 2, 45),
            scene(0.05, M_PI, 45),
            scene(2.5, 5 * M_PI / 8, 45),
            wide,
            flat};
}

// The spec variations both Delaunay forms are held to the general kernel
// with: Delaunay over the corners and `dynamic`, each weighting, the
// placement tunables, a larger plane shift, formfactor, the far-field blend
// and the area form.
std::vector<std::string> delaunaySpecs(const std::string& dynamic)
{
    const std::string d = "cubature:triangulation=delaunay,dynamic=" + dynamic;
    return {d,
            d + ",weighting=sample",
            d + ",weighting=dotout",
            d + ",corner_inset=0.3,dyn_weight=2",
            d + ",plane_eps=0.05",
            d + ",normalize=formfactor",
            d + ",blend_dist=1.5",
            d + ",area=gauss2"};
}

// Worst relative differences of a straight-line Delaunay form against the
// general kernel over delaunayScenes() x specs: diff(scene, spec, precision,
// lanes, reference precision, bound) renders both and checks one pair. The
// bounds: double 1e-12; float `rel` of the reference or twice the general
// float kernel's own worst error on the scene, formfactor 1e-4.
struct FormWorst {
    double f = 0, d = 0, general = 0;
};
template <class Diff>
FormWorst delaunayAgainstGeneral(ocl::Runtime& rt, const photometry::Table& t, const std::vector<std::string>& specs,
                                 Precision ref, double rel, Diff diff)
{
    FormWorst w;
    for (const auto& s : delaunayScenes())
        for (const auto& spec : specs) {
            bool ff = spec.find("formfactor") != std::string::npos;
            double g = rt.fp64() ? generalFloatError(rt, t, s, spec) : 0;
            w.general = std::max(w.general, g);
            for (const char* lanes : {"1", "8"})
                w.f = std::max(w.f, diff(s, spec, Precision::Float, lanes, ref, std::max(ff ? 1e-4 : rel, 2 * g)));
            if (rt.fp64()) w.d = std::max(w.d, diff(s, spec, Precision::Double, "1", Precision::Double, 1e-12));
            if (::testing::Test::HasFailure()) return w;
        }
    return w;
}

// The straight-line Delaunay over corners + CP + barycentre against the
// general kernel (Lawson flips over the triangulation structure), with the
// bounds of the rectangle fan above: double 1e-12; float 1e-6 of the double
// general kernel or twice the general float kernel's own error, formfactor
// 1e-4. The scenes put pixels exactly on the light's diagonals and centre
// (R = pi, odd resolution: B on a fan edge, B on CP), on its edges and
// corners (CP on the hull), and a 2 x 0.5 m light (unequal quadrants); the
// flip statistics must match as well, so every flip decision is the general
// code's.
TEST(Specialize, CubatureRectDelaunayEqualsGeneral)
{
    LB_REQUIRE_RUNTIME(rt);
    auto asym = asymmetric();
    std::vector<std::string> specs = delaunaySpecs("cp+barycentre");
    specs.push_back(specs[0] + ",blend_dist=0.6,weighting=sample");
    specs.push_back(specs[0] + ",area=gauss3,area_q=3");
    Precision ref = rt->fp64() ? Precision::Double : Precision::Float;
    FormWorst w = delaunayAgainstGeneral(
        *rt, asym, specs, ref, rt->fp64() ? 1e-6 : 2e-5,
        [&](const Scene& s, const std::string& spec, Precision p, const std::string& lanes, Precision pr,
            double bound) { return cubatureDiff(*rt, asym, s, spec, p, lanes, pr, bound); });
    if (HasFailure()) return;
    std::cout << "Delaunay cp + barycentre, straight-line against the general kernel: float " << w.f
              << " (general float kernel against its double result: " << w.general << "), double " << w.d << "\n";
}

// The check of a Delaunay form that counts flips its own way (define: its
// -D), for delaunayAgainstGeneral: the worst relative difference of the
// images, the form's define in use, triangle counts equal and flips within 5 %
// (the form reports the edges its final triangulation does not share with
// the general code's start: the general count up to the sweep's
// intermediate edges; on the host never above it, the Cubature*
// RectDelaunay*EqualsGeneral tests; a kernel's rounding decides a few
// exactly cocircular quadrilaterals of the symmetric scenes otherwise).
// flipRatio gets the smallest ratio of the two counts. flipsAtRef: flips
// against the general kernel in the reference precision (not the form's),
// within flipTol.
auto ownFlipsDiff(ocl::Runtime& rt, const photometry::Table& t, std::string define, double& flipRatio,
                  bool flipsAtRef = false, double flipTol = 0.05)
{
    return [&rt, &t, define, &flipRatio, flipsAtRef, flipTol](const Scene& s, const std::string& spec, Precision p,
                                                              const std::string& lanes, Precision pr, double bound) {
        RenderOptions opt;
        opt.reps = 1;
        auto gen = render(rt, t, s, parseSpec(spec + ",specialize=none"), pr, opt);
        auto sp = render(rt, t, s, parseSpec(spec + ",lanes=" + lanes), p, opt);
        EXPECT_NE(sp.stats.value("defines", std::string()).find(define), std::string::npos);
        double w =
            test::worstRelDiff(gen.image.px, sp.image.px, 1e-12, bound, spec + " lanes=" + lanes + " " + s.describe());
        double gf = gen.stats["flips_per_pixel"], sf = sp.stats["flips_per_pixel"];
        if (p != pr) gen = render(rt, t, s, parseSpec(spec + ",specialize=none"), p, opt);
        EXPECT_EQ(gen.stats["triangles_per_pixel"], sp.stats["triangles_per_pixel"]) << spec << " " << s.describe();
        if (!flipsAtRef) gf = gen.stats["flips_per_pixel"];
        EXPECT_NEAR(sf, gf, flipTol * gf) << spec << " " << s.describe();
        if (gf > 0) flipRatio = std::min(flipRatio, std::min(sf / gf, gf / sf));
        return w;
    };
}

// A Delaunay form that counts flips its own way against the general kernel
// over delaunayScenes() x specs (delaunayAgainstGeneral with ownFlipsDiff).
void ownFlipsForm(ocl::Runtime& rt, const photometry::Table& t, const std::vector<std::string>& specs,
                  const std::string& define, const std::string& name)
{
    Precision ref = rt.fp64() ? Precision::Double : Precision::Float;
    double flipRatio = 1;
    FormWorst w =
        delaunayAgainstGeneral(rt, t, specs, ref, rt.fp64() ? 1e-6 : 2e-5, ownFlipsDiff(rt, t, define, flipRatio));
    if (::testing::Test::HasFailure()) return;
    std::cout << name << ", straight-line against the general kernel: float " << w.f
              << " (general float kernel against its double result: " << w.general << "), double " << w.d
              << "; flips per pixel within a factor " << flipRatio << " of the general kernel's\n";
}

// The straight-line Delaunay over corners + CP + NP + MRP + barycentre
// (rule rectDelAll) against the general kernel, with the bounds of the forms
// above: double 1e-12; float 1e-6 of the double general kernel or twice the
// general float kernel's own worst error on the scene (formfactor 1e-4). The
// scenes put pixels on the light's diagonals and centre (R = pi, odd
// resolution), on its edges and corners (CP on the hull, NP clamped into a
// corner), on the u = 0 line (odd resolution: the barycentre on the line of
// CP, MRP and NP), and a 2 x 0.5 m light. Triangle counts equal in every
// precision; flips: the general code's count depends on its sweep order
// (common/cubature_lanes.inc), so the form reports the number of edges its
// final triangulation does not share with the general code's starting one,
// which is the general count up to the sweep's intermediate edges.
TEST(Specialize, CubatureRectDelaunayAllEqualsGeneral)
{
    LB_REQUIRE_RUNTIME(rt);
    auto asym = asymmetric();
    std::vector<Scene> scenes = delaunayScenes();
    const std::vector<std::string> specs = delaunaySpecs("cp+np+mrp+barycentre");
    const std::string& d = specs[0];
    for (const auto& s : scenes) {
        auto a = analyseCubature(s, asym, CubatureOptions::parse(parseSpec(d).values));
        EXPECT_TRUE(a.form == "rect_del_all") << s.describe();
        EXPECT_FALSE(a.form == "rect_fan" || a.form == "rect_del") << s.describe();
    }
    // only that method, not with specialize=none; where the horizon cuts the
    // light along u, on what it leaves (CubatureRectDelaunayAllClipEqualsGeneral)
    auto delAll = [&](const Scene& s, const std::string& spec) {
        return analyseCubature(s, asym, CubatureOptions::parse(parseSpec(spec).values)).form == "rect_del_all";
    };
    EXPECT_FALSE(delAll(scenes[0], d + ",specialize=none"));
    EXPECT_FALSE(delAll(scenes[0], "cubature:triangulation=delaunay,dynamic=cp+np+barycentre"));
    EXPECT_TRUE(delAll(scene(-0.2, 5 * M_PI / 8, 45), d));
    EXPECT_FALSE(delAll(scene(-0.2, 5 * M_PI / 8, 45), d + ",normalize=formfactor"));
    ownFlipsForm(*rt, asym, specs, "-DLB_CUB_RECT_DELALL", "Delaunay cp + np + mrp + barycentre");
}

// The straight-line Delaunay over corners + CP + 1 to 4 static samples (rule
// rectDelStatic) against the general kernel, with the bounds of the forms
// above: double 1e-12; float 1e-6 of the double general kernel or twice the
// general float kernel's own worst error on the scene (formfactor 1e-4), on
// delaunayScenes() (pixels on the light's diagonals, edges and corners), with
// one sample at a tuned position, 2 % from a corner and at the centre (on
// the spokes of the pixels on the diagonals), and two to four (the defaults
// and moved ones). Triangle counts equal; flips as the form of every dynamic
// point (the general count up to its sweep's intermediate edges). The rule:
// dynamic=cp, nothing clipped, every sample at least 1 % inside.
TEST(Specialize, CubatureRectDelaunayStaticEqualsGeneral)
{
    LB_REQUIRE_RUNTIME(rt);
    auto asym = asymmetric();
    std::vector<Scene> scenes = delaunayScenes();
    const std::string d = "cubature:triangulation=delaunay,static=1";
    const std::vector<std::string> specs = {d + ",s1=0.485,t1=0.11",
                                            d + ",s1=0.02,t1=0.98,weighting=dotout,corner_inset=0.3,dyn_weight=2",
                                            d + ",s1=0.5,t1=0.5,weighting=sample",
                                            d + ",s1=0.7,t1=0.4,normalize=formfactor",
                                            d + ",s1=0.485,t1=0.11,blend_dist=1.5,area=gauss2",
                                            "cubature:triangulation=delaunay,static=2,s1=0.485,t1=0.11",
                                            "cubature:triangulation=delaunay,static=3,weighting=dotout,dyn_weight=0.5",
                                            "cubature:triangulation=delaunay,static=4,s2=0.6,t2=0.2,corner_inset=0.3"};
    auto delSt = [&](const Scene& s, const std::string& spec) {
        return analyseCubature(s, asym, CubatureOptions::parse(parseSpec(spec).values)).form == "rect_del_static";
    };
    for (const auto& s : scenes) EXPECT_TRUE(delSt(s, specs[0])) << s.describe();
    EXPECT_FALSE(delSt(scenes[0], specs[0] + ",specialize=none"));
    EXPECT_FALSE(delSt(scenes[0], d + ",s1=0.005"));
    EXPECT_TRUE(delSt(scenes[0], "cubature:triangulation=delaunay,static=4"));
    EXPECT_FALSE(delSt(scenes[0], "cubature:triangulation=delaunay,static=2,s2=0.995"));
    EXPECT_FALSE(delSt(scenes[0], "cubature:triangulation=delaunay,dynamic=cp+barycentre,static=1"));
    EXPECT_FALSE(delSt(scene(-0.2, 5 * M_PI / 8, 45), specs[0]));
    ownFlipsForm(*rt, asym, specs, "-DLB_CUB_RECT_DELST", "Delaunay cp + one static sample");
}

}  // namespace
}  // namespace lb::methods

namespace lb::methods {
namespace {

// The straight-line forms where the horizon cuts the light (rule rectClip),
// against the general kernel's clip: the light through the receiver plane
// (h < 0, three rotations), touching it, cut by horizon_eps, and a
// horizontal light wholly behind the receiver plane (av = 0: all or
// nothing). Bounds as the unclipped forms above (double 1e-12; float 1e-6 of
// the double general kernel or twice the general float kernel's own error),
// and the triangle and flip counts of every pixel equal.
// The clipped scenes of the tests below, each with the tunables that clip it.
std::vector<std::pair<Scene, std::string>> clippedCases()
{
    return {{scene(-0.2, 5 * M_PI / 8, 45), ""},
            {scene(-0.3, M_PI / 2, 45), ""},
            {scene(-0.5, 3 * M_PI / 4, 45), ""},
            {scene(0.0, M_PI / 2, 45), ""},
            {scene(0.1, M_PI / 2, 45), "horizon_eps=0.1"}};
}

TEST(Specialize, CubatureRectClipEqualsGeneral)
{
    LB_REQUIRE_RUNTIME(rt);
    auto asym = asymmetric();
    Scene below = scene(-1.0, M_PI, 45);
    auto cases = clippedCases();
    const std::vector<std::string> specs = {"cubature",
                                            "cubature:weighting=sample",
                                            "cubature:weighting=dotout,corner_inset=0.3,dyn_weight=2",
                                            "cubature:blend_dist=1.5",
                                            "cubature:triangulation=delaunay",
                                            "cubature:triangulation=delaunay,dynamic=cp+barycentre",
                                            "cubature:triangulation=delaunay,dynamic=cp+barycentre,weighting=dotout",
                                            "cubature:area=gauss2,area_q=0.5",
                                            "robust"};
    Precision ref = rt->fp64() ? Precision::Double : Precision::Float;
    double rel = rt->fp64() ? 1e-6 : 2e-5;
    double worst = 0, worstD = 0, worstGeneral = 0;
    for (const auto& [s, kv] : cases)
        for (const auto& base : specs) {
            std::string spec = kv.empty() ? base : base + (base.find(':') == std::string::npos ? ":" : ",") + kv;
            auto a = analyseCubature(s, asym, CubatureOptions::parse(parseSpec(spec).values));
            EXPECT_TRUE(a.has(Rule::RectClip)) << spec << " " << s.describe();
            bool ff = spec.find("formfactor") != std::string::npos;
            double g = rt->fp64() ? generalFloatError(*rt, asym, s, spec) : 0;
            worstGeneral = std::max(worstGeneral, g);
            if (rt->fp64())
                worstD = std::max(worstD,
                                  cubatureDiff(*rt, asym, s, spec, Precision::Double, "1", Precision::Double, 1e-12));
            for (const char* lanes : {"1", "8"})
                worst = std::max(
                    worst,
                    cubatureDiff(*rt, asym, s, spec, Precision::Float, lanes, ref, std::max(ff ? 1e-4 : rel, 2 * g)));
            if (HasFailure()) return;
        }
    // wholly behind: every pixel exactly 0 and no triangle, as the general kernel
    RenderOptions opt;
    opt.reps = 1;
    // the record says which variant ran
    auto one = render(*rt, asym, cases[0].first, parseSpec("cubature"), Precision::Float, opt);
    EXPECT_NE(one.stats.value("defines", std::string()).find("-DLB_CUB_RECT_CLIP"), std::string::npos)
        << one.stats.dump();
    for (const auto& spec : specs) {
        EXPECT_TRUE(analyseCubature(below, asym, CubatureOptions::parse(parseSpec(spec).values)).has(Rule::RectClip))
            << spec;
        auto sp = render(*rt, asym, below, parseSpec(spec), Precision::Float, opt);
        for (double e : sp.image.px) EXPECT_EQ(e, 0.0) << spec;
        EXPECT_EQ(sp.stats["triangles_per_pixel"], 0.0) << spec;
    }
    std::cout << "clipped straight-line forms against the general kernel: float " << worst
              << " (general float kernel against its double result: " << worstGeneral << "), double " << worstD << "\n";
}

// Delaunay over corners + CP + NP + MRP + barycentre where the horizon cuts
// the light along u (rules rectDelAll and rectClip: the form on the
// rectangle the clip leaves, whose centre is the barycentre and to which NP
// and MRP are clamped, as the general code's clipped polygon), on the clipped
// scenes above and wholly behind. Bounds as its unclipped test (double
// 1e-12; float 1e-6 of the double general kernel or twice the general float
// kernel's own error), triangle counts equal. Flips (counted its own way, as
// ownFlipsDiff) within 5 % of the general kernel's in the reference
// precision: the general float kernel decides the near-cocircular
// quadrilaterals of a light through the receiver plane otherwise (h = -0.5,
// R = 3pi/4: 0.846 flips per pixel in float, 0.938 in double; the form 0.917
// in float, 0.920 in double); without double, within 12 %.
TEST(Specialize, CubatureRectDelaunayAllClipEqualsGeneral)
{
    LB_REQUIRE_RUNTIME(rt);
    auto asym = asymmetric();
    auto cases = clippedCases();
    const std::string d = "cubature:triangulation=delaunay,dynamic=cp+np+mrp+barycentre";
    const std::vector<std::string> specs = {d, d + ",weighting=dotout,corner_inset=0.3,dyn_weight=2",
                                            d + ",weighting=sample"};
    Precision ref = rt->fp64() ? Precision::Double : Precision::Float;
    double rel = rt->fp64() ? 1e-6 : 2e-5;
    double flipRatio = 1, worst = 0, worstD = 0, worstGeneral = 0;
    auto diff =
        ownFlipsDiff(*rt, asym, "-DLB_CUB_RECT_DELALL -DLB_CUB_RECT_CLIP", flipRatio, true, rt->fp64() ? 0.05 : 0.12);
    for (const auto& [s, kv] : cases)
        for (const auto& base : specs) {
            std::string spec = kv.empty() ? base : base + "," + kv;
            auto a = analyseCubature(s, asym, CubatureOptions::parse(parseSpec(spec).values));
            EXPECT_TRUE(a.form == "rect_del_all" && a.has(Rule::RectClip)) << spec << " " << s.describe();
            double g = rt->fp64() ? generalFloatError(*rt, asym, s, spec) : 0;
            worstGeneral = std::max(worstGeneral, g);
            if (rt->fp64()) worstD = std::max(worstD, diff(s, spec, Precision::Double, "1", Precision::Double, 1e-12));
            for (const char* lanes : {"1", "8"})
                worst = std::max(worst, diff(s, spec, Precision::Float, lanes, ref, std::max(rel, 2 * g)));
            if (HasFailure()) return;
        }
    // wholly behind: every pixel exactly 0 and no triangle, as the general kernel
    RenderOptions opt;
    opt.reps = 1;
    Scene below = scene(-1.0, M_PI, 45);
    EXPECT_TRUE(analyseCubature(below, asym, CubatureOptions::parse(parseSpec(d).values)).form == "rect_del_all");
    auto sp = render(*rt, asym, below, parseSpec(d), Precision::Float, opt);
    for (double e : sp.image.px) EXPECT_EQ(e, 0.0);
    EXPECT_EQ(sp.stats["triangles_per_pixel"], 0.0);
    std::cout << "clipped Delaunay cp + np + mrp + barycentre against the general kernel: float " << worst
              << " (general float kernel against its double result: " << worstGeneral << "), double " << worstD
              << "; flips per pixel within a factor " << flipRatio << " of the general kernel's\n";
}

}  // namespace
}  // namespace lb::methods
