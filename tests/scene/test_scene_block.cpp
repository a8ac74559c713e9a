// The scene block P the kernels read (kernels/common/scene.h declares its
// layout by name, LB_P_*): Scene::params() puts every field at its named
// index, and the kernels' own readers (lb_scene_light, lb_pixel_position)
// get the scene back from it.
#include "math/kmath.h"
#include "scene/scene.h"
#include "util/error.h"

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
    EXPECT_EQ(P[LB_P_KIND], double(LB_KIND_DIFFUSE));
    s.kind = SceneKind::Specular;
    s.alpha = 0.07;
    s.eye = {0.5, 3.5, 1.5};
    s.albedo = 0.3;
    auto Q = s.params();
    EXPECT_EQ(Q[LB_P_KIND], double(LB_KIND_SPECULAR));
    EXPECT_EQ(Q[LB_P_ALPHA], 0.07);
    EXPECT_EQ(Q[LB_P_ALBEDO], 0.3);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(Q[LB_P_EYE + k], s.eye[k]) << k;
    s.kind = SceneKind::Indirect;
    EXPECT_EQ(s.params()[LB_P_KIND], double(LB_KIND_INDIRECT));
    // the room: one value on both sides
    EXPECT_EQ(LB_ROOM_HALF, kRoomHalf);
    EXPECT_EQ(LB_ROOM_HEIGHT, kRoomHeight);
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

TEST(SceneKinds, NamesRoundTripAndBadValuesAreRefused)
{
    for (SceneKind k : {SceneKind::Diffuse, SceneKind::Specular, SceneKind::Indirect})
        EXPECT_EQ(parseSceneKind(sceneKindName(k)), k);
    EXPECT_THROW(parseSceneKind("glossy"), InputError);

    Scene s;
    s.kind = SceneKind::Specular;
    EXPECT_NO_THROW(s.validate());
    s.alpha = 0.005;  // below kMinAlpha
    EXPECT_THROW(s.validate(), InputError);
    s.alpha = NAN;
    EXPECT_THROW(s.validate(), InputError);
    s.alpha = 0.25;
    s.eye = {0, 4, 0};  // in the floor's plane
    EXPECT_THROW(s.validate(), InputError);
    s.eye = {0, 4, INFINITY};
    EXPECT_THROW(s.validate(), InputError);

    Scene r;
    r.kind = SceneKind::Indirect;
    r.height = 1.0;  // R = pi: the light faces down at z = h + L/2 = 1.5, |x|, |y| <= 0.5: inside
    EXPECT_NO_THROW(r.validate());
    r.albedo = 1.5;
    EXPECT_THROW(r.validate(), InputError);
    r.albedo = 0.5;
    r.height = 2.6;  // z = 3.1: above the ceiling
    EXPECT_THROW(r.validate(), InputError);
}

}  // namespace
}  // namespace lb
