// The scene block P the kernels read (kernels/common/scene.h declares its
// layout by name, LB_P_*): Scene::params() puts every field at its named
// index, and the kernels' own readers (lb_scene_light, lb_pixel_position)
// get the scene back from it.
#include "math/kmath.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lb {
namespace {

TEST(SceneBlock, EveryFieldAtItsNamedIndex)
{
    Scene s;
    s.height = 0.7;
    s.rotation = 5 * M_PI / 8;
    s.width = 1.3;
    s.length = 0.4;
    s.extent = 6;
    s.res = 37;
    auto P = s.params();
    ASSERT_EQ(P.size(), size_t(LB_SCENE_SIZE));
    // distinct values, so a swapped index cannot pass
    EXPECT_EQ(P[LB_P_W], 1.3);
    EXPECT_EQ(P[LB_P_L], 0.4);
    EXPECT_EQ(P[LB_P_EXTENT], 6.0);
    EXPECT_EQ(P[LB_P_RES], 37.0);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(P[LB_P_C + k], s.center()[k]) << k;
        EXPECT_EQ(P[LB_P_U + k], s.u()[k]) << k;
        EXPECT_EQ(P[LB_P_V + k], s.v()[k]) << k;
        EXPECT_EQ(P[LB_P_N + k], s.n()[k]) << k;
    }
    EXPECT_EQ(P[LB_P_NX], 0.0);
    EXPECT_EQ(P[LB_P_NX + 1], 0.0);
    EXPECT_EQ(P[LB_P_NX + 2], 1.0);
    // the kernels' readers of the block (compiled here as C++)
    f64::lb_light L = f64::lb_scene_light(P.data());
    EXPECT_EQ(L.w, 1.3);
    EXPECT_EQ(L.l, 0.4);
    EXPECT_EQ(L.c.z, s.center().z);
    EXPECT_EQ(L.n.y, s.n().y);
    glm::dvec3 x = f64::lb_pixel_position(P.data(), 0, 36);
    EXPECT_DOUBLE_EQ(x.x, 3.0 - 0.5 * 6.0 / 37);  // the last column's centre
    EXPECT_DOUBLE_EQ(x.y, 3.0 - 0.5 * 6.0 / 37);  // row 0 at the top
}

} // namespace
} // namespace lb
