// scene.h -- the normalized evaluation scene of docs/design.md section 2.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <string>
#include <vector>

namespace lb {

// Limits of the scene's values, checked by Scene::validate and by every flag
// and experiment key that sets them (util::checkRange).
// Lengths (|height|, W, L, extent) up to 10 km: the kernels work in float by
// default, whose spacing at 1e4 m is 1e-3 m (2^-10), so beyond it a light of
// a few millimetres cannot be told from a point and a metre-sized one loses
// its shape to rounding; real scenes are < 1 km.
constexpr double kMaxSceneLength = 1e4;
// The narrowest light, short side over long side: float cubature merges
// points within ~1.2e-5 of the light's diagonal (Scene::validate).
constexpr double kMinAspect = 2e-5;
// Pixels per side: 16384^2 doubles are 2 GiB, the largest buffer we ask of a device.
constexpr int kMaxRes = 16384;

// What the image shows (docs/design.md sections 2, 8, 9): the floor's direct
// irradiance, the luminance a glossy floor reflects towards an eye, or the
// floor's one-bounce indirect irradiance inside a room.
enum class SceneKind { Diffuse, Specular, Indirect };
std::string sceneKindName(SceneKind k);  // "diffuse" | "specular" | "indirect"
SceneKind parseSceneKind(const std::string& s);  // InputError naming the three otherwise

// GGX roughness range of the specular scene: below 0.01 the lobe is narrower
// than a float-resolved direction near grazing and no reference resolves it;
// above 1 the Trowbridge-Reitz lobe is wider than any real glossy floor.
constexpr double kMinAlpha = 0.01, kMaxAlpha = 1.0;
// The room of the indirect scene (docs/design.md section 9): [-half, half]^2 x [0, height] m.
constexpr double kRoomHalf = 2.5, kRoomHeight = 3.0;

// The light's outline (docs/design.md section 2): the rectangle W x L, or
// the ellipse inscribed in it (a disk of diameter D when W = L = D), both
// centred at center() in the frame (u, v, n_L).
enum class LightShape { Rect, Disk };
std::string lightShapeName(LightShape s);  // "rect" | "disk"
LightShape parseLightShape(const std::string& s);  // InputError naming both otherwise

struct Scene {
    double height = 1.0;  // h: lower edge at R = pi/2; centre at h + L/2
    double rotation = 3.14159265358979;  // R: angle between n_L and n_x, pi/2 .. pi
    double width = 1.0;  // W along u
    double length = 1.0;  // L along v
    LightShape shape = LightShape::Rect;
    double extent = 5.0;  // S: side of the imaged square
    int res = 256;  // N x N pixels

    SceneKind kind = SceneKind::Diffuse;
    double alpha = 0.25;  // specular: GGX roughness, kMinAlpha .. kMaxAlpha
    glm::dvec3 eye{0.0, 4.0, 2.0};  // specular: eye point (m), z > 0
    double albedo = 0.5;  // indirect: albedo of walls and ceiling, 0 .. 1

    glm::dvec3 center() const;
    glm::dvec3 u() const;
    glm::dvec3 v() const;  // cross(u, n_L)
    glm::dvec3 n() const;  // n_L = (0, sin R, cos R)
    std::array<glm::dvec3, 4> corners() const;  // (-u,-v), (+u,-v), (+u,+v), (-u,+v): of the W x L box
    double area() const;  // W L, or pi W L / 4 for the disk
    glm::dvec3 pixel(int row, int col) const;  // receiver point at a pixel centre

    // The LB_SCENE_SIZE reals the kernels take (kernels/common/scene.h).
    std::vector<double> params() const;
    std::string describe() const;

    // Throws lb::InputError unless every value is finite, |h|, W, L, S <=
    // kMaxSceneLength, S > 0 and the
    // light is a proper rectangle: W, L > 0 and both sides resolvable in float
    // against the scene's coordinates (>= 1e-6 of max(W, L, h + L, S), i.e.
    // ~8 float ulps). A narrower light has coincident or collinear corners in
    // the kernels (zero area, undefined L_e = I / (A cos)): a clear error, not
    // NaN or a silent zero image. The kind's own values too: alpha in
    // kMinAlpha .. kMaxAlpha, the eye finite and above the floor (z > 0), the
    // albedo in 0 .. 1, and in the room the light's corners inside it. The
    // disk is a diffuse scene's light only (the specular and indirect
    // kernels integrate rectangles).
    // render() calls it.
    void validate() const;

private:
    void validateKind() const;
};

}  // namespace lb
