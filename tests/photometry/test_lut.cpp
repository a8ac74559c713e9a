// The trig-free lookup table (photometry/lut.h, kernels/common/lut.h): its
// pseudo-angles, and its interpolation error against the exact bilinear lookup
// for every luminaire of the suite and of ../shared, within the derived bound.
#include "math/kmath.h"
#include "photometry/load.h"
#include "photometry/lut.h"
#include "photometry/synth.h"
#include "testutil.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

namespace lb::photometry {
namespace {

namespace fs = std::filesystem;

TEST(Lut, PseudoAnglesRoundTripAndAreMonotonic)
{
    // Inverses to ~1e-12 deg (atan2 and the rational pseudo-angles in double).
    double prevQ = -1, prevA = -1;
    for (int i = 0; i <= 1800; ++i) {
        double g = i * 0.1;
        double q = pseudoGamma(g);
        EXPECT_NEAR(gammaOfPseudo(q), g, 1e-9) << g;
        EXPECT_GT(q, prevQ) << g;
        prevQ = q;
    }
    EXPECT_NEAR(pseudoGamma(90), 1.0, 1e-15);
    for (int i = 0; i < 3600; ++i) {
        double c = i * 0.1;
        double a = pseudoAzimuth(c);
        EXPECT_NEAR(azimuthOfPseudo(a), c, 1e-9) << c;
        EXPECT_GT(a, prevA) << c;
        prevA = a;
    }
}

// Every luminaire file we have: the suite's own and ../shared's.
std::vector<std::string> allLuminaires()
{
    std::vector<std::string> files;
    auto scan = [&](const fs::path& dir) {
        if (!fs::is_directory(dir)) return;
        for (auto& e : fs::recursive_directory_iterator(dir)) {
            auto ext = e.path().extension().string();
            std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
            if (ext == ".ldt" || ext == ".ies") files.push_back(e.path().string());
        }
    };
    scan(fs::path(test::sourceDir()) / "luminaires");
    if (!test::sharedDir().empty()) scan(fs::path(test::sharedDir()) / "luminaires");
    std::sort(files.begin(), files.end());
    return files;
}

// Max |LUT - exact| over 20000 random directions (uniform on the sphere) plus
// directions at the file's own nodes, evaluated as a float kernel would.
double maxError(const Table& t, const Lut& lut, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> g;
    double worst = 0;
    const auto packed = t.packed();
    auto check = [&](double x, double y, double z) {
        double gamma = std::atan2(std::hypot(x, y), z) * 180 / M_PI;
        double c = std::atan2(y, x) * 180 / M_PI;
        if (c < 0) c += 360;
        double exact = f64::lb_intensity_cg(packed.data(), c, gamma);
        double fast = f32::lb_lut_intensity3(lut.packed.data(), float(x), float(y), float(z));
        worst = std::max(worst, std::fabs(fast - exact));
    };
    for (int i = 0; i < 20000; ++i) check(g(rng), g(rng), g(rng));
    for (double c : t.c)
        for (double gm : t.gamma) {
            double cr = c * M_PI / 180, gr = gm * M_PI / 180;
            check(std::sin(gr) * std::cos(cr), std::sin(gr) * std::sin(cr), std::cos(gr));
        }
    return worst;
}

TEST(Lut, ErrorWithinDerivedBoundForEveryLuminaire)
{
    auto files = allLuminaires();
    ASSERT_GE(files.size(), 18u) << "the suite's own 18 luminaire files";
    double worstRel = 0;
    std::string worstFile;
    for (const auto& f : files) {
        Table t = load(f);
        Lut lut = buildLut(t);
        double err = maxError(t, lut, 7);
        double maxCd = t.maxCd();
        // The bound of buildLut (Lipschitz constants x LUT cell size) plus
        // float rounding: values stored as float (2^-24 relative) and the
        // float pseudo-angles (a few ulp of q times the slope); 1e-5 of the
        // largest cd covers both with a margin of > 10x.
        EXPECT_LE(err, lut.errorBound + 1e-5 * maxCd) << f;
        // The pencil stress luminaire (a 0.4-degree beam) is narrower than a
        // LUT cell; its error (3.5 % of the peak) is within its derived bound,
        // checked above, but not the resolution claim below (docs/studies/robust.md).
        const bool subCell = fs::path(f).stem() == "pencil";
        if (!subCell && err / maxCd > worstRel) worstRel = err / maxCd, worstFile = f;
        std::printf("  %-60s max err %.2e of max cd (bound %.2e)%s\n", fs::path(f).filename().c_str(), err / maxCd,
                    lut.errorBound / maxCd, lut.rotational ? " rotational" : "");
    }
    // Resolution check: 256 x 512 cells keep every file but the pencil within
    // 2 % of its peak (the bound is ~2x pessimistic; the worst measured is printed).
    EXPECT_LT(worstRel, 0.02) << worstFile;
}

TEST(Lut, ExactAtMeasuredRangeEndsAndZeroOutside)
{
    // A downlight measured over 0..90 only: the LUT ends exactly there.
    Table t = tabulate([](double, double g) { return 100 + g; }, 5, 19, 0, 90);
    Lut lut = buildLut(t);
    EXPECT_TRUE(lut.rotational);  // f does not depend on C
    // gamma = 90 (z = 0): the last node holds I(90) = 190 exactly (float).
    EXPECT_NEAR(f32::lb_lut_intensity3(lut.packed.data(), 1.0f, 0.0f, 0.0f), 190.0, 190 * 1e-6);
    // Just past 90 deg: 0, as the exact lookup.
    EXPECT_EQ(f32::lb_lut_intensity3(lut.packed.data(), 1.0f, 0.0f, -1e-3f), 0.0f);
    // On the axis: I(0) = 100.
    EXPECT_NEAR(f32::lb_lut_intensity3(lut.packed.data(), 0.0f, 0.0f, 2.0f), 100.0, 100 * 1e-6);
}

TEST(Lut, CosineLobeWithinBound)
{
    // I = 1000 cos(gamma)+ : Sg = 1000 cd/rad (largest chord slope, at 90 deg),
    // Sc = 0 -> bound = 1000 * 2 * (q1 - q0 = 2) / 256.
    Table t = tabulate([](double, double g) { return std::max(0.0, 1000 * std::cos(g * M_PI / 180)); }, 2, 181);
    Lut lut = buildLut(t);
    EXPECT_TRUE(lut.rotational);
    EXPECT_NEAR(lut.errorBound, 1000.0 * 2 * 2 / 256,
                1000.0 * 2 * 2 / 256 * 0.02);  // Sg within 2 % of 1000 (chord slopes)
    EXPECT_LE(maxError(t, lut, 3), lut.errorBound + 1e-2);
}

TEST(Lut, SymmetryAnalysis)
{
    Table rot = tabulate([](double, double g) { return 1 + g; }, 7, 19);
    Table asym = tabulate([](double c, double g) { return 1 + g + c; }, 7, 19);
    Table front = tabulate([](double, double g) { return g < 90 ? 90 - g : 0.0; }, 3, 19);
    EXPECT_TRUE(isRotational(rot));
    EXPECT_FALSE(isRotational(asym));
    EXPECT_TRUE(emitsNoBack(front));
    EXPECT_FALSE(emitsNoBack(rot));
}

}  // namespace
}  // namespace lb::photometry
