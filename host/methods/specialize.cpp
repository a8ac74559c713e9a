#include "methods/specialize.h"

#include "math/kmath.h"
#include "methods/straight.h"
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
    if (rectFan) d += " -DLB_CUB_RECT_FAN";
    if (rectDel) d += " -DLB_CUB_RECT_DEL";
    if (rectDelAll) d += " -DLB_CUB_RECT_DELALL";
    if (rectDelStatic) d += " -DLB_CUB_RECT_DELST";
    if (rectForm() && rectClip) d += " -DLB_CUB_RECT_CLIP";
    if (rectForm() && blend) d += " -DLB_CUB_BLEND";
    return d;
}

nlohmann::json Specialization::json() const
{
    return {{"lut", lut},
            {"lut1d", lut && lut1d},
            {"no_horizon", noHorizon},
            {"no_back", noBack},
            {"rect_fan", rectFan},
            {"rect_del", rectDel},
            {"rect_del_all", rectDelAll},
            {"rect_del_static", rectDelStatic},
            {"rect_clip", rectForm() && rectClip},
            {"blend", blend}};
}

bool lightAboveEveryHorizon(const Scene& scene, double margin)
{
    auto P = scene.params();
    glm::dvec3 nx(P[LB_P_NX], P[LB_P_NX + 1], P[LB_P_NX + 2]);
    int n = scene.res;
    double lo = std::numeric_limits<double>::infinity();
    for (const auto& p : scene.corners())
        for (int r : {0, n - 1})
            for (int c : {0, n - 1}) lo = std::min(lo, glm::dot(nx, p - scene.pixel(r, c)));
    return lo > margin;
}

bool horizonAlongU(const Scene& scene)
{
    // Exactly as the kernels compute it (lb_receiver_normal_local), in float
    // and in double: the straight-line clip needs au == 0 exactly.
    auto P = scene.params();
    double au = P[LB_P_NX] * P[LB_P_U] + P[LB_P_NX + 1] * P[LB_P_U + 1] + P[LB_P_NX + 2] * P[LB_P_U + 2];
    float auf = float(P[LB_P_NX]) * float(P[LB_P_U]) + float(P[LB_P_NX + 1]) * float(P[LB_P_U + 1]) +
        float(P[LB_P_NX + 2]) * float(P[LB_P_U + 2]);
    return au == 0 && auf == 0;
}

namespace {

// Largest distance from the light's centre to a pixel centre: distance is
// convex, so over the square grid it peaks at an image corner.
double farthestPixel(const Scene& scene)
{
    glm::dvec3 c = scene.center();
    int n = scene.res;
    double far = 0;
    for (int r : {0, n - 1})
        for (int col : {0, n - 1}) far = std::max(far, glm::length(scene.pixel(r, col) - c));
    return far;
}

}  // namespace

Specialization analyseCubature(const Scene& scene, const photometry::Table& table, const CubatureOptions& o)
{
    Specialization s;
    s.lut = o.lut;
    if (!o.specialize) return s;
    s.lut1d = o.lut && photometry::isRotational(table);
    // lb_blend_weight is exactly 0 up to blend_dist; 1e-6 relative covers the
    // kernel's float rounding of the distance.
    bool noBlend = farthestPixel(scene) * (1 + 1e-6) < o.tunables.blend_dist;
    // Delaunay over corners + CP never flips on an unclipped rectangle (the
    // header's proof): it is the fan around CP.
    bool fanCp =
        (o.triangulation == 0 && (o.dynamic == 1 || o.dynamic == 0)) || (o.triangulation == 1 && o.dynamic == 1);
    bool delCpBary = o.triangulation == 1 && o.dynamic == (1 | 8);  // LB_CUB_CP | LB_CUB_BARY
    bool unclipped = lightAboveEveryHorizon(scene, o.tunables.horizon_eps + o.tunables.plane_eps);
    // Otherwise the straight-line forms run on what the horizon leaves where
    // it cuts along the light's u edges (LB_CUB_RECT_CLIP). dynamic=none fans
    // from the clipped polygon's first vertex, which the clip decides: general.
    // Not for normalize=formfactor: the clipped rectangle's Lambert edge sum
    // lost float accuracy at grazing receivers (2.2e-4 against the general
    // kernel's own 5.4e-5 at h = -0.2, R = 5pi/8).
    // Delaunay over corners + CP + NP + MRP + barycentre: the three dynamic
    // points on one line of constant u needs the receiver normal
    // perpendicular to u (exactly, as the clip along u does).
    bool delAll = o.triangulation == 1 && o.dynamic == (1 | 2 | 4 | 8) && horizonAlongU(scene);
    bool clipAlongU =
        !unclipped && horizonAlongU(scene) && (fanCp || delCpBary || delAll) && o.dynamic != 0 && !o.formfactor;
    s.rectFan = fanCp && (unclipped || clipAlongU);
    s.rectDel = delCpBary && (unclipped || clipAlongU);
    s.rectDelAll = delAll && (unclipped || clipAlongU);
    s.rectClip = clipAlongU;
    s.blend = !noBlend;
    // Static samples beside corners + CP: their own form, each at least 1 %
    // inside the light (no merge with a corner, no split of a hull edge,
    // whatever the pixel); beside other dynamic points, or on a clipped
    // light, the general kernel renders them (honestly slower).
    if (o.staticSamples > 0) s.rectFan = s.rectDel = s.rectDelAll = s.rectClip = false;
    const double st[8] = {o.tunables.s1, o.tunables.t1, o.tunables.s2, o.tunables.t2,
                          o.tunables.s3, o.tunables.t3, o.tunables.s4, o.tunables.t4};
    bool inside = true;
    for (int i = 0; i < 2 * std::min(o.staticSamples, 4); ++i) inside = inside && st[i] >= 0.01 && st[i] <= 0.99;
    s.rectDelStatic = o.staticSamples >= 1 && o.triangulation == 1 && o.dynamic == 1 && unclipped && inside;
    return s;
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

}  // namespace lb::methods

namespace lb::methods {

int cubatureLanes(const Specialization& s, const CubatureOptions& o, const std::string& deviceType, bool dbl)
{
    if (!s.rectForm() || !s.lut || dbl) return 1;
    return lanesFor(o.lanes, deviceType);
}

}  // namespace lb::methods
