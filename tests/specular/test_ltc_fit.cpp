// The LTC fit's options (host/ltc/ltc.h): the free frame and the L1 objective
// against Heitz's fixed frame and cubed error on a small fit, the committed
// table's smoothness between its nodes, its albedo, the table file's round
// trip.
#include "ltc/ltc.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace lb {
namespace {

ltc::Table smallFit(ltc::Frame f, ltc::Objective o)
{
    // 4 x 4 cells: sqrt(alpha) 0, 1/3, 2/3, 1 and theta_o 0, 30, 60, 90 deg;
    // 16 samples per side (the fit's error is a 2 x 256-point estimate)
    ltc::FitOptions opt;
    opt.size = 4;
    opt.samples = 16;
    opt.normPanels = 16;
    opt.frame = f;
    opt.objective = o;
    return ltc::fit(opt);
}

double l1At(const ltc::Table& t, int i, int j)
{
    const ltc::Cell& c = t.at(i, j);
    double m[5] = {c.m00, c.m02, c.m20, c.m22, c.norm};
    return ltc::l1Distance(m, t.alpha(i), t.theta(j), 64);
}

TEST(LtcFit, FreeFrameImprovesOnTheFixedFrame)
{
    // The free frame's family contains the fixed frame's (phi at the mean
    // direction), and the fit starts each cell from a nearby point, so with
    // the same objective it ends at most at the fixed frame's error: asserted
    // with 1 % slack for Nelder-Mead stopping at its tolerance (measured: 35 %
    // to 8x lower at alpha 0.11 and 0.44, equal to 0.2 % at alpha 1). The L1
    // fit with the free frame lowers the independent L1 distance (64^2
    // samples from each of the BRDF and the LTC, not the fit's 16^2) at the
    // glossy cells, measured 0.023 -> 0.017 (alpha 0.11, 30 deg), 0.139 ->
    // 0.093 (0.11, 60), 0.104 -> 0.048 (0.44, 30), 0.259 -> 0.108 (0.44, 60):
    // asserted to fall by 15 % at least (the smallest measured fall: 25 %); at
    // alpha 1 the lobe is wide and the fixed frame already fits (0.034 and
    // 0.052 both). Against the free frame with the cubed error the L1 fit's
    // L1 distance is lower at alpha < 1 (by 5-17 %) and 0.3 % higher at alpha
    // 1: asserted not above it by more than 3 % (the fit minimises its own
    // 2 x 256-sample estimate, which differs from this one by about that).
    ltc::Table fixed = smallFit(ltc::Frame::Fixed, ltc::Objective::L3);
    ltc::Table free3 = smallFit(ltc::Frame::Free, ltc::Objective::L3);
    ltc::Table free1 = smallFit(ltc::Frame::Free, ltc::Objective::L1);
    for (int i = 1; i < 4; ++i)
        for (int j = 1; j < 3; ++j) {
            EXPECT_LE(free3.at(i, j).error, 1.01 * fixed.at(i, j).error) << i << "," << j;
            double a = l1At(fixed, i, j), b = l1At(free1, i, j);
            double c = l1At(free3, i, j);
            if (i < 3) {
                EXPECT_LT(b, 0.85 * a) << "alpha " << fixed.alpha(i) << " theta " << fixed.theta(j);
            }
            EXPECT_LT(b, 1.03 * c) << "alpha " << fixed.alpha(i) << " theta " << fixed.theta(j);
            std::printf("alpha %.3f theta %.3f  L1 fixed/l3 %.4f  free/l3 %.4f  free/l1 %.4f\n", fixed.alpha(i),
                        fixed.theta(j), a, c, b);
        }
}

TEST(LtcFit, NormIsTheExactAlbedo)
{
    // The fit never rescales norm to absorb its shape error: every cell's
    // norm is the albedo quadrature's value (ltc::albedo, which
    // Ggx.EnergyAtMostOneAndAlbedoAgrees holds to an independent quadrature
    // at 2e-5), the same arithmetic: bit for bit.
    const ltc::Table& t = ltc::defaultTable();
    int n = t.options.size;
    for (int i = 0; i < n; i += 9)
        for (int j = 0; j < n; j += 13)
            EXPECT_EQ(t.at(i, j).norm, ltc::albedo(t.alpha(i), t.theta(j), t.options.normPanels)) << i << "," << j;
}

TEST(LtcFit, CommittedTableIsSmoothBetweenNodes)
{
    // Bilinear lookup is only as good as the parameters are smooth: at the
    // centre of a cell of the committed table (mid-way in sqrt(alpha) and in
    // theta_o) the L1 distance of the interpolated LTC stays near its four
    // corners'. Measured (every 4th cell with theta_o < 70 deg, alpha >=
    // 0.009, 32^2 samples) at most 0.0060 above the largest corner's, at the
    // glossiest row (alpha 0.009-0.012, corners' L1 < 0.02), where the lobe's
    // width changes by a third per cell and bilinear interpolation of any
    // table's matrices lags it: the fixed-frame table has the same excess
    // there (0.0059). Asserted 0.01. A jump of the fit between two local
    // minima shows as an excess of the size of the L1 distance itself
    // (0.05-0.3 at these cells).
    const ltc::Table& t = ltc::defaultTable();
    std::vector<float> buf = ltc::packed(t);
    int n = t.options.size;
    double worst = 0;
    for (int i = 6; i + 1 < n; i += 4)
        for (int j = 1; j + 1 < n && t.theta(j + 1) < 70 * M_PI / 180; j += 4) {
            double corner = 0, c[5];
            for (int di = 0; di < 2; ++di)
                for (int dj = 0; dj < 2; ++dj) {
                    ltc::lookup(buf, t.alpha(i + di), t.theta(j + dj), c);
                    corner = std::max(corner, ltc::l1Distance(c, t.alpha(i + di), t.theta(j + dj), 32));
                }
            double s = (i + 0.5) / (n - 1), alpha = s * s, theta = 0.5 * (t.theta(j) + t.theta(j + 1));
            ltc::lookup(buf, alpha, theta, c);
            double mid = ltc::l1Distance(c, alpha, theta, 32);
            worst = std::max(worst, mid - corner);
            EXPECT_LT(mid, corner + 0.01) << "cell " << i << "," << j;
        }
    std::printf("largest excess of the L1 distance at a cell centre over its corners: %.4f\n", worst);
}

TEST(LtcFit, MassBelowHorizonIsTheDensitysIntegral)
{
    // massBelowHorizon's closed form against int_{z < 0} D dw by the midpoint
    // rule in (z, phi) (dw = dz dphi), 400 x 800 points; D is smooth below the
    // horizon (its own horizon lies elsewhere), so the rule converges as h^2:
    // measured at most 1.7e-5 (alpha 0.05, theta_o 86 deg, where D peaks at
    // the horizon), 1e-6 elsewhere; asserted 1e-4. Cells of both committed
    // tables with 0.2-12 % of the mass below.
    for (const char* name : {"ggx.json", "ggx-fixed.json"}) {
        ltc::Table t = ltc::read(ltc::dataDir() + "/ltc/" + name);
        for (auto [i, j] : {std::pair{20, 30}, {31, 45}, {31, 55}, {45, 50}, {14, 60}}) {
            const ltc::Cell& c = t.at(i, j);
            double m[5] = {c.m00, c.m02, c.m20, c.m22, c.norm};
            const int nz = 400, np = 800;
            double sum = 0;
            for (int a = 0; a < nz; ++a)
                for (int b = 0; b < np; ++b) {
                    double z = -(a + 0.5) / nz, phi = 2 * M_PI * (b + 0.5) / np, r = std::sqrt(1 - z * z);
                    sum += ltc::ltcDensity(c, r * std::cos(phi), r * std::sin(phi), z);
                }
            sum *= 2 * M_PI / (double(nz) * np);
            double exact = ltc::massBelowHorizon(m);
            EXPECT_NEAR(exact, sum, 1e-4) << name << " " << i << "," << j;
            std::printf("%s cell %d,%d: below %.6f, quadrature %.6f\n", name, i, j, exact, sum);
        }
    }
}

TEST(LtcFit, TableFileRoundTrips)
{
    // toJson / read keep every number (round-trip precision) and the fit's
    // options, frame and objective included.
    ltc::FitOptions o;
    o.size = 3;
    o.samples = 8;
    o.normPanels = 8;
    o.frame = ltc::Frame::Fixed;
    o.objective = ltc::Objective::L1;
    ltc::Table t = ltc::fit(o);
    auto path = std::filesystem::temp_directory_path() / "lumibench-ltc-roundtrip.json";
    ltc::write(t, path.string());
    ltc::Table r = ltc::read(path.string());
    std::filesystem::remove(path);
    EXPECT_EQ(r.options.size, 3);
    EXPECT_EQ(r.options.samples, 8);
    EXPECT_EQ(r.options.normPanels, 8);
    EXPECT_TRUE(r.options.frame == ltc::Frame::Fixed);
    EXPECT_TRUE(r.options.objective == ltc::Objective::L1);
    ASSERT_EQ(r.cells.size(), t.cells.size());
    for (size_t k = 0; k < t.cells.size(); ++k) {
        const ltc::Cell &a = t.cells[k], &b = r.cells[k];
        for (auto m :
             {&ltc::Cell::m00, &ltc::Cell::m02, &ltc::Cell::m20, &ltc::Cell::m22, &ltc::Cell::norm, &ltc::Cell::error,
              &ltc::Cell::l1, &ltc::Cell::m11, &ltc::Cell::m22p, &ltc::Cell::m13, &ltc::Cell::phi})
            EXPECT_EQ(a.*m, b.*m) << k;
        // a version-1 file has no phi: read recovers it from M^-1 (M's first
        // column is m11 X, X = (cos phi, 0, -sin phi)); rounding only
        EXPECT_NEAR(std::atan2(a.m20, a.m22), a.phi, 1e-12) << k;
    }
}

TEST(LtcFit, FixedFrameTableReadsAsHeitzsFit)
{
    // data/ltc/ggx-fixed.json (version 1, the fit before the frame was
    // freed) reads as frame fixed, objective l3.
    ltc::Table t = ltc::read(ltc::dataDir() + "/ltc/ggx-fixed.json");
    EXPECT_TRUE(t.options.frame == ltc::Frame::Fixed);
    EXPECT_TRUE(t.options.objective == ltc::Objective::L3);
    EXPECT_EQ(t.options.size, 64);
}

}  // namespace
}  // namespace lb
