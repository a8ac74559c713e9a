// metrics::pooled: the metrics of several images as if stitched into one,
// checked against compare() of the stitched image itself.
#include "metrics/metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lb {
namespace {

TEST(Metrics, PooledEqualsTheStitchedImage)
{
    // Three parts of different sizes and brightness (one nearly dark), the
    // stitched image stacks them vertically.
    const int w = 5, rows[3] = {4, 3, 6};
    const double scale[3] = {100, 0.01, 7};
    std::vector<Image> refs, tests;
    Image sr(w, 13), st(w, 13);
    int y0 = 0;
    for (int p = 0; p < 3; ++p) {
        Image r(w, rows[p]), t(w, rows[p]);
        for (int y = 0; y < rows[p]; ++y)
            for (int x = 0; x < w; ++x) {
                r.at(y, x) = scale[p] * (1 + 0.3 * x + 0.7 * y);
                t.at(y, x) = r.at(y, x) * (1 + 0.1 * std::sin(3.0 * x + 5.0 * y + p));
                sr.at(y0 + y, x) = r.at(y, x);
                st.at(y0 + y, x) = t.at(y, x);
            }
        y0 += rows[p];
        refs.push_back(r);
        tests.push_back(t);
    }
    std::vector<metrics::Metrics> parts;
    for (int p = 0; p < 3; ++p) {
        parts.push_back(metrics::compare(refs[p], tests[p]));
        parts.back().flip = 0.1 * (p + 1);
    }
    metrics::Metrics pool = metrics::pooled(parts), whole = metrics::compare(sr, st);
    // The same sums regrouped: equal to a few ulps of the double sums
    // (relative 1e-12 leaves room for the regrouping's rounding).
    EXPECT_NEAR(pool.nmse, whole.nmse, 1e-12 * whole.nmse);
    EXPECT_NEAR(pool.nrmse, whole.nrmse, 1e-12 * whole.nrmse);
    EXPECT_NEAR(pool.mean_ref, whole.mean_ref, 1e-12 * whole.mean_ref);
    EXPECT_NEAR(pool.mean_test, whole.mean_test, 1e-12 * whole.mean_test);
    EXPECT_EQ(pool.ueb, whole.ueb);
    EXPECT_EQ(pool.leb, whole.leb);
    EXPECT_EQ(pool.pixels, whole.pixels);
    // grad_nmse: the stitched image has 2 x 5 pairs across the seams that no
    // part has; without them the sums are the parts'
    EXPECT_EQ(pool.grad_pairs + 2 * w, whole.grad_pairs);
    double gsse = 0;
    for (const auto& m : parts) gsse += m.grad_nmse * double(m.grad_pairs) * m.mean_ref * m.mean_test;
    EXPECT_NEAR(pool.grad_nmse, gsse / double(pool.grad_pairs) / (whole.mean_ref * whole.mean_test),
                1e-12 * pool.grad_nmse);
    // FLIP: the pixel-weighted mean (20 px at 0.1, 15 at 0.2, 30 at 0.3)
    EXPECT_NEAR(pool.flip, (20 * 0.1 + 15 * 0.2 + 30 * 0.3) / 65, 1e-15);
    EXPECT_TRUE(std::isnan(pool.relmse));
    // not the mean of the parts' NMSE: the stitched image weighs each part by its squared errors
    double meanNmse = (parts[0].nmse + parts[1].nmse + parts[2].nmse) / 3;
    EXPECT_GT(std::fabs(meanNmse - pool.nmse), 0.1 * pool.nmse);
    // one part: itself
    EXPECT_NEAR(metrics::pooled({parts[1]}).nmse, parts[1].nmse, 1e-12 * parts[1].nmse);
}

}  // namespace
}  // namespace lb
