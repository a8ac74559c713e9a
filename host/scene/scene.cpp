#include "scene/scene.h"

#include "math/kmath.h"

#include <fmt/format.h>

#include <cmath>

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
    glm::dvec3 c = center(), uu = u(), vv = v(), nn = n();
    return {c.x,   c.y,    c.z,    uu.x,   uu.y, uu.z, vv.x, vv.y, vv.z, nn.x,
            nn.y,  nn.z,   width,  length, extent, static_cast<double>(res), 0.0, 0.0, 1.0, 0.0};
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

} // namespace lb
