#include "methods/specialize.h"

#include "photometry/lut.h"

#include <algorithm>
#include <limits>

namespace lb::methods {

std::string Specialization::defines() const
{
    std::string d;
    if (lut) d += " -DLB_LUT";
    if (lut && lut1d) d += " -DLB_LUT_1D";
    if (noHorizon) d += " -DLB_NO_HORIZON";
    if (noBack) d += " -DLB_NO_BACK";
    return d;
}

nlohmann::json Specialization::json() const
{
    return {{"lut", lut}, {"lut1d", lut && lut1d}, {"no_horizon", noHorizon}, {"no_back", noBack}};
}

bool lightAboveEveryHorizon(const Scene& scene)
{
    auto P = scene.params();
    glm::dvec3 nx(P[16], P[17], P[18]);
    int n = scene.res;
    double lo = std::numeric_limits<double>::infinity();
    for (const auto& p : scene.corners())
        for (int r : {0, n - 1})
            for (int c : {0, n - 1}) lo = std::min(lo, glm::dot(nx, p - scene.pixel(r, c)));
    return lo > 0;
}

Specialization analyse(const Scene& scene, const photometry::Table& table, bool lut, bool specialize)
{
    Specialization s;
    s.lut = lut;
    if (!specialize) return s;
    s.lut1d = lut && photometry::isRotational(table);
    s.noHorizon = lightAboveEveryHorizon(scene);
    s.noBack = photometry::emitsNoBack(table);
    return s;
}

} // namespace lb::methods
