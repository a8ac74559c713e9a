// The intensity lookup of kernels/common/photometry.h on a hand-made table.
#include "math/kmath.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

// C = {0, 90, 360}, gamma = {0, 30, 90}; values v = 100*ic + ig.
std::vector<float> table()
{
    std::vector<float> t = {3, 3, 0, 90, 360, 0, 30, 90};
    for (int ic = 0; ic < 3; ++ic)
        for (int ig = 0; ig < 3; ++ig) t.push_back(static_cast<float>(100 * (ic == 2 ? 0 : ic) + ig));
    return t;
}

TEST(PhotometryLookup, ExactAtNodesBilinearBetween)
{
    using namespace lb::f64;
    auto t = table();
    EXPECT_EQ(lb_intensity_cg(t.data(), 0, 0), 0.0);
    EXPECT_EQ(lb_intensity_cg(t.data(), 90, 30), 101.0);
    EXPECT_EQ(lb_intensity_cg(t.data(), 90, 90), 102.0);
    EXPECT_EQ(lb_intensity_cg(t.data(), 360, 90), 2.0);
    EXPECT_DOUBLE_EQ(lb_intensity_cg(t.data(), 45, 15), 0.25 * (0 + 1 + 100 + 101));
    EXPECT_DOUBLE_EQ(lb_intensity_cg(t.data(), 90, 60), 101.5);
    // C 90 -> 360 interpolates back to the C = 0 plane.
    EXPECT_DOUBLE_EQ(lb_intensity_cg(t.data(), 225, 0), 50.0);
}

TEST(PhotometryLookup, ZeroOutsideMeasuredGamma)
{
    using namespace lb::f32;
    auto t = table();
    EXPECT_EQ(lb_intensity_cg(t.data(), 10, 90.001f), 0.0f);
    EXPECT_EQ(lb_intensity_cg(t.data(), 10, 179.0f), 0.0f);
    EXPECT_EQ(lb_intensity_cg(t.data(), 10, -1.0f), 0.0f);
}

TEST(PhotometryLookup, DirectionToAngles)
{
    using namespace lb::f64;
    EXPECT_NEAR(lb_gamma_deg(real3(0, 0, 2)), 0, 1e-12);
    EXPECT_NEAR(lb_gamma_deg(real3(1, 0, 0)), 90, 1e-12);
    EXPECT_NEAR(lb_gamma_deg(real3(0, 0, -1)), 180, 1e-12);
    EXPECT_NEAR(lb_c_deg(real3(1, 0, 0)), 0, 1e-12);
    EXPECT_NEAR(lb_c_deg(real3(0, 1, 0)), 90, 1e-12);  // C = 90 along v
    EXPECT_NEAR(lb_c_deg(real3(-1, 0, 0)), 180, 1e-12);
    EXPECT_NEAR(lb_c_deg(real3(0, -1, 0)), 270, 1e-12);
    EXPECT_NEAR(lb_c_deg(real3(1, -1e-9, 0)), 360, 1e-6);  // just below 360, never negative
}

}  // namespace
