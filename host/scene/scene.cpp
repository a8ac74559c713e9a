#include "scene/scene.h"

#include "math/kmath.h"

#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>

#include <cmath>
#include <utility>

namespace lb {

std::string sceneKindName(SceneKind k)
{
    switch (k) {
    case SceneKind::Diffuse:
        return "diffuse";
    case SceneKind::Specular:
        return "specular";
    case SceneKind::Indirect:
        return "indirect";
    }
    return "?";
}

SceneKind parseSceneKind(const std::string& s)
{
    for (SceneKind k : {SceneKind::Diffuse, SceneKind::Specular, SceneKind::Indirect})
        if (s == sceneKindName(k)) return k;
    throw InputError(fmt::format("scene: expected diffuse, specular or indirect, got '{}'", s));
}

std::string lightShapeName(LightShape s) { return s == LightShape::Disk ? "disk" : "rect"; }

LightShape parseLightShape(const std::string& s)
{
    for (LightShape k : {LightShape::Rect, LightShape::Disk})
        if (s == lightShapeName(k)) return k;
    throw InputError(fmt::format("shape: expected rect or disk, got '{}'", s));
}

double Scene::area() const { return shape == LightShape::Disk ? 0.25 * M_PI * width * length : width * length; }

glm::dvec3 Scene::n() const { return {0.0, std::sin(rotation), std::cos(rotation)}; }
glm::dvec3 Scene::u() const { return {1.0, 0.0, 0.0}; }
glm::dvec3 Scene::v() const { return glm::cross(u(), n()); }
glm::dvec3 Scene::center() const { return {0.0, 0.0, height + 0.5 * length}; }

std::array<glm::dvec3, 4> Scene::corners() const
{
    glm::dvec3 hu = u() * (0.5 * width), hv = v() * (0.5 * length), c = center();
    return {c - hu - hv, c + hu - hv, c + hu + hv, c - hu + hv};
}

std::vector<double> Scene::params() const
{
    std::vector<double> P(LB_SCENE_SIZE, 0.0);
    auto put3 = [&P](int at, const glm::dvec3& a) {
        P[at] = a.x;
        P[at + 1] = a.y;
        P[at + 2] = a.z;
    };
    put3(LB_P_C, center());
    put3(LB_P_U, u());
    put3(LB_P_V, v());
    put3(LB_P_N, n());
    P[LB_P_W] = width;
    P[LB_P_L] = length;
    P[LB_P_EXTENT] = extent;
    P[LB_P_RES] = static_cast<double>(res);
    put3(LB_P_NX, {0.0, 0.0, 1.0});  // the receiver plane z = 0, seen from above
    P[LB_P_KIND] = kind == SceneKind::Specular ? LB_KIND_SPECULAR
        : kind == SceneKind::Indirect          ? LB_KIND_INDIRECT
                                               : LB_KIND_DIFFUSE;
    put3(LB_P_EYE, eye);
    P[LB_P_ALPHA] = alpha;
    P[LB_P_ALBEDO] = albedo;
    P[LB_P_SHAPE] = shape == LightShape::Disk ? LB_SHAPE_DISK : LB_SHAPE_RECT;
    return P;
}

glm::dvec3 Scene::pixel(int row, int col) const
{
    auto P = params();
    return f64::lb_pixel_position(P.data(), row, col);
}

std::string Scene::describe() const
{
    std::string d = fmt::format("h={} R={} size={}x{} extent={} res={}", height, rotation, width, length, extent, res);
    if (shape == LightShape::Disk) d += " shape=disk";
    if (kind == SceneKind::Specular)
        d += fmt::format(" scene=specular alpha={} eye={},{},{}", alpha, eye.x, eye.y, eye.z);
    else if (kind == SceneKind::Indirect)
        d += fmt::format(" scene=indirect albedo={}", albedo);
    return d;
}

void Scene::validate() const
{
    for (double x : {height, rotation, width, length, extent})
        if (!std::isfinite(x)) throw InputError(fmt::format("scene {}: every value must be finite", describe()));
    // h < 0 is allowed: the light then passes through the receiver plane and
    // every method must clip it at the receiver's horizon (a stiff case).
    if (!(extent > 0)) throw InputError(fmt::format("scene {}: extent must be > 0", describe()));
    const std::pair<const char*, double> lengths[] = {
        {"height", std::fabs(height)}, {"width", width}, {"length", length}, {"extent", extent}};
    for (auto [name, x] : lengths)
        if (x > kMaxSceneLength)
            throw InputError(fmt::format("scene {}: {} {} m beyond the {} m the scene allows (float coordinates)",
                                         describe(), name, x, kMaxSceneLength));
    if (!(width > 0 && length > 0))
        throw InputError(fmt::format("scene {}: degenerate light {} x {}: its corners coincide or are collinear "
                                     "(W and L must be > 0)",
                                     describe(), width, length));
    const double scale = std::max({width, length, std::fabs(height) + length, extent});
    if (std::min(width, length) < 1e-6 * scale)
        throw InputError(fmt::format("scene {}: degenerate light {} x {}: a side below 1e-6 of the scene scale {} "
                                     "makes corners coincide or collinear in float",
                                     describe(), width, length, scale));
    // The cubature merges points closer than ~1.2e-5 of the light's diagonal
    // (kernels/common/cubature.h lb_cub_tol): in float a narrower rectangle
    // collapses to nothing (1 m x 8 um rendered 0 lx against 35.4).
    if (std::min(width, length) < kMinAspect * std::max(width, length))
        throw InputError(fmt::format("scene {}: light {} x {} m narrower than 1:{:.0f}: its short side is below what "
                                     "the kernels resolve against its long one",
                                     describe(), width, length, 1 / kMinAspect));
    validateKind();
}

void Scene::validateKind() const
{
    if (shape != LightShape::Rect && kind != SceneKind::Diffuse)
        throw InputError(fmt::format("scene {}: the {} scene's light is a rectangle (shape=rect); a disk lights the "
                                     "diffuse scene only",
                                     describe(), sceneKindName(kind)));
    switch (kind) {
    case SceneKind::Diffuse:
        return;
    case SceneKind::Specular:
        if (!(alpha >= kMinAlpha && alpha <= kMaxAlpha))
            throw InputError(
                fmt::format("scene {}: alpha {} outside {} .. {}", describe(), alpha, kMinAlpha, kMaxAlpha));
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(eye[k]) || std::fabs(eye[k]) > kMaxSceneLength)
                throw InputError(fmt::format("scene {}: eye coordinates must be finite and within {} m", describe(),
                                             kMaxSceneLength));
        if (!(eye.z > 0))
            throw InputError(fmt::format("scene {}: the eye must be above the floor (z > 0)", describe()));
        return;
    case SceneKind::Indirect:
        if (!(albedo >= 0 && albedo <= 1))
            throw InputError(fmt::format("scene {}: albedo {} outside 0 .. 1", describe(), albedo));
        for (const auto& c : corners())
            if (!(std::fabs(c.x) < kRoomHalf && std::fabs(c.y) < kRoomHalf && c.z > 0 && c.z < kRoomHeight))
                throw InputError(fmt::format("scene {}: the light's corner ({:.3g}, {:.3g}, {:.3g}) lies outside "
                                             "the room [-{}, {}]^2 x [0, {}] m (choose a height with the light "
                                             "inside it)",
                                             describe(), c.x, c.y, c.z, kRoomHalf, kRoomHalf, kRoomHeight));
        return;
    }
}

}  // namespace lb
