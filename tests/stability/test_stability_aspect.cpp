// Linear lights at their real aspect in the stability catalogue: SLOTLIGHT
// and LINETIK-S at the openings their files declare (../shared; skipped when
// absent) and the synthetic 1 m x 10 mm light, through every registered
// method and through the cubature's structural variants, float and double.
#include "methods/render.h"
#include "photometry/load.h"
#include "stability/stability.h"
#include "testutil.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace lb {
namespace {

const stability::Case& caseNamed(const std::string& name)
{
    for (auto& c : stability::catalogue())
        if (c.name == name) return c;
    throw std::runtime_error("no case " + name);
}

std::vector<std::string> linearCases()
{
    std::vector<std::string> v;
    for (auto& c : stability::catalogue())
        if (c.name.rfind("aspect100_", 0) == 0 || c.name.rfind("slotlight_", 0) == 0 ||
            c.name.rfind("linetik_", 0) == 0)
            v.push_back(c.name);
    return v;
}

// The real files' cases take the opening the file declares: W (along u =
// C0) is the file's length, L its width (docs/design.md section 2), aspect
// 28 and 77; the synthetic light is 1:100.
TEST(Stability, LinearAspect100CasesTakeTheDeclaredOpening)
{
    EXPECT_EQ(linearCases().size(), 9u);
    const auto& a = caseNamed("aspect100_near_down");
    EXPECT_DOUBLE_EQ(a.width / a.length, 100.0);
    LB_REQUIRE_SHARED(shared);
    for (auto* name : {"slotlight_declared", "slotlight_vertical", "linetik_declared", "linetik_vertical"}) {
        const auto& c = caseNamed(name);
        ASSERT_EQ(stability::missingLuminaire(c), "") << name;
        auto t = stability::luminaire(c.luminaire);
        EXPECT_EQ(t.opening.shape, photometry::OpeningShape::Rectangle) << name;
        EXPECT_DOUBLE_EQ(c.width, t.opening.lengthM) << name;
        EXPECT_DOUBLE_EQ(c.length, t.opening.widthM) << name;
    }
    EXPECT_NEAR(caseNamed("slotlight_declared").width / caseNamed("slotlight_declared").length, 27.8, 0.1);
    EXPECT_NEAR(caseNamed("linetik_declared").width / caseNamed("linetik_declared").length, 76.9, 0.1);
}

// A "shared:" luminaire that is absent makes its case a skip with the path
// named, never a failure; the suite's own luminaires are never missing.
TEST(Stability, LinearAspect100MissingSharedFileSkipsTheCase)
{
    stability::Case c = caseNamed("linetik_declared");
    c.luminaire = "shared:zumtobel/NO_SUCH_FILE.LDT";
    const std::string why = stability::missingLuminaire(c);
    EXPECT_NE(why.find("NO_SUCH_FILE.LDT"), std::string::npos) << why;
    EXPECT_NE(why.find("absent"), std::string::npos) << why;
    EXPECT_EQ(stability::missingLuminaire(caseNamed("aspect100_near_down")), "");
    stability::CaseResult cr;
    cr.c = c;
    cr.skipped = why;
    EXPECT_TRUE(cr.ok());
}

// relBound: a family's own bound, else "*", else none (+inf); and a row over
// its bound, or with a negative pixel, fails.
TEST(Stability, LinearAspect100BoundsFireOnBrokenRows)
{
    const auto& c = caseNamed("aspect100_near_down");
    EXPECT_EQ(stability::relBound(c, "reference"), 1e-4);
    EXPECT_EQ(stability::relBound(c, "robust"), 36);
    EXPECT_EQ(stability::relBound(c, "cubature"), 12);
    EXPECT_TRUE(std::isinf(stability::relBound(caseNamed("touching"), "cubature")));
    const Scene s = stability::sceneOf(c, 4);
    const Image none;
    auto failures = [&](double rel, long negative) {
        stability::Row row;
        row.method = "cubature";
        row.err.maxRelErr = rel;
        row.err.negative = negative;
        stability::checkRow(c, s, none, true, row);
        return row.failures;
    };
    EXPECT_TRUE(failures(11.9, 0).empty());
    auto f = failures(12.1, 0);
    ASSERT_EQ(f.size(), 1u);
    EXPECT_EQ(f[0].rfind("max_rel_err", 0), 0u) << f[0];
    f = failures(1, 3);
    ASSERT_EQ(f.size(), 1u);
    EXPECT_EQ(f[0], "3 negative pixels");
}

// The linear cases through lumibench stability's run(): every registered
// method in float and double within the case's bounds (finite, >= 0, the
// measured max_rel_err x 2, float vs double within 1e-3 of max R). The
// documented failures stay measured: robust and tuned put the 3 x 3 area
// rule under the light (aspect100_near_down: 10-18x too bright); once that
// is fixed this test fails and the case's bound and docs/usage.md get the
// new numbers.
TEST(Stability, LinearAspect100EveryMethodWithinItsBounds)
{
    LB_REQUIRE_RUNTIME(rt);
    stability::Options o;
    o.res = 16;
    o.cases = linearCases();
    auto res = stability::run(*rt, o);
    ASSERT_EQ(res.size(), o.cases.size());
    int ran = 0;
    for (auto& cr : res) {
        if (!cr.skipped.empty()) continue;
        ++ran;
        for (auto& r : cr.rows) {
            EXPECT_TRUE(r.failures.empty()) << cr.c.name << " " << r.method << " " << r.precision << ": "
                                            << (r.failures.empty() ? "" : r.failures[0]);
            EXPECT_EQ(r.err.nonfinite, 0);
            EXPECT_EQ(r.err.negative, 0);
            EXPECT_LE(r.fdDiff, 1e-3) << cr.c.name << " " << r.method;
            if (cr.c.name == "aspect100_near_down" && (r.method == "robust" || r.method == "tuned"))
                EXPECT_GT(r.err.maxRelErr, 5) << "robust's area rule under a long light: update docs/usage.md";
        }
    }
    EXPECT_GE(ran, 5);  // the five synthetic cases run everywhere
}

// The cubature's structural variants (fan; Delaunay over CP + barycentre and
// over all four dynamic points; the form-factor normalisation; voronoi) on
// the synthetic cases: the straight-line form of the scene (specialize=auto)
// equals the general kernel (specialize=none) within float rounding, with
// the same flip counts in float and double (the in-circle decisions at
// aspect 100 do not depend on the precision); finite and >= 0 everywhere.
TEST(Stability, LinearAspect100CubatureVariantsAgree)
{
    LB_REQUIRE_RUNTIME(rt);
    const char* variants[] = {"cubature", "cubature:triangulation=delaunay,dynamic=cp+barycentre",
                              "cubature:triangulation=delaunay,dynamic=cp+np+mrp+barycentre",
                              "cubature:triangulation=delaunay,dynamic=cp+barycentre,normalize=formfactor"};
    methods::RenderOptions ro;
    ro.reps = 1;
    for (auto& name : linearCases()) {
        if (name.rfind("aspect100_", 0) != 0) continue;
        const auto& c = caseNamed(name);
        Scene s = stability::sceneOf(c, 9);
        auto table = stability::luminaire(c.luminaire);
        for (std::string v : variants) {
            double rmax = 0, flips[2] = {-1, -1};
            Image img[2][2];  // [specialize auto / none][float / double]
            for (int gen = 0; gen < 2; ++gen)
                for (int dbl = 0; dbl < 2; ++dbl) {
                    auto spec = methods::parseSpec(v + (v.find(':') == std::string::npos ? ":" : ",") +
                                                   (gen ? "specialize=none" : "specialize=auto"));
                    auto r = methods::render(*rt, table, s, spec,
                                             dbl ? methods::Precision::Double : methods::Precision::Float, ro);
                    img[gen][dbl] = r.image;
                    for (double x : r.image.px) {
                        ASSERT_TRUE(std::isfinite(x)) << name << " " << v;
                        EXPECT_GE(x, 0.0) << name << " " << v;
                        rmax = std::max(rmax, x);
                    }
                    if (gen && r.stats.contains("flips_per_pixel"))
                        flips[dbl] = r.stats["flips_per_pixel"].get<double>();
                }
            // float vs double and form vs general: measured <= 1e-4 of max R
            // on these cases (the catalogue's fd_diff); 1e-3 leaves margin.
            EXPECT_LE(stability::maxDiffRel(img[0][0], img[1][0], rmax), 1e-3) << name << " " << v;
            EXPECT_LE(stability::maxDiffRel(img[0][1], img[1][1], rmax), 1e-3) << name << " " << v;
            EXPECT_LE(stability::maxDiffRel(img[1][0], img[1][1], rmax), 1e-3) << name << " " << v;
            EXPECT_EQ(flips[0], flips[1]) << name << " " << v;
            if (v.find("delaunay") != std::string::npos) EXPECT_GE(flips[0], 0) << "no flip count: " << v;
        }
    }
}

}  // namespace
}  // namespace lb
