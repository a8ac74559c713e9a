// flip (metrics/flip.h): mean HDR-FLIP from NVIDIA's flip-evaluator through
// the Python co-process. Skips only when the package cannot be imported
// (scripts/install-deps.sh installs it into .venv), and says why.
#include "metrics/flip.h"
#include "util/error.h"

#include "testutil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace lb {
namespace {

// Skips when flip_evaluator cannot be imported by the Python FLIP uses
// (checked here on its own, as the pyldt peer test does); where it can,
// the co-process must be available: a broken co-process fails, never skips.
#define LB_REQUIRE_FLIP()                                                                           \
    do {                                                                                            \
        const std::string py = metrics::flipPython();                                               \
        if (std::system(("'" + py + "' -c 'import flip_evaluator' 2>/dev/null").c_str()) != 0)      \
            GTEST_SKIP() << "flip_evaluator cannot be imported by " << py                           \
                         << " (scripts/install-deps.sh installs it into .venv; no PyPI, no FLIP)";  \
        std::string why;                                                                            \
        ASSERT_TRUE(metrics::flipAvailable(&why)) << py << " imports flip_evaluator, yet: " << why; \
    } while (0)

// A smooth HDR image like a receiver's illuminance: a bright peak (~2000 lx)
// over a floor of a few lux, so FLIP sees several exposures.
Image peak(int n)
{
    Image r(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            double u = (x + 0.5) / n - 0.4, v = (y + 0.5) / n - 0.5;
            r.at(y, x) = 2 + 2000 / std::pow(1 + 40 * (u * u + v * v), 1.5);
        }
    return r;
}

// R times (1 + s u), u uniform in [-1, 1] from a fixed LCG: the same noise
// pattern at every strength s.
Image noisy(const Image& r, double s)
{
    Image a = r;
    uint64_t state = 12345;
    for (auto& v : a.px) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        double u = double(state >> 11) / double(1ULL << 53) * 2 - 1;
        v *= 1 + s * u;
    }
    return a;
}

TEST(Flip, IsZeroForTheReferenceAndGrowsWithNoise)
{
    LB_REQUIRE_FLIP();
    Image r = peak(64);
    // FLIP of identical images is 0 by construction (every difference term vanishes).
    EXPECT_EQ(metrics::flip(r, r), 0.0);
    double weak = metrics::flip(r, noisy(r, 0.05)), strong = metrics::flip(r, noisy(r, 0.4));
    std::printf("FLIP of 64 x 64: noise 5 %%: %.6g, noise 40 %%: %.6g\n", weak, strong);
    // Monotone in the noise, and a FLIP value in (0, 1). 5 % noise is visible
    // (measured 0.019), 40 % much more (0.100): the factor 2 leaves room for
    // other package versions without letting equal values pass.
    EXPECT_GT(weak, 0.0);
    EXPECT_GT(strong, 2 * weak);
    EXPECT_LT(strong, 1.0);
}

// A non-finite test pixel is left out of the mean (it takes the reference's
// value inside FLIP): the result stays finite and, on an otherwise perfect
// image, is exactly 0; an all non-finite image has nothing to average: NaN.
TEST(Flip, NonFinitePixelsAreLeftOut)
{
    LB_REQUIRE_FLIP();
    Image r = peak(32), a = r;
    a.px[5] = std::numeric_limits<double>::quiet_NaN();
    a.px[40] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(metrics::flip(r, a), 0.0);
    Image b = noisy(r, 0.2);
    double withNan = metrics::flip(r, b);
    b.px[100] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(std::isfinite(metrics::flip(r, b)));
    EXPECT_GT(metrics::flip(r, b), 0.0);
    EXPECT_NE(metrics::flip(r, b), withNan);  // one pixel fewer, and one changed: not the same mean
    Image all(32, 32, std::numeric_limits<double>::quiet_NaN());
    EXPECT_TRUE(std::isnan(metrics::flip(r, all)));
}

TEST(Flip, BadInputIsAnInputError)
{
    // Checked before FLIP is asked, so also without flip-evaluator.
    EXPECT_THROW(metrics::flip(Image(2, 2, 1.0), Image(3, 2, 1.0)), InputError);
    Image bad(2, 2, 1.0);
    bad.px[3] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(metrics::flip(bad, Image(2, 2, 1.0)), InputError);
}

}  // namespace
}  // namespace lb
