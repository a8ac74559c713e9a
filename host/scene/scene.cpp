#include "scene/scene.h"

#include "math/kmath.h"

#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>

#include <cmath>
#include <utility>

namespace lb {

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
    return P;
}

glm::dvec3 Scene::pixel(int row, int col) const
{
    auto P = params();
    return f64::lb_pixel_position(P.data(), row, col);
}

std::string Scene::describe() const
{
    return fmt::format("h={} R={} size={}x{} extent={} res={}", height, rotation, width, length, extent, res);
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
}

} // namespace lb
