// equaltime::search on synthetic time models (no device): MC's time a known
// function of its sample count, the method's a constant, both slowed alike by
// a machine whose speed drifts 3x from round to round. The closed-form N_eq
// of each model is the expected answer; the drift checks that the verdict is
// the paired ratio, not two medians taken at different moments.
#include "equaltime/equaltime.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace lb {
namespace {

// A method of constant cost and MC of cost mcMs(N + extra), both times the
// machine's slowness of the current round (the method is launched first in
// each round: its launch count is the round index).
struct Model {
    double methodMs;
    std::function<double(double)> mcMs;
    bool fractional = true;
    std::function<double(double)> scaledMs{};  // MC at N = 1 and scale s (empty: none below N = 1)
    int methodLaunches = 0;
    int mcBuilds = 0;

    double drift() const { return 1.0 + std::fabs(std::sin(0.7 * methodLaunches)) * 2.0; }  // 1x .. 3x
    equaltime::Sides sides()
    {
        equaltime::Sides s;
        s.method = [this] {
            ++methodLaunches;
            return methodMs * drift();
        };
        s.mc = [this](long n, double extra) -> equaltime::Launch {
            ++mcBuilds;
            const double base = mcMs(double(n) + extra);
            return [this, base] { return base * drift(); };
        };
        s.fractional = fractional;
        if (scaledMs)
            s.scaled = [this](double scale) -> equaltime::Launch {
                ++mcBuilds;
                const double base = scaledMs(scale);
                return [this, base] { return base * drift(); };
            };
        return s;
    }
};

equaltime::Options tight()
{
    equaltime::Options o;
    o.tolerance = 0.02;
    o.rounds = 11;
    return o;
}

// t(N) = 0.05 + 0.1 N against 1 ms: N_eq = 9.5. No integer is within 2 %
// (N = 9: 0.95, N = 10: 1.05), so the fraction closes the step: the linear
// interpolation of the two paired ratios lands on 0.5 exactly. The fit the
// search starts from is wrong by 2x (t = 0.2 N: first aim N = 5), which the
// secant through the paired ratios corrects.
TEST(EqualTime, FindsTheFractionalCountBetweenBracketingIntegers)
{
    Model m{1.0, [](double n) { return 0.05 + 0.1 * n; }};
    const equaltime::Curve wrongFit = {{1, 0.2}, {32, 6.4}};
    const equaltime::Result r = equaltime::search(m.sides(), tight(), wrongFit, 1.0);
    EXPECT_EQ(r.n, 9);
    EXPECT_NEAR(r.extra, 0.5, 1e-9);
    EXPECT_NEAR(r.ratio, 1.0, 1e-9);  // the drift cancels in every round's ratio
    EXPECT_TRUE(r.ok);
    EXPECT_TRUE(r.bracketed);
    // the pair's two times come from the same rounds: their medians differ
    // from the models' constants by the drift, not their ratio
    EXPECT_NEAR(r.partner.median_ms / r.method.median_ms, 1.0, 1e-9);
    EXPECT_GT(r.method.max_ms / r.method.min_ms, 1.5) << "the model's drift reached the timings";
    EXPECT_GE(r.candidates.size(), 3u);
    EXPECT_TRUE(r.candidates.back().contains("extra"));
}

// The same model where MC has no fractional count: the closer integer in
// log, N = 10 (|log 1.05| = 0.0488 < |log 0.95| = 0.0513), flagged as off
// and bracketed.
TEST(EqualTime, WithoutAFractionTheClosestIntegerIsFlagged)
{
    Model m{1.0, [](double n) { return 0.05 + 0.1 * n; }, false};
    const equaltime::Result r = equaltime::search(m.sides(), tight(), {{1, 0.15}, {16, 1.65}}, 1.0);
    EXPECT_EQ(r.n, 10);
    EXPECT_EQ(r.extra, 0);
    EXPECT_NEAR(r.ratio, 1.05, 1e-9);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.bracketed);
}

// t proportional to N, 0.125 ms per sample, against 1 ms: N_eq = 8 exactly,
// found on the first try from a right fit, each N built once.
TEST(EqualTime, AnExactIntegerIsFoundOnTheFirstTry)
{
    Model m{1.0, [](double n) { return 0.125 * n; }};
    const equaltime::Result r = equaltime::search(m.sides(), tight(), {{1, 0.125}, {4, 0.5}, {64, 8.0}}, 1.0);
    EXPECT_EQ(r.n, 8);
    EXPECT_EQ(r.extra, 0);
    EXPECT_NEAR(r.ratio, 1.0, 1e-12);
    EXPECT_TRUE(r.ok);
    EXPECT_EQ(m.mcBuilds, 2);  // N = 8 and its neighbour towards the target
}

// A method faster than MC at N = 1: N_eq = 1, as close as MC can come, off.
TEST(EqualTime, AMethodFasterThanOneSampleGetsNOne)
{
    Model m{0.5, [](double n) { return 1.0 + 0.1 * n; }};
    const equaltime::Result r = equaltime::search(m.sides(), tight(), {{1, 1.1}, {8, 1.8}}, 0.5);
    EXPECT_EQ(r.n, 1);
    EXPECT_NEAR(r.ratio, 2.2, 1e-9);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.bracketed);
    EXPECT_EQ(m.mcBuilds, 1);  // N = 1 too slow: the search stops there (no N is faster), no N = 2 timed
}

// Below N = 1: MC at N = 1 and scale s costs 0.2 + 1.8 s^2 ms (a fixed
// share, the upsampling and launch, and the rest as the pixels), the method
// 1 ms, so s_eq = sqrt(0.8 / 1.8) = 0.6667. The first try takes time as the
// pixels, s^2 = 1 / ratio(1) = 1 / 2, s = 0.707 (3 decimals), and half of
// it, s = 0.5: ratios 0.2 + 1.8 x 0.499849 = 1.0997 and 0.65, both off by
// more than 2 %; they bracket 1, and the interpolation between them, on the
// model's line, aims at s^2 = 0.4444, s = 0.667: ratio 1.0008.
TEST(EqualTime, BelowOneSampleTheScaleIsSearched)
{
    Model m{1.0, [](double n) { return 1.9 + 0.1 * n; }};
    m.scaledMs = [](double s) { return 0.2 + 1.8 * s * s; };
    const equaltime::Result r = equaltime::search(m.sides(), tight(), {{1, 2.0}, {8, 2.7}}, 1.0);
    EXPECT_EQ(r.n, 1);
    EXPECT_EQ(r.extra, 0);
    EXPECT_NEAR(r.scale, 0.667, 1e-12);
    EXPECT_NEAR(r.ratio, 0.2 + 1.8 * 0.667 * 0.667, 1e-9);
    EXPECT_TRUE(r.ok);
    ASSERT_EQ(r.candidates.size(), 4u);  // N = 1, then three scales
    EXPECT_NEAR(r.candidates[1]["scale"].get<double>(), 0.707, 1e-12);
    EXPECT_NEAR(r.candidates[2]["scale"].get<double>(), 0.5, 1e-12);
    EXPECT_EQ(m.mcBuilds, 4);

    // a method faster than MC at the least scale: the scale's floor, off (the
    // line through the first two aims below 0, then the floor itself, then
    // the floor again: the search stops)
    Model fast{0.1, [](double n) { return 1.9 + 0.1 * n; }};
    fast.scaledMs = m.scaledMs;
    const equaltime::Result f = equaltime::search(fast.sides(), tight(), {{1, 2.0}, {8, 2.7}}, 0.1);
    EXPECT_NEAR(f.scale, tight().minScale, 1e-12);
    EXPECT_NEAR(f.ratio, (0.2 + 1.8 * 0.05 * 0.05) / 0.1, 1e-9);
    EXPECT_FALSE(f.ok);
}

TEST(EqualTime, SolveAndInterpolateOnTheMeasuredCurve)
{
    const equaltime::Curve c = {{1, 0.2}, {8, 0.9}, {32, 3.3}};
    EXPECT_EQ(equaltime::solveN(c, 0.9), 8);
    EXPECT_EQ(equaltime::solveN(c, 2.1), 20);  // 8 + (2.1 - 0.9) / 0.1
    EXPECT_NEAR(equaltime::interpolateMs(c, 20), 2.1, 1e-12);
    EXPECT_NEAR(equaltime::interpolateMs(c, 64), 6.6, 1e-12);  // proportional beyond the end
}

}  // namespace
}  // namespace lb
