// Error metrics on tiny images whose values are worked out by hand (docs/design.md section 5).
#include "metrics/metrics.h"
#include "util/error.h"

#include "testutil.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

namespace lb {
namespace {

Image img2x2(double a, double b, double c, double d)
{
    Image m(2, 2);
    m.px = {a, b, c, d};
    return m;
}

// R = [1 2; 3 4], A = [2 2; 2 6]: d = A - R = [1 0 -1 2], sum d^2 = 6, MSE = 3/2,
// mean R = 5/2, mean A = 3.
TEST(Metrics, HandComputedTwoByTwo)
{
    auto m = metrics::compare(img2x2(1, 2, 3, 4), img2x2(2, 2, 2, 6));
    // Every input is a small dyadic number, so sums and means are exact and each
    // metric is one or two correctly rounded operations away from the closed
    // form: 4 ulp (EXPECT_DOUBLE_EQ) is the right tolerance.
    EXPECT_DOUBLE_EQ(m.mean_ref, 2.5);
    EXPECT_DOUBLE_EQ(m.mean_test, 3.0);
    EXPECT_DOUBLE_EQ(m.nmse, 0.2);  // (3/2) / (5/2 * 3)
    EXPECT_DOUBLE_EQ(m.nrmse, std::sqrt(1.5) / 2.5);  // sqrt(3/2) / (5/2)
    // relMSE: eps = 1e-2 (5/2)^2 = 1/16; terms 1/(1 + 1/16) = 16/17, 0,
    // 1/(9 + 1/16) = 16/145, 4/(16 + 1/16) = 64/257; four pixels.
    EXPECT_DOUBLE_EQ(m.relmse, (16.0 / 17 + 16.0 / 145 + 64.0 / 257) / 4);
    EXPECT_EQ(m.ueb, 2.0);  // largest A - R, exact
    EXPECT_EQ(m.leb, -1.0);  // smallest A - R, exact (negative: thesis convention)
    EXPECT_EQ(m.nonfinite, 0);
    EXPECT_EQ(m.pixels, 4);
}

TEST(Metrics, IdenticalImagesGiveZero)
{
    Image r(5, 3);
    for (size_t i = 0; i < r.px.size(); ++i) r.px[i] = 0.3 + 1.7 * i;
    auto m = metrics::compare(r, r);
    // d = 0 exactly at every pixel, so every error is exactly 0.
    EXPECT_EQ(m.nmse, 0.0);
    EXPECT_EQ(m.nrmse, 0.0);
    EXPECT_EQ(m.relmse, 0.0);
    EXPECT_EQ(m.ueb, 0.0);
    EXPECT_EQ(m.leb, 0.0);
    EXPECT_EQ(m.pixels, 15);
}

// A = 2 R: d = R, so NMSE = mean(R^2) / (2 mean(R)^2) = (30/4) / (2 * 25/4) = 0.6:
// scaling only the test image is (rightly) not invariant.
TEST(Metrics, ScalingTheTestAloneIsAnError)
{
    auto m = metrics::compare(img2x2(1, 2, 3, 4), img2x2(2, 4, 6, 8));
    EXPECT_DOUBLE_EQ(m.nmse, 0.6);  // exact dyadic inputs: 4 ulp
    EXPECT_DOUBLE_EQ(m.nrmse, std::sqrt(7.5) / 2.5);  // sqrt(30/4) / (5/2)
    EXPECT_EQ(m.ueb, 4.0);
    EXPECT_EQ(m.leb, 0.0);  // nothing under-estimated: LEB is 0, not a positive number
}

// Scaling R and A by the same s leaves NMSE, NRMSE and relMSE unchanged (each is a
// ratio of two terms quadratic in s) and scales UEB and LEB by s (lux).
TEST(Metrics, ScalingBothImagesKeepsTheRelativeMetrics)
{
    Image r(4, 3), a(4, 3);
    for (size_t i = 0; i < r.px.size(); ++i) {
        r.px[i] = 1.0 + 0.37 * i + 0.05 * i * i;
        a.px[i] = r.px[i] * (1.0 + 0.1 * std::sin(1.3 * i));
    }
    const double s = 7.3;
    Image rs = r, as = a;
    for (auto& v : rs.px) v *= s;
    for (auto& v : as.px) v *= s;
    auto m = metrics::compare(r, a), ms = metrics::compare(rs, as);
    // The scaled sums differ from the exact s-multiples by a few rounding errors
    // of 12 terms: 1e-13 relative is ~500 ulp, far above that and far below any
    // real change (a 1% change in A moves NMSE by percent).
    EXPECT_NEAR(ms.nmse / m.nmse, 1.0, 1e-13);
    EXPECT_NEAR(ms.nrmse / m.nrmse, 1.0, 1e-13);
    EXPECT_NEAR(ms.relmse / m.relmse, 1.0, 1e-13);
    EXPECT_NEAR(ms.ueb / (s * m.ueb), 1.0, 1e-13);
    EXPECT_NEAR(ms.leb / (s * m.leb), 1.0, 1e-13);
    EXPECT_GT(m.nmse, 0.0);
    EXPECT_GT(m.ueb, 0.0);
    EXPECT_LT(m.leb, 0.0);
}

// Non-finite test pixels are counted and left out of every sum and mean:
// R = [1 2; 3 4], A = [2 NaN; 2 inf] is compared on R = [1 3], A = [2 2]:
// means 2 and 2, d = [1 -1], MSE 1, NMSE 1/4, NRMSE 1/2.
TEST(Metrics, NonFiniteTestPixelsAreCountedAndExcluded)
{
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    auto m = metrics::compare(img2x2(1, 2, 3, 4), img2x2(2, nan, 2, -inf));
    EXPECT_EQ(m.nonfinite, 2);
    EXPECT_EQ(m.pixels, 4);
    // Exact dyadic arithmetic again: 4 ulp.
    EXPECT_DOUBLE_EQ(m.mean_ref, 2.0);
    EXPECT_DOUBLE_EQ(m.mean_test, 2.0);
    EXPECT_DOUBLE_EQ(m.nmse, 0.25);
    EXPECT_DOUBLE_EQ(m.nrmse, 0.5);
    EXPECT_EQ(m.ueb, 1.0);
    EXPECT_EQ(m.leb, -1.0);

    // All pixels non-finite: nothing to average, every metric is NaN (not 0).
    auto all = metrics::compare(img2x2(1, 2, 3, 4), img2x2(nan, nan, inf, inf));
    EXPECT_EQ(all.nonfinite, 4);
    EXPECT_TRUE(std::isnan(all.nmse));
    EXPECT_TRUE(std::isnan(all.ueb));
    EXPECT_TRUE(std::isnan(all.mean_ref));
}

// grad_nmse (docs/design.md section 5) on R = [1 2; 3 4], A = [2 2; 2 6]: the pairs
// right and down have dR = 1, 1 (rows) and 2, 2 (columns), dA = 0, 4 and 0, 4,
// so (dR - dA)^2 = 1, 9, 4, 4: sum 18 over M = 4 pairs, 4.5 / (mean R mean A)
// = 4.5 / 7.5 = 0.6.
TEST(GradNmse, HandComputedTwoByTwo)
{
    auto m = metrics::compare(img2x2(1, 2, 3, 4), img2x2(2, 2, 2, 6));
    EXPECT_EQ(m.grad_pairs, 4);
    // Sum and quotient of small integers are exact; one rounding in the last division: 4 ulp.
    EXPECT_DOUBLE_EQ(m.grad_nmse, 0.6);
}

// Closed form on a W x H ramp: R = 1 + 2x, A = 2 + x (x the column). Every
// horizontal pair has dR = 2, dA = 1, so (dR - dA)^2 = 1 on its H (W - 1)
// pairs; every vertical pair has dR = dA = 0. With M = H (W - 1) + W (H - 1)
// and the means 1 + (W - 1) and 2 + (W - 1) / 2:
//   grad_nmse = H (W - 1) / M / ((1 + (W - 1)) (2 + (W - 1) / 2)).
// W = 4, H = 3: 9 / 17 / (4 * 3.5) = 9 / 238. NMSE sees a different number:
// d = 1 - x = [1 0 -1 -2] per row, mean d^2 = 6 / 4, NMSE = 1.5 / 14.
TEST(GradNmse, RampsOfTwoSlopesMatchTheClosedForm)
{
    const int W = 4, H = 3;
    Image r(W, H), a(W, H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            r.at(y, x) = 1 + 2 * x;
            a.at(y, x) = 2 + x;
        }
    auto m = metrics::compare(r, a);
    EXPECT_EQ(m.grad_pairs, H * (W - 1) + W * (H - 1));
    // Integer inputs: the sum of squared differences (9) and the means (4 and
    // 3.5) are exact; the two divisions round once each, the closed form
    // once: a few ulp apart, within EXPECT_DOUBLE_EQ's 4 ulp.
    EXPECT_DOUBLE_EQ(m.grad_nmse, 9.0 / 238.0);
    EXPECT_DOUBLE_EQ(m.nmse, 1.5 / 14.0);
}

// A constant offset is a smooth bias: every neighbour difference is the
// reference's, so grad_nmse is exactly 0, while NMSE is not:
// A = R + 5 on R = [1 2; 3 4] gives d = 5 everywhere, NMSE = 25 / (2.5 * 7.5).
TEST(GradNmse, DoesNotSeeAConstantOffsetWhileNmseDoes)
{
    auto m = metrics::compare(img2x2(1, 2, 3, 4), img2x2(6, 7, 8, 9));
    EXPECT_EQ(m.grad_nmse, 0.0);  // integers: every difference is exact
    EXPECT_DOUBLE_EQ(m.nmse, 25.0 / (2.5 * 7.5));  // one or two roundings: 4 ulp
    EXPECT_GT(m.nmse, 1.0);
}

// A bump (one pixel too bright in a smooth ramp) costs grad_nmse on each of
// its pairs; here R = 1..9 on 3 x 3 (row-major), A = R + 1 at (0, 0) and
// NaN at the centre (1, 1). The centre is counted as non-finite and its
// four pairs are left out: M = 12 - 4 = 8. The bump's two pairs each have
// (dR - dA)^2 = 1: sum 2. Means over the 8 finite pixels: R (45 - 5) / 8 = 5,
// A (40 + 1) / 8 = 41 / 8, so grad_nmse = (2 / 8) / (5 * 41 / 8) = 2 / 205.
TEST(GradNmse, NonFinitePixelsAndTheirPairsAreLeftOutAndCounted)
{
    Image r(3, 3), a(3, 3);
    for (size_t i = 0; i < 9; ++i) r.px[i] = a.px[i] = double(i + 1);
    a.px[0] += 1;
    a.px[4] = std::numeric_limits<double>::quiet_NaN();
    auto m = metrics::compare(r, a);
    EXPECT_EQ(m.nonfinite, 1);
    EXPECT_EQ(m.grad_pairs, 8);
    EXPECT_DOUBLE_EQ(m.mean_test, 41.0 / 8);  // exact sums of integers, one division
    EXPECT_DOUBLE_EQ(m.grad_nmse, 2.0 / 205);  // a few roundings of exact integers: 4 ulp
    // A corner pixel has two pairs only: M = 12 - 2.
    Image c = r;
    c.px[8] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(metrics::compare(r, c).grad_pairs, 10);
    // Nothing left to compare: NaN, never 0.
    EXPECT_TRUE(std::isnan(metrics::compare(Image(1, 1, 2.0), Image(1, 1, 3.0)).grad_nmse));
}

TEST(Metrics, MinimisableNamesEveryMetricAndRefusesOthers)
{
    auto m = metrics::compare(img2x2(1, 2, 3, 4), img2x2(2, 2, 2, 6));
    EXPECT_EQ(metrics::minimisable(m, "nmse"), m.nmse);
    EXPECT_EQ(metrics::minimisable(m, "grad_nmse"), m.grad_nmse);
    EXPECT_EQ(metrics::minimisable(m, "leb"), 1.0);  // the magnitude of LEB = -1
    for (const auto& k : metrics::minimisableMetrics()) EXPECT_NO_THROW(metrics::minimisable(m, k)) << k;
    std::string what = test::inputErrorOf([&] { metrics::minimisable(m, "psnr"); });
    EXPECT_NE(what.find("'psnr'"), std::string::npos) << what;
    EXPECT_NE(what.find("grad_nmse"), std::string::npos) << what;
}

TEST(Metrics, BadInputIsAnInputError)
{
    EXPECT_THROW(metrics::compare(Image(2, 2, 1.0), Image(2, 3, 1.0)), InputError);
    EXPECT_THROW(metrics::compare(Image(3, 2, 1.0), Image(2, 3, 1.0)), InputError);
    EXPECT_THROW(metrics::compare(Image(), Image()), InputError);
    try {
        metrics::compare(img2x2(1, std::numeric_limits<double>::quiet_NaN(), 3, 4), img2x2(1, 2, 3, 4));
        FAIL() << "a non-finite reference must be rejected";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("row 0, column 1"), std::string::npos) << e.what();
    }
}

TEST(Metrics, JsonHasTheDocumentedKeysAndRoundTrips)
{
    auto m = metrics::compare(img2x2(1, 2, 3, 4), img2x2(2, 2, 2, 6));
    nlohmann::json j = m;
    for (const char* k : {"nmse", "nrmse", "relmse", "ueb", "leb", "nonfinite", "pixels", "mean_ref", "mean_test",
                          "grad_nmse", "grad_pairs", "flip"})
        EXPECT_TRUE(j.contains(k)) << k;
    EXPECT_EQ(j.size(), 12u);
    EXPECT_TRUE(j["flip"].is_null());  // compare() does not compute FLIP: null, not 0
    EXPECT_EQ(j["nmse"].get<double>(), m.nmse);
    // A dump and parse keeps doubles exactly (nlohmann writes 17 significant digits).
    auto back = nlohmann::json::parse(j.dump()).get<metrics::Metrics>();
    EXPECT_EQ(back.nmse, m.nmse);
    EXPECT_EQ(back.relmse, m.relmse);
    EXPECT_EQ(back.leb, m.leb);
    EXPECT_EQ(back.pixels, 4);
    EXPECT_EQ(back.grad_nmse, m.grad_nmse);
    EXPECT_EQ(back.grad_pairs, 4);

    // A record of an older file has no grad_nmse or flip: they read as NaN.
    nlohmann::json old = j;
    old.erase("grad_nmse");
    old.erase("grad_pairs");
    old.erase("flip");
    auto o = old.get<metrics::Metrics>();
    EXPECT_TRUE(std::isnan(o.grad_nmse));
    EXPECT_TRUE(std::isnan(o.flip));
    EXPECT_EQ(o.nmse, m.nmse);

    // Undefined values are null, and come back as NaN.
    metrics::Metrics u;
    u.nmse = std::numeric_limits<double>::quiet_NaN();
    u.nrmse = std::numeric_limits<double>::infinity();
    nlohmann::json ju = u;
    EXPECT_TRUE(ju["nmse"].is_null());
    EXPECT_TRUE(ju["nrmse"].is_null());
    EXPECT_TRUE(std::isnan(ju.get<metrics::Metrics>().nmse));
}

}  // namespace
}  // namespace lb
