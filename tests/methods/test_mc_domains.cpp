// mc's sampling domains and per-pixel sequences in the kernel (kernels/mc.cl,
// common/mc_sample.h): unbiased over seeds at the 1/sqrt(R) rate, the
// low-discrepancy sequences below random, a Lambertian emitter at zero
// variance under projected sampling, the specialised kernels equal to the
// general one, and the paper's preset.
#include "methods/analytic.h"
#include "methods/closed_form.h"
#include "methods/samples.h"
#include "metrics/metrics.h"
#include "methods/mc_denoise.h"
#include "methods/render.h"
#include "methods/render_helpers.h"
#include "photometry/load.h"
#include "photometry/table.h"
#include "test_tables.h"
#include "testutil.h"
#include "util/error.h"

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

struct SeedStats {
    double z2 = 0;  // mean over pixels of ((mean - ref) / (sd / sqrt(R)))^2
    double mse4 = 0, mse16 = 0;  // MSE of the mean of 4 seeds (average of 4 groups), of all 16
};

// z^2 over R seeds (R >= 16), the MSEs over the first 16.
SeedStats seedStats(ocl::Runtime& rt, const photometry::Table& t, const Scene& sc, const Image& ref,
                    const std::string& spec, int R = 16)
{
    std::vector<Image> img;
    for (int s = 1; s <= R; ++s) img.push_back(run(rt, t, sc, fmt::format("{},seed={}", spec, s)).image);
    SeedStats st;
    const size_t np = ref.px.size();
    for (size_t i = 0; i < np; ++i) {
        double m = 0, m2 = 0, m16 = 0;
        for (auto& im : img) m += im.px[i] / R;
        for (auto& im : img) m2 += (im.px[i] - m) * (im.px[i] - m) / (R - 1);
        for (int k = 0; k < 16; ++k) m16 += img[k].px[i] / 16;
        double e = m - ref.px[i];
        // pixels where every seed agrees (no variance): the error must be
        // rounding only; they count as z = 0 when it is
        st.z2 += m2 > 0 ? e * e / (m2 / R) / np : (std::fabs(e) <= 1e-9 * std::fabs(ref.px[i]) + 1e-12 ? 0 : 1e9);
        st.mse16 += (m16 - ref.px[i]) * (m16 - ref.px[i]) / np;
        for (int g = 0; g < 4; ++g) {
            double mg = 0;
            for (int k = 0; k < 4; ++k) mg += img[4 * g + k].px[i] / 4;
            st.mse4 += (mg - ref.px[i]) * (mg - ref.px[i]) / np / 4;
        }
    }
    return st;
}

// The seed tests' bounds per case (z^2 of the seed mean, MSE(4) / MSE(16):
// their reasons at MeanOverSeedsConvergesToReference) and the geometric mean
// of the ratios over the cases.
struct RateTally {
    double logRatio = 0;
    int cases = 0;
    void add(const SeedStats& st, const std::string& what)
    {
        const double ratio = st.mse4 / st.mse16;
        EXPECT_LE(st.z2, 1.8) << what;
        EXPECT_GE(ratio, 1.2) << what;
        EXPECT_LE(ratio, 20) << what;
        logRatio += std::log(ratio);
        ++cases;
    }
    // The geometric mean of the ratios, printed and held to [lo, hi].
    void expectGeomean(const char* label, double lo, double hi) const
    {
        const double gm = std::exp(logRatio / cases);
        std::printf("%sgeometric mean of MSE(4) / MSE(16): %.2f\n", label, gm);
        EXPECT_GE(gm, lo);
        EXPECT_LE(gm, hi);
    }
};

// The mean over R seeds converges to the reference: the per-pixel z^2 of the
// seed mean averages ~ E[t^2] = 15/13 for Student's t with 15 degrees of
// freedom (pixels are near-independent); a bias of a tenth of the spread of
// one seed's estimate adds 16 * 0.01 = 0.16, a third adds 1.8 (measured:
// 1.05-1.52 over the 18 cases). The 1/sqrt(R) rate: the MSE of the seed mean
// falls 4x from 4 to 16 seeds. One case's ratio scatters widely where a few
// pixels near the light's plane dominate the MSE (measured 1.6-13.4), so the
// rate is held on the geometric mean over all cases (measured 4.3), each
// case only to [1.2, 20].
TEST(McDomains, MeanOverSeedsConvergesToReference)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "no fp64";
    auto t = lumpy();
    struct S {
        double h, rot;
    };
    RateTally tally;
    for (S s : {S{1.1, 3 * M_PI / 4}, S{0.1, M_PI / 2}}) {
        Scene sc = scene(s.h, s.rot, 12);
        Image ref = run(*rt, t, sc, "reference:tol=1e-7").image;
        for (const char* spec : {"mc:n=4,domain=area,sequence=random", "mc:n=4,domain=solid,sequence=sobol",
                                 "mc:n=4,domain=solid,sequence=zsobol,cosine_warp=1",
                                 "mc:n=4,domain=projected,sequence=random", "mc:n=4,domain=projected,sequence=zsobol",
                                 "mc:n=4,domain=mis,sequence=sobol", "mc:n=5,domain=mis,sequence=random,mis_split=0.4",
                                 "mc:n=4,paper=1", "mc:n=4,domain=solid,sequence=random,min_solid=0.5"}) {
            SeedStats st = seedStats(*rt, t, sc, ref, spec);
            double ratio = st.mse4 / st.mse16;
            std::printf("%-56s h %.1f: z^2 %.3f, MSE(4) / MSE(16) %.2f\n", spec, s.h, st.z2, ratio);
            // 144 pixels: the mean z^2 scatters by ~ sqrt(2 / 144) ~ 0.12
            // around 1.15 (more with the heavy tails near the light's
            // plane); 1.8 leaves room and still catches a third of a sigma
            tally.add(st, fmt::format("{} h {}", spec, s.h));
        }
    }
    // 18 cases: the log of the mean scatters by ~ 0.5 / sqrt(18) ~ 0.12
    tally.expectGeomean("", 3.0, 5.5);
}

// The table samplers (domain=table, mis_table: common/mc_table.h) are
// unbiased at the 1/sqrt(R) rate, as MeanOverSeedsConvergesToReference holds
// the others (its bounds and their reasons): 12 cases, so the geometric mean's
// log scatters by ~ 0.5 / sqrt(12) ~ 0.14 and its bounds widen to [2.5, 6.5]
// (min_solid=0.5: the solid-angle technique falls back to area sampling in
// most pixels, its density converted to solid angle).
// z^2 over 64 seeds (E[t^2] = 63/61): the table sampler alone rejects most
// of its directions where the light is a thin sliver of its window (the
// horizon clip at h 1.1 R 3pi/4: 232 of 256 seeds' 4 samples all missed in
// one pixel), so 16 seeds leave pixels with every seed 0 (no variance
// estimate) and heavy tails (mis_table, sobol: z^2 2.34 over 16 seeds, 1.15
// over 256; table, random: 1.10 over 256).

TEST(McDomains, TableSamplersConvergeToReference)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "no fp64";
    auto t = lumpy();
    RateTally tally;
    for (double h : {1.1, 0.1}) {
        Scene sc = scene(h, h > 1 ? 3 * M_PI / 4 : M_PI / 2, 12);
        Image ref = run(*rt, t, sc, "reference:tol=1e-7").image;
        for (const char* spec :
             {"mc:n=4,domain=table,sequence=random", "mc:n=4,domain=table,sequence=sobol",
              "mc:n=4,domain=mis_table,sequence=sobol", "mc:n=5,domain=mis_table,sequence=zsobol,mis_split=0.4",
              "mc:n=4,domain=mis_table_solid,sequence=sobol",
              "mc:n=5,domain=mis_table_solid,sequence=random,mis_split=0.6,min_solid=0.5"}) {
            SeedStats st = seedStats(*rt, t, sc, ref, spec, 64);
            double ratio = st.mse4 / st.mse16;
            std::printf("%-56s h %.1f: z^2 %.3f, MSE(4) / MSE(16) %.2f\n", spec, h, st.z2, ratio);
            tally.add(st, fmt::format("{} h {}", spec, h));
        }
    }
    tally.expectGeomean("", 2.5, 6.5);
}

double mseOverSeeds(ocl::Runtime& rt, const photometry::Table& t, const Scene& sc, const Image& ref,
                    const std::string& spec, int seeds)
{
    double m = 0;
    for (int s = 1; s <= seeds; ++s) {
        Image a = run(rt, t, sc, fmt::format("{},seed={}", spec, s)).image;
        for (size_t i = 0; i < a.px.size(); ++i) m += (a.px[i] - ref.px[i]) * (a.px[i] - ref.px[i]);
    }
    return m / (seeds * static_cast<double>(ref.px.size()));
}

// The disk light (shape=disk) at the scenes of MeanOverSeedsConvergesToReference.
Scene diskScene(double h, double rot, int res)
{
    Scene sc = scene(h, rot, res);
    sc.shape = LightShape::Disk;
    return sc;
}

// Solid-angle sampling of the disk (common/disk_sample.h) with every
// sequence, the paper's preset and the area fallback (min_solid=0.5: most
// pixels of the h 1.1 scene) is unbiased at the 1/sqrt(R) rate, held as
// MeanOverSeedsConvergesToReference holds the rectangle's domains (its
// bounds and their reasons; 12 cases, so the geometric mean's bounds are
// TableSamplersConvergeToReference's [2.5, 6.5]). At h 0.1 R pi/2 the horizon
// cuts the disk: the samples below it count 0.
TEST(McDomains, DiskSolidAngleConvergesToReference)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "no fp64";
    auto t = lumpy();
    RateTally tally;
    for (double h : {1.1, 0.1}) {
        Scene sc = diskScene(h, h > 1 ? 3 * M_PI / 4 : M_PI / 2, 12);
        Image ref = run(*rt, t, sc, "reference:tol=1e-7").image;
        for (const char* spec :
             {"mc:n=4,domain=solid,sequence=random", "mc:n=4,domain=solid,sequence=sobol",
              "mc:n=4,domain=solid,sequence=zsobol", "mc:n=4,domain=solid,pattern=stratified,shift=1", "mc:n=4,paper=1",
              "mc:n=5,domain=solid,sequence=random,min_solid=0.5"}) {
            SeedStats st = seedStats(*rt, t, sc, ref, spec);
            double ratio = st.mse4 / st.mse16;
            std::printf("disk %-50s h %.1f: z^2 %.3f, MSE(4) / MSE(16) %.2f\n", spec, h, st.z2, ratio);
            tally.add(st, fmt::format("{} h {}", spec, h));
        }
    }
    tally.expectGeomean("disk: ", 2.5, 6.5);
}

// A Lambertian downlight disk (cos1, R pi): uniform in solid angle leaves
// only the receiver cosine and the angular table's error (the weight's
// relative spread, DiskMc.*) to vary, where area sampling's 1 / r^2 varies
// by (1 + (D / 2h)^2)^2 = 26x over the disk under its centre at h 0.1.
// Measured MSE solid / area (8 seeds, random sequence, 16^2 pixels over 5 x
// 5 m): 0.054 (N 4) and 0.056 (N 16) at h 0.1, 0.17 and 0.19 at h 1.1. The
// MSE over 8 seeds scatters by some 30 %: the bounds 0.15 and 0.4 keep 2x
// to the measurements and fail a sampler no better than area (ratio 1).
TEST(McDomains, DiskSolidAngleBelowAreaOnLambertian)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "no fp64";
    auto t = methods::loadLuminaire("analytic:cos1");
    for (double h : {0.1, 1.1}) {
        Scene sc = diskScene(h, M_PI, 16);
        Image ref = run(*rt, t, sc, "reference:tol=1e-7").image;
        for (int n : {4, 16}) {
            double area = mseOverSeeds(*rt, t, sc, ref, fmt::format("mc:n={},sequence=random", n), 8);
            double solid = mseOverSeeds(*rt, t, sc, ref, fmt::format("mc:n={},domain=solid,sequence=random", n), 8);
            std::printf("Lambertian disk h %.1f N %d: MSE solid / area %.4f\n", h, n, solid / area);
            EXPECT_LE(solid, (h < 1 ? 0.15 : 0.4) * area) << "h " << h << " N " << n;
        }
    }
}

// At equal N = 16 (a (0, 4, 2)-net per pixel) Owen-scrambled Sobol and
// ZSobol have lower variance than independent points: for a smooth
// integrand a scrambled net's variance falls as N^-3 (log N) against N^-1,
// an order of magnitude here; the table's kinks and the horizon keep it from
// that. Measured (8 seeds): solid 0.002 / 0.002, projected 0.035 / 0.045,
// area 0.009 / 0.006; the bound 0.2 keeps a wide margin to them and to 1.
// A concentrated profile: luminaires/pencil.ldt (a Gaussian beam of sigma
// 0.4 degrees) under the 1 m light at h 1.1. A pixel under the light gets its
// light from the few square centimetres of the light within ~1.5 degrees of
// its zenith: projected sampling spreads its samples over the light's whole
// solid angle and rarely lands there, the table sampler puts most of them
// there. The beam's cone (~2 pi sigma^2 = 3e-4 sr) is ~5e-4 of the light's
// ~0.6 sr: projected's variance is of the order of mean^2 / 5e-4, so a
// sampler that finds the beam is 2-3 orders of magnitude below it. Measured
// (4 seeds, 16^2): MSE table / projected 3.0e-5, mis_table (half of the
// samples projected) / projected 9.3e-5, mis_table_solid 8.1e-5; the bounds
// 1e-3 and 1e-2 keep 30x and 100x to them and fail a sampler that misses
// the beam.
TEST(McDomains, TableSamplerFarBelowProjectedOnAPencilBeam)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "no fp64";
    auto t = photometry::load(test::sourceDir() + "/luminaires/pencil.ldt");
    Scene sc = scene(1.1, M_PI, 16);
    Image ref = run(*rt, t, sc, "reference:tol=1e-6").image;
    double proj = mseOverSeeds(*rt, t, sc, ref, "mc:n=4,domain=projected,sequence=sobol", 4);
    double table = mseOverSeeds(*rt, t, sc, ref, "mc:n=4,domain=table,sequence=sobol", 4);
    double mis = mseOverSeeds(*rt, t, sc, ref, "mc:n=4,domain=mis_table,sequence=sobol", 4);
    double mss = mseOverSeeds(*rt, t, sc, ref, "mc:n=4,domain=mis_table_solid,sequence=sobol", 4);
    std::printf("pencil h 1.1 R pi, N 4, sobol: MSE table / projected %.2e, mis_table / projected %.2e, "
                "mis_table_solid / projected %.2e\n",
                table / proj, mis / proj, mss / proj);
    EXPECT_LE(table, 1e-3 * proj);
    EXPECT_LE(mis, 1e-2 * proj);
    EXPECT_LE(mss, 1e-2 * proj);
}

TEST(McDomains, SobolAndZSobolBelowRandomAtEqualN)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "no fp64";
    auto t = lumpy();
    Scene sc = scene(1.1, 3 * M_PI / 4, 12);
    Image ref = run(*rt, t, sc, "reference:tol=1e-7").image;
    for (const char* domain : {"solid", "projected", "area"}) {
        auto spec = [&](const char* seq) { return fmt::format("mc:n=16,domain={},sequence={}", domain, seq); };
        double r = mseOverSeeds(*rt, t, sc, ref, spec("random"), 8);
        double s = mseOverSeeds(*rt, t, sc, ref, spec("sobol"), 8);
        double z = mseOverSeeds(*rt, t, sc, ref, spec("zsobol"), 8);
        std::printf("%s: MSE sobol / random %.3f, zsobol / random %.3f\n", domain, s / r, z / r);
        EXPECT_LE(s, 0.2 * r) << domain;
        EXPECT_LE(z, 0.2 * r) << domain;
    }
}

// I = I0 cos(gamma): f / p = Phi I0 / A for every projected sample, whatever
// the sequence (zero variance). The table's linear interpolation of cos on a
// 1-degree grid is off by at most (1 deg)^2 / 8 = 3.8e-5 relative (cos'' =
// -cos), so per pixel every seed agrees to 1e-4, and the mean is the closed
// form to the same. Area sampling of the same light scatters by far more
// (checked, so that the test sees a sampler that ignores the seed).
// The shared best-candidate set (mc's default, sequence=shared,
// pattern=poisson): every point uniform on the light over seeds, so MCI-N is
// unbiased and its expected NMSE falls with N. With plain (not toroidal)
// distances the edge band held 1.6x its share of the points (0.198 against
// 0.121 at N = 64) and the mean NMSE over seeds rose from N = 32 to 64 on a
// real luminaire (docs/mc-baselines.md).
TEST(McDomains, SharedPoissonSetIsUniformAndItsExpectedNmseFallsWithN)
{
    {
        const int n = 64, seeds = 256;
        const double band = 0.25 / std::sqrt(double(n)), share = 1 - (1 - 2 * band) * (1 - 2 * band);
        double inBand = 0;
        for (int seed = 0; seed < seeds; ++seed) {
            auto st = methods::samplePoints("poisson", n, seed);
            for (size_t k = 0; k < st.size(); k += 2)
                inBand += std::min({st[k], 1 - st[k], st[k + 1], 1 - st[k + 1]}) < band;
        }
        const double frac = inBand / (n * seeds), sigma = std::sqrt(share * (1 - share) / (n * seeds));
        std::printf("edge band: %.4f of the points, uniform %.4f (sigma %.4f)\n", frac, share, sigma);
        // 5 binomial sigmas (0.014, a tenth of the share); the points of one
        // set are not independent, but repel, which narrows the spread
        EXPECT_NEAR(frac, share, 5 * sigma);
    }
    LB_REQUIRE_RUNTIME(rt);
    auto t = methods::loadLuminaire(test::sourceDir() + "/luminaires/spot.ldt");
    const Precision p = rt->fp64() ? Precision::Double : Precision::Float;
    Scene sc = scene(1.1, M_PI / 2, 32);
    Image ref = run(*rt, t, sc, "reference", p).image;
    std::vector<double> mean;
    for (int n : {8, 16, 32, 64, 128}) {
        double m = 0;
        for (int seed = 0; seed < 16; ++seed)
            m += metrics::compare(ref, run(*rt, t, sc, fmt::format("mc:n={},seed={}", n, seed), p).image).nmse / 16;
        std::printf("mc:n=%d: mean NMSE over 16 seeds %.4f\n", n, m);
        if (!mean.empty()) {
            EXPECT_LT(m, mean.back()) << "n=" << n;  // falls at every doubling
        }
        mean.push_back(m);
    }
    // An unbiased MCI falls as 1 / N, a well-spread set faster (measured here:
    // 80.8, 16.8, 5.8, 3.2, 1.4, slope -1.45); the old edge-heavy set
    // rose between 32 and 64. -0.8 over the four doublings: the seeds' mean
    // has a standard error of ~ 25 % at each N.
    EXPECT_LT(std::log(mean.back() / mean.front()) / std::log(16.0), -0.8);
}

TEST(McDomains, LambertianEmitterHasZeroVarianceUnderProjected)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "no fp64";
    const double i0 = 1000;
    auto t =
        photometry::tabulate([&](double, double g) { return g < 90 ? i0 * std::cos(g * M_PI / 180) : 0.0; }, 2, 181);
    for (double rot : {3 * M_PI / 4, M_PI / 2}) {
        Scene sc = scene(0.1, rot, 10);
        std::vector<Image> proj, area;
        for (int s = 1; s <= 6; ++s) {
            proj.push_back(
                run(*rt, t, sc, fmt::format("mc:n=2,domain=projected,sequence=random,lookup=exact,seed={}", s)).image);
            area.push_back(
                run(*rt, t, sc, fmt::format("mc:n=2,domain=area,sequence=random,lookup=exact,seed={}", s)).image);
        }
        double worstSpread = 0, worstClosed = 0, areaSpread = 0;
        for (int row = 0; row < sc.res; ++row)
            for (int col = 0; col < sc.res; ++col) {
                size_t i = static_cast<size_t>(row) * sc.res + col;
                double want = test::cosnIrradiance(sc, 1, i0, sc.pixel(row, col));
                double lo = 1e300, hi = -1e300, alo = 1e300, ahi = -1e300;
                for (auto& im : proj) lo = std::min(lo, im.px[i]), hi = std::max(hi, im.px[i]);
                for (auto& im : area) alo = std::min(alo, im.px[i]), ahi = std::max(ahi, im.px[i]);
                if (want <= 0) {
                    EXPECT_EQ(hi, 0.0) << row << "," << col;
                    continue;
                }
                worstSpread = std::max(worstSpread, (hi - lo) / want);
                worstClosed = std::max(worstClosed, std::fabs(proj[0].px[i] - want) / want);
                areaSpread = std::max(areaSpread, (ahi - alo) / want);
            }
        std::printf("R %.3f: projected spread %.2e, vs closed form %.2e; area spread %.2e\n", rot, worstSpread,
                    worstClosed, areaSpread);
        // measured 3.4e-5 and 3.8e-5: the interpolation bound itself
        EXPECT_LE(worstSpread, 1e-4);
        EXPECT_LE(worstClosed, 1e-4);
        EXPECT_GE(areaSpread, 1e-2);
    }
}

// The a-trous filter holds a zero-variance image still: a Lambertian emitter
// under projected sampling with the exact lookup gives every sample the same
// value up to rounding, so every pixel's variance estimate is ~0 and the edge
// stop (sigma_l standard deviations) admits only neighbours within rounding.
// At h 0.1 the light's plane crosses the image: whole tiles behind it are 0
// without a sample loop and must report a variance of 0 too (unwritten, the
// buffer kept the previous launch's filtered variance of their lit
// neighbours, which the filter then let in); float sums of e^2 cancel to a
// spread ~ 1e-4 near the peak (a change of 1.1e-4 of the peak). Measured
// after: 2.3e-6 of the peak in float and double (the table's linear
// interpolation in gamma is real variance); the bound 1e-5.
TEST(McDomains, AtrousHoldsAZeroVarianceImageStill)
{
    LB_REQUIRE_RUNTIME(rt);
    const double i0 = 1000;
    auto t =
        photometry::tabulate([&](double, double g) { return g < 90 ? i0 * std::cos(g * M_PI / 180) : 0.0; }, 2, 181);
    Scene sc = scene(0.1, 3 * M_PI / 4, 64);
    const std::string base = "mc:n=8,domain=projected,sequence=random,lookup=exact,seed=5";
    for (Precision p : {Precision::Float, Precision::Double}) {
        if (p == Precision::Double && !rt->fp64()) continue;
        // timed launches after the first: each filtered launch leaves the
        // filtered variance of the lit neighbours in the variance buffer
        methods::RenderOptions opt;
        opt.reps = 3;
        opt.useCache = false;
        Image raw = run(*rt, t, sc, base, p).image;
        Image flt = methods::render(*rt, t, sc, methods::parseSpec(base + ",denoise=atrous", sc.kind), p, opt).image;
        double peak = *std::max_element(raw.px.begin(), raw.px.end()), worst = 0;
        size_t at = 0;
        for (size_t i = 0; i < raw.px.size(); ++i)
            if (std::fabs(flt.px[i] - raw.px[i]) > worst) worst = std::fabs(flt.px[i] - raw.px[i]), at = i;
        std::printf("%s: a-trous moved the zero-variance image by %.2e of its peak (pixel %zu)\n",
                    p == Precision::Float ? "float" : "double", worst / peak, at);
        EXPECT_LE(worst, 1e-5 * peak) << "pixel " << at;
    }
}

// Solid angle with the cosine warp on a constant-radiance (Lambertian)
// light: the remaining integrand is the receiver cosine, which the bilinear
// warp follows, so the variance drops far below plain solid-angle sampling.
TEST(McDomains, CosineWarpLowersSolidAngleVarianceOnLambertian)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "no fp64";
    auto t =
        photometry::tabulate([](double, double g) { return g < 90 ? 1000 * std::cos(g * M_PI / 180) : 0.0; }, 2, 181);
    Scene sc = scene(0.1, 3 * M_PI / 4, 10);
    Image ref = run(*rt, t, sc, "reference:tol=1e-7").image;
    double plain = mseOverSeeds(*rt, t, sc, ref, "mc:n=2,domain=solid,sequence=random,lookup=exact", 8);
    double warp = mseOverSeeds(*rt, t, sc, ref, "mc:n=2,domain=solid,sequence=random,lookup=exact,cosine_warp=1", 8);
    std::printf("Lambertian, h 0.1 R 3pi/4: MSE warp / plain %.3f\n", warp / plain);
    // the warp is exact for a bilinear cosine; measured 0.13, 0.5 separates
    // a working warp from none
    EXPECT_LE(warp, 0.5 * plain);
}

// Every specialised kernel (LUT 1D, no-back tile skip) renders what the
// general one renders: the dropped work is 0 or the identity; 1e-6 relative
// is ~8 float ulp (the straight-line form, a different kernel: below). Also
// the disk's solid-angle sampler (zsobol; paper=1).
TEST(McDomains, SpecialisedEqualsGeneral)
{
    LB_REQUIRE_RUNTIME(rt);
    auto front = photometry::tabulate(
        [](double, double g) { return g < 90 ? 500 * std::pow(std::cos(g * M_PI / 180), 3) : 0.0; }, 2, 91);
    auto check = [&](const Scene& sc, const char* spec) {
        auto gen = run(*rt, front, sc, std::string(spec) + ",specialize=none", Precision::Float);
        auto sp = run(*rt, front, sc, spec, Precision::Float);
        ASSERT_NE(sp.stats["defines"].get<std::string>().find("LB_NO_BACK"), std::string::npos) << spec;
        // the straight-line form is another kernel of the same code: the
        // bounds of test_mc_straight.cpp (projected's inversion 1e-4)
        const bool straight = sp.stats["defines"].get<std::string>().find("LB_MC_STRAIGHT") != std::string::npos;
        const double tol = straight ? (methods::test_tables::samplesProjected(spec) ? 1e-4 : 1e-5) : 1e-6;
        test::worstRelDiff(gen.image.px, sp.image.px, 1e-12, tol, spec);
    };
    for (const char* spec :
         {"mc:n=6,domain=solid,sequence=sobol,cosine_warp=1", "mc:n=6,domain=projected,sequence=zsobol",
          "mc:n=6,domain=mis,sequence=random", "mc:n=6,domain=area,sequence=sobol", "mc:n=6,paper=1",
          "mc:n=6,domain=table,sequence=sobol", "mc:n=6,domain=mis_table,sequence=random",
          "mc:n=6,domain=mis_table_solid,sequence=sobol"})
        check(scene(0.1, M_PI / 2, 24), spec);
    for (const char* spec : {"mc:n=6,domain=solid,sequence=zsobol", "mc:n=6,paper=1"})
        check(diskScene(0.1, M_PI / 2, 24), spec);
}

// paper=1 is exactly the spelled-out spec; it refuses keys it sets; the
// default mc keeps today's kernel (no extended path), so its images are
// those of before.
TEST(McDomains, PaperPresetAndDefaults)
{
    LB_REQUIRE_RUNTIME(rt);
    auto t = lumpy();
    Scene sc = scene(1.1, 3 * M_PI / 4, 12);
    auto a = run(*rt, t, sc, "mc:n=8,paper=1", Precision::Float);
    auto b = run(*rt, t, sc, "mc:n=8,domain=solid,pattern=halton,shift=1,min_solid=1e-3", Precision::Float);
    EXPECT_EQ(a.image.px, b.image.px);
    EXPECT_THROW(methods::parseSpec("mc:paper=1,domain=projected"), InputError);
    // a key at its default overrides nothing, so the canonical SPEC (every key written out) parses again
    const auto paper = methods::parseSpec("mc:paper=1");
    EXPECT_EQ(methods::parseSpec(paper.canonical()).values, paper.values);
    auto d = run(*rt, t, sc, "mc:n=8", Precision::Float);
    EXPECT_EQ(d.stats["defines"].get<std::string>().find("LB_MC_EXT"), std::string::npos);
    EXPECT_NE(a.stats["defines"].get<std::string>().find("LB_MC_EXT"), std::string::npos);
    // a seed changes every randomised sequence
    for (const char* seq : {"random", "sobol", "zsobol"}) {
        auto s1 = run(*rt, t, sc, fmt::format("mc:n=4,domain=solid,sequence={},seed=1", seq), Precision::Float);
        auto s2 = run(*rt, t, sc, fmt::format("mc:n=4,domain=solid,sequence={},seed=2", seq), Precision::Float);
        EXPECT_NE(s1.image.px, s2.image.px) << seq;
    }
}

// The filters as post-passes of the same method: gauss16 is the separable
// Gaussian of methods/mc_denoise.h (held to a host convolution of the
// unfiltered image, renormalised at the border as the kernel does); both
// filters lower a noisy image's error, the a-trous filter at n = 1 too; both
// are timed with the render (the record's stages denoise_*).
TEST(McDomains, DenoisePostPasses)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "no fp64";
    auto t = lumpy();
    Scene sc = scene(1.1, 3 * M_PI / 4, 128);
    const std::string base = "mc:n=4,domain=area,sequence=random,seed=3";
    Image raw = run(*rt, t, sc, base).image;
    auto g = run(*rt, t, sc, base + ",denoise=gauss16");
    const double sigma = methods::gaussSigmaPx(sc.res);
    const int rad = static_cast<int>(std::ceil(2 * sigma)), res = sc.res;
    auto blur = [&](const std::vector<double>& in, bool vertical) {
        std::vector<double> out(in.size());
        for (int r = 0; r < res; ++r)
            for (int c = 0; c < res; ++c) {
                double s = 0, ws = 0;
                for (int d = -rad; d <= rad; ++d) {
                    int cc = vertical ? c : c + d, rr = vertical ? r + d : r;
                    if (cc < 0 || rr < 0 || cc >= res || rr >= res) continue;
                    double w = std::exp(-0.5 * d * d / (sigma * sigma));
                    s += w * in[rr * res + cc];
                    ws += w;
                }
                out[r * res + c] = s / ws;
            }
        return out;
    };
    auto want = blur(blur(raw.px, false), true);
    double peak = *std::max_element(want.begin(), want.end());
    for (size_t i = 0; i < want.size(); ++i)
        ASSERT_NEAR(g.image.px[i], want[i], 1e-12 * peak) << i;  // double: rounding of 34 taps
    EXPECT_TRUE(g.stats["stage_ms"].contains("denoise_row"));
    EXPECT_TRUE(g.stats["stage_ms"].contains("denoise_col"));
    // on a noisy image both lower the error
    Image ref = run(*rt, t, sc, "reference:tol=1e-5").image;
    auto err = [&](const Image& im) {
        double m = 0;
        for (size_t i = 0; i < im.px.size(); ++i) m += (im.px[i] - ref.px[i]) * (im.px[i] - ref.px[i]);
        return m;
    };
    double e0 = err(raw), e1 = err(run(*rt, t, sc, base + ",denoise=atrous").image), eg = err(g.image);
    std::printf("128^2, area random n 4: squared error atrous / none %.3f, gauss16 / none %.3f\n", e1 / e0, eg / e0);
    // measured 0.051 (a-trous), 0.080 (gauss16) of the unfiltered error
    EXPECT_LT(e1, 0.3 * e0);
    EXPECT_LT(eg, 0.3 * e0);
    // at n = 1 the render has no variance: the a-trous filter runs on the
    // spatial estimate (7 x 7 moments) and acts; its bias: the means' ratio
    const std::string one = "mc:n=1,domain=area,sequence=random,seed=3";
    Image raw1 = run(*rt, t, sc, one).image;
    auto a1 = run(*rt, t, sc, one + ",denoise=atrous");
    double e10 = err(raw1), e11 = err(a1.image), m1 = 0, mr = 0;
    for (size_t i = 0; i < ref.px.size(); ++i) m1 += a1.image.px[i], mr += ref.px[i];
    std::printf("128^2, area random n 1: squared error atrous / none %.3f, mean / reference's %.4f\n", e11 / e10,
                m1 / mr);
    EXPECT_TRUE(a1.stats["stage_ms"].contains("denoise_var"));
    // measured 0.030; inert it would be 1
    EXPECT_LT(e11, 0.3 * e10);
}

}  // namespace
}  // namespace lb
