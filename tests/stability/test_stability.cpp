// The stability catalogue, its metrics, the degenerate-light
// validation and the regressions of the fixes it found.
#include "methods/render.h"
#include "stability/stability.h"
#include "testutil.h"
#include "util/error.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>

namespace lb {
namespace {

// The scene of a catalogue case with a w x l light at height h (stability::sceneOf).
Scene lightScene(double w, double l, double h = 1)
{
    stability::Case c;
    c.width = w;
    c.length = l;
    c.height = h;
    return stability::sceneOf(c, 4);
}

TEST(Stability, DegenerateLightsAreInputErrors)
{
    EXPECT_NO_THROW(lightScene(1, 1).validate());
    EXPECT_NO_THROW(lightScene(1e-3, 1e-3).validate());  // the catalogue's tiny light
    EXPECT_NO_THROW(lightScene(40, 0.02).validate());  // and its thin one
    EXPECT_THROW(lightScene(0, 0).validate(), InputError);  // coincident corners
    EXPECT_THROW(lightScene(0, 1).validate(), InputError);  // collinear corners
    EXPECT_THROW(lightScene(1, -1).validate(), InputError);
    EXPECT_THROW(lightScene(1e-9, 1).validate(), InputError);  // collinear in float
    EXPECT_THROW(lightScene(NAN, 1).validate(), InputError);
    EXPECT_NO_THROW(lightScene(1, 1, -0.1).validate());  // light through the receiver plane: clipped, legal
    EXPECT_THROW(lightScene(1, 1, INFINITY).validate(), InputError);
    try {
        lightScene(0, 1).validate();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("collinear"), std::string::npos) << e.what();
    }
}

TEST(Stability, RenderRejectsDegenerateLightForEveryMethod)
{
    LB_REQUIRE_RUNTIME(rt);
    auto table = stability::luminaire("lambert");
    for (auto& f : methods::registry().all())
        for (SceneKind k : f.scenes) {
            Scene s = lightScene(0, 1);
            s.kind = k;
            EXPECT_THROW(methods::render(*rt, table, s, methods::parseSpec(f.name, k), methods::Precision::Float),
                         InputError)
                << f.name << " " << sceneKindName(k);
        }
}

// measure() on images whose answers are known by hand.
TEST(Stability, MetricsClosedForms)
{
    Image R(2, 2), A(2, 2);
    R.px = {100, 100, 100, 0};  // max 100: floor 1
    A.px = {100, 110, 100, 0.5};
    auto e = stability::measure(R, A);
    EXPECT_EQ(e.nonfinite, 0);
    // |0.5 - 0| / max(0, floor 1) = 0.5 beats 10 / 100.
    EXPECT_DOUBLE_EQ(e.maxRelErr, 0.5);
    // Largest step of A: 110 - 0.5 (right column) over max A = 110.
    EXPECT_DOUBLE_EQ(e.maxJump, 109.5 / 110);
    // Beyond the reference's own step: top row 10 - 0 = 10; right column
    // 109.5 - 100 = 9.5; over max R = 100.
    EXPECT_DOUBLE_EQ(e.jumpExcess, 0.1);
    EXPECT_DOUBLE_EQ(stability::maxDiffRel(A, R, 100), 0.1);  // 10 / 100
    EXPECT_DOUBLE_EQ(stability::maxDiffRel(A, R, 0), 10);  // absolute

    A.px[1] = NAN;
    e = stability::measure(R, A);
    EXPECT_EQ(e.nonfinite, 1);
    EXPECT_TRUE(std::isnan(e.maxRelErr));
    EXPECT_TRUE(std::isnan(stability::maxDiffRel(A, R, 100)));

    // A black reference: the error is absolute (lux).
    Image Z(2, 2), B(2, 2);
    B.px = {0, 0, 0, 3};
    EXPECT_DOUBLE_EQ(stability::measure(Z, B).maxRelErr, 3);
}

// onLight() flags the pixels on the light and only those; measure() and
// maxDiffRel() leave them out; onLightBound() is its closed form.
TEST(Stability, PixelsOnTheLightAreLeftOutOfTheErrors)
{
    constexpr double kPi = 3.14159265358979323846;
    Scene s;  // light standing on the receiver, a pixel row in its plane
    s.height = 0;
    s.rotation = kPi / 2;
    s.width = s.length = 1;
    s.res = 9;  // pixels 5/9 m apart: x = 0 and x = +-0.56 on the row y = 0
    auto on = stability::onLight(s);
    int n = 0;
    for (size_t i = 0; i < on.size(); ++i)
        if (on[i]) {
            ++n;
            EXPECT_EQ(i, 4u * 9 + 4) << "only the middle pixel lies on the lower edge, |x| <= 0.5";
        }
    EXPECT_EQ(n, 1);
    s.width = 1.2;  // now x = +-0.56 lie on it too
    n = 0;
    for (bool b : stability::onLight(s)) n += b;
    EXPECT_EQ(n, 3);
    s.shape = LightShape::Disk;  // the inscribed disk touches the ground at x = 0 only
    n = 0;
    for (bool b : stability::onLight(s)) n += b;
    EXPECT_EQ(n, 1);
    s.height = 1e-6;  // lifted off the receiver: nothing on it
    n = 0;
    for (bool b : stability::onLight(s)) n += b;
    EXPECT_EQ(n, 0);

    Image R(2, 1), A(2, 1);
    R.px = {10, 1e9};
    A.px = {11, 5};
    const std::vector<bool> skip = {false, true};
    EXPECT_DOUBLE_EQ(stability::measure(R, A, skip).maxRelErr, 0.1);  // 1 / 10; the skipped pixel not the scale
    EXPECT_DOUBLE_EQ(stability::maxDiffRel(A, R, 10, skip), 0.1);
    A.px[1] = NAN;  // non-finite counts everywhere
    EXPECT_EQ(stability::measure(R, A, skip).nonfinite, 1);

    // (I_max / A) pi ln(1 + D^2 / eps^2): 1000 cd on 1 m^2, D^2 = 2, eps = 1 m
    photometry::Table t = stability::luminaire("lambert");
    s = Scene{};
    EXPECT_NEAR(stability::onLightBound(s, t, 1), t.maxCd() * kPi * std::log(3.0), 1e-9 * t.maxCd());
}

TEST(Stability, CatalogueCoversTheIssue)
{
    std::set<std::string> names;
    int quick = 0;
    for (auto& c : stability::catalogue()) {
        EXPECT_TRUE(names.insert(c.name).second) << "duplicate case " << c.name;
        quick += c.quick;
        if (c.expect != stability::Expect::Rejected) {
            Scene s;
            s.height = c.height;
            s.rotation = c.rotation;
            s.width = c.width;
            s.length = c.length;
            s.extent = c.extent;
            EXPECT_NO_THROW(s.validate()) << c.name;
            if (stability::missingLuminaire(c).empty())  // a ../shared file may be absent: run() skips the case
                EXPECT_NO_THROW(stability::luminaire(c.luminaire).validate()) << c.name;
        }
    }
    for (auto* n : {"touching", "grazing", "plane_diffuse", "far", "tiny", "thin", "huge_ceiling", "zero_upward",
                    "pencil", "coincident", "collinear", "slotlight_declared", "linetik_declared",
                    "aspect100_near_vertical", "aspect100_near_down", "aspect100_far_vertical", "aspect100_far_down"})
        EXPECT_TRUE(names.count(n)) << n;
    EXPECT_GT(quick, 5);
}

// The synthetic luminaires: the up-light sends nothing below gamma 90, the
// pencil beam is zero outside its measured 10 degrees.
TEST(Stability, SyntheticLuminaires)
{
    auto up = stability::luminaire("stab:upward");
    EXPECT_EQ(up.intensity(0, 89.99), 0.0);
    EXPECT_NEAR(up.intensity(0, 180), 1000, 1e-9);
    auto pencil = stability::luminaire("stab:pencil");
    EXPECT_NEAR(pencil.intensity(0, 0), 5000, 1e-9);
    EXPECT_EQ(pencil.intensity(0, 10.5), 0.0);
}

// Regression: receiver points exactly in the light's plane with emission at
// gamma = 90 (odd resolution: the middle row is at y = 0). The solid-angle
// methods divided I by |n_L . d| = 0 and multiplied by Omega_L = 0: NaN.
TEST(Stability, InPlaneReceiverIsFiniteForEveryMethod)
{
    LB_REQUIRE_RUNTIME(rt);
    stability::Options o;
    o.res = 5;
    o.cases = {"plane_diffuse"};
    auto res = stability::run(*rt, o);
    ASSERT_EQ(res.size(), 1u);
    EXPECT_EQ(res[0].res, 5);
    for (auto& r : res[0].rows) EXPECT_EQ(r.err.nonfinite, 0) << r.method << " " << r.precision;
}

// The CI run: `lumibench stability --quick --res 16 --out DIR` passes and
// writes the report.
TEST(Stability, QuickCliRunPasses)
{
    LB_REQUIRE_RUNTIME(rt);
    auto dir = std::filesystem::temp_directory_path() / fmt::format("lb-stability-{}", ::getpid());
    // a picture of an earlier run (removed) and a file of the user's (kept)
    std::filesystem::create_directories(dir / "png");
    std::ofstream(dir / "png" / "old_case_np_float_err.png") << "x";
    std::ofstream(dir / "png" / "notes.txt") << "x";
    std::string cmd = test::binary() + " stability --quick --res 16 --out " + dir.string() + " > " +
        (dir.string() + ".log") + " 2>&1";
    int st = std::system(cmd.c_str());
    std::ifstream log(dir.string() + ".log");
    std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    EXPECT_EQ(WEXITSTATUS(st), 0) << text;
    EXPECT_TRUE(std::filesystem::exists(dir / "stability.json"));
    EXPECT_TRUE(std::filesystem::exists(dir / "report.md"));
    EXPECT_FALSE(std::filesystem::is_empty(dir / "png"));
    EXPECT_FALSE(std::filesystem::exists(dir / "png" / "old_case_np_float_err.png"));
    EXPECT_TRUE(std::filesystem::exists(dir / "png" / "notes.txt"));
    std::filesystem::remove_all(dir);
    std::filesystem::remove(dir.string() + ".log");
}

}  // namespace
}  // namespace lb

namespace lb {
namespace {

// A failed requirement anywhere makes the whole document fail (the command
// then exits 1); non-finite numbers are written as null, never as numbers.
TEST(Stability, FailureAndNonFiniteReachTheDocument)
{
    LB_REQUIRE_RUNTIME(rt);
    stability::CaseResult cr;
    cr.c = stability::catalogue().front();
    cr.res = 4;
    stability::Row ok, bad;
    ok.method = bad.method = "point";
    ok.precision = "double";
    bad.precision = "float";
    bad.err.nonfinite = 3;
    bad.err.maxRelErr = NAN;
    bad.failures.push_back("3 non-finite pixels");
    cr.rows = {ok};
    EXPECT_TRUE(cr.ok());
    EXPECT_TRUE(stability::toJson({cr}, *rt, {})["ok"].get<bool>());
    cr.rows.push_back(bad);
    EXPECT_FALSE(cr.ok());
    auto j = stability::toJson({cr}, *rt, {});
    EXPECT_FALSE(j["ok"].get<bool>());
    EXPECT_TRUE(j["cases"][0]["rows"][1]["max_rel_err"].is_null());
    EXPECT_EQ(j["cases"][0]["rows"][1]["nonfinite"].get<long>(), 3);
}

// The far-field bound at the catalogue's h = 1000, 1 x 1 light: first order
// 4 a/d = 2.83e-3 dominates in double (32 eps d/a = 5e-12); float adds
// 32 eps d/a = 2.70e-3. Tolerance: a few ulp of 5e-3.
TEST(Stability, PointBoundValues)
{
    Scene s;
    s.height = 1000;
    double a = std::sqrt(0.5), d = 1000.5;
    EXPECT_NEAR(stability::pointBound(s, true), 4 * a / d + 32 * 0x1p-53 * d / a, 1e-15);
    EXPECT_NEAR(stability::pointBound(s, false), 4 * a / d + 32 * 0x1p-24 * d / a, 1e-15);
}

// Each check of a row fires on a row that breaks it, and only then: a far
// case (PointLimit) whose image is the point light's scaled by 1 + 2 bound
// fails the point limit, by 1 + bound / 2 passes; a Zero case fails on any
// non-zero pixel; NaN float-vs-double and non-finite pixels fail.
TEST(Stability, RowChecksFireOnBrokenRows)
{
    const auto& cat = stability::catalogue();
    auto far =
        std::find_if(cat.begin(), cat.end(), [](const auto& c) { return c.expect == stability::Expect::PointLimit; });
    ASSERT_NE(far, cat.end());
    const Scene s = stability::sceneOf(*far, 4);
    const double b = stability::pointBound(s, false);
    const Image point(4, 4, 2.0);
    auto failuresOf = [&](const stability::Case& c, double scale, auto&& edit) {
        stability::Row row;
        row.image = Image(4, 4, 2.0 * scale);
        row.maxAbs = 2.0 * scale;
        edit(row);
        stability::checkRow(c, s, point, false, row);
        return row.failures;
    };
    auto none = [](stability::Row&) {};
    EXPECT_TRUE(failuresOf(*far, 1 + b / 2, none).empty());
    auto f = failuresOf(*far, 1 + 2 * b, none);
    ASSERT_EQ(f.size(), 1u);
    EXPECT_EQ(f[0].rfind("point limit", 0), 0u) << f[0];
    f = failuresOf(*far, 1, [](stability::Row& r) { r.fdDiff = NAN; });
    ASSERT_EQ(f.size(), 1u);
    EXPECT_EQ(f[0].rfind("float vs double", 0), 0u) << f[0];
    f = failuresOf(*far, 1, [](stability::Row& r) { r.err.nonfinite = 2; });
    ASSERT_EQ(f.size(), 1u);
    EXPECT_EQ(f[0], "2 non-finite pixels");
    stability::Case zero = *far;
    zero.expect = stability::Expect::Zero;
    EXPECT_TRUE(failuresOf(zero, 0, none).empty());
    f = failuresOf(zero, 1e-30, none);
    ASSERT_EQ(f.size(), 1u);
    EXPECT_EQ(f[0].rfind("not exactly zero", 0), 0u) << f[0];
}

}  // namespace
}  // namespace lb
