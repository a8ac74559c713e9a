// cubature: scattered sampling (paper 5, thesis 5.2) -- kernels/cubature.cl,
// math in kernels/common/cubature.h, spec keys -> defines in cubature_options.h.
#include "methods/cubature_options.h"
#include "methods/registry.h"
#include "methods/specialize.h"
#include "photometry/lut.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>

namespace lb::methods {

// The defaults `robust` changes (docs/robust.md).
const std::map<std::string, std::string> kRobustDefaults = {{"area", "gauss3"}};

namespace {

// The spec's canonical values (every key present) as CubatureOptions.
CubatureOptions options(const MethodSpec& s) { return CubatureOptions::parse(s.values); }

int popcount(int m)
{
    int n = 0;
    for (; m; m &= m - 1) ++n;
    return n;
}

}  // namespace

namespace {

Family cubatureFamily()
{
    Family f;
    f.name = "cubature";
    f.summary = "scattered sampling: horizon clip, dynamic points, fan or Delaunay spherical-triangle cubature";
    f.file = "cubature.cl";
    f.params = {
        Param::choice("triangulation", "fan", {"fan", "delaunay"},
                      "fan around the first dynamic point (paper 5.2) or Delaunay by Lawson flips (thesis 5.2); "
                      "fan accepts at most one dynamic point"),
        Param::choice("weighting", "average", {"sample", "average", "dotout"},
                      "per-sample weights: sample (paper Eq. 9), average (Eq. 10), dotout (by |n_L . d|)"),
        Param::choice("normalize", "none", {"none", "formfactor"},
                      "formfactor: cosine-weighted mean radiance times the exact Lambert irradiance of the clipped "
                      "light (thesis Eq. 5.11)"),
        Param::list("dynamic", "cp", {"cp", "np", "mrp", "barycentre", "none"},
                    "dynamic points added to the clipped light's corners ('+'-joined; none = corners only)"),
        // Ranges from geometry (a tuner searches them): plane_eps up to 1 m, the
        // side of the normalized scene's light (a larger shift moves the
        // receiver farther than the light is wide); corner_inset the whole way
        // from the corner (0) to the corner mean (1); blend_dist down to 0.4 m,
        // 2/3 of the nearest light-centre distance of the published scenes
        // (0.6 m at h = 0.1): below it every pixel is already pure grid MC.
        Param::real("plane_eps", 1e-3, 1e-6, 1.0, Scale::Log,
                    "receivers closer than this (m) to the light's plane are moved to this distance (paper 5.3)"),
        Param::real("horizon_eps", 0.0, 0.0, 0.5, Scale::Linear,
                    "clip the light at n_x . (p - x) >= this (m): the tilted horizon of thesis 5.2.4 (it used 0.1)"),
        Param::real("corner_inset", 0.0, 0.0, 1.0, Scale::Linear,
                    "the corner samples look the radiance up this fraction of the way towards the clipped light's "
                    "corner mean (0 = at the corners; the triangles keep their weights)"),
        Param::real("dyn_weight", 1.0, 0.0, 4.0, Scale::Linear,
                    "scale of the dynamic samples' weights, all weights rescaled to the same sum (1 = the "
                    "triangulation's weights)"),
        Param::real(
            "blend_dist", 1e6, 0.4, 1e6, Scale::Log,
            "beyond this distance (m) from the light's centre the result blends linearly into a 3 x 3 grid "
            "MC estimate, fully MC from 1.5x on (thesis 6.6; the default 1e6 = never: beyond every scene of the "
            "suite, the h = 1000 far-field stability cases included)"),
        Param::choice("lookup", "lut", {"lut", "exact"},
                      "intensity lookup: trig-free table (photometry/lut.h, as mc) or the exact bilinear one"),
        Param::choice("specialize", "auto", {"auto", "none"},
                      "auto: smallest kernel for the scene (methods/specialize.h: the straight-line fan, or "
                      "Delaunay over cp+barycentre, of an unclipped rectangle; 1D table); none: the general one"),
        Param::choice("lanes", "auto", {"auto", "1", "8"},
                      "pixels per work-item of the straight-line forms (float, lut): 8 = float8 code, "
                      "auto = 8 on CPU devices (PoCL), 1 elsewhere"),
        Param::choice("area", "none", {"none", "gauss2", "gauss3"},
                      "blend in the area form of the integral (I cos / r^2 over the light, no 1/cos: finite in the "
                      "light's plane) by the n x n Gauss-Legendre rule, n = 2 or 3, away from the light"),
        // area_q from 0.1 (the area rule only within a tenth of the light's
        // size: its error there exceeds 100 %) to 10 (far field only).
        Param::real("area_q", kDefaultAreaQ, 0.1, 10.0, Scale::Log,
                    "with area: the cubature alone within area_q/2 light sizes (longer side) of the light, the area "
                    "rule alone beyond area_q, smoothstep between"),
        // area_sin over the whole range of an elevation's sine.
        Param::real("area_sin", kDefaultAreaSin, 0.0, 1.0, Scale::Linear,
                    "with area: the cubature alone where the light's farthest point is seen at an elevation "
                    "sin(beta) >= area_sin above the light's plane, the area rule alone below area_sin/2 (0: never "
                    "by elevation)"),
    };
    f.validate = [](const MethodSpec& s) {
        CubatureOptions o = options(s);
        // Part 1 measured jumps of up to 20% between neighbouring pixels for a
        // fan with several dynamic points: the later points are inserted into
        // the fan of the first, and which triangle holds them changes
        // abruptly. Rejected rather than rendered with visible seams.
        if (o.triangulation == 0 && popcount(o.dynamic) > 1)
            throw InputError(fmt::format(
                "method cubature: triangulation=fan takes at most one dynamic point, got dynamic={} (the fan of "
                "several points jumps by up to 20% between pixels); use triangulation=delaunay",
                dynamicSetName(o.dynamic)));
    };
    f.defines = [](const MethodSpec& s) { return options(s).defines(); };
    f.sceneDefines = [](const MethodSpec& s, const Scene& scene, const photometry::Table& t) {
        return analyseCubature(scene, t, options(s)).defines();
    };
    f.lanes = [](const MethodSpec& s, const Scene& scene, const photometry::Table& t, const ocl::DeviceInfo& dev,
                 Precision p) {
        CubatureOptions o = options(s);
        return cubatureLanes(analyseCubature(scene, t, o), o, dev.type, p == Precision::Double);
    };
    f.lumBuffer = [](const MethodSpec& s, const photometry::Table& t) {
        return options(s).lut ? photometry::buildLut(t).packed : t.packed();
    };
    f.args = {"stats",      "want_stats", "plane_eps", "horizon_eps", "corner_inset",
              "dyn_weight", "blend_dist", "area_q",    "area_sin"};
    f.statsSwitch = "want_stats";
    f.setArgs = [](LaunchContext& c) {
        CubatureOptions o = options(c.spec);
        size_t npx = static_cast<size_t>(c.res()) * c.res();
        cl::Buffer stats = c.outputInts(2 * npx);
        c.named["stats"] = stats;
        c.arg("stats", stats);
        c.arg("want_stats", cl_int(0));
        c.realArg("plane_eps", o.planeEps);
        c.realArg("horizon_eps", o.horizonEps);
        c.realArg("corner_inset", o.cornerInset);
        c.realArg("dyn_weight", o.dynWeight);
        c.realArg("blend_dist", o.blendDist);
        c.realArg("area_q", o.areaQ);
        c.realArg("area_sin", o.areaSin);
    };
    f.straightDefines = {"-DLB_CUB_RECT_FAN", "-DLB_CUB_RECT_DEL"};
    f.benchSpecs = {"cubature:lanes=1", "cubature:specialize=none,lookup=exact",
                    "cubature:triangulation=delaunay,dynamic=cp+barycentre",
                    "cubature:triangulation=delaunay,dynamic=cp+np+mrp+barycentre",
                    "cubature:normalize=formfactor,weighting=sample"};
    // Triangles and Lawson flips per pixel, from the one untimed launch with
    // want_stats = 1 (the timed launches write only the image).
    f.finish = [](LaunchContext& c) {
        size_t npx = static_cast<size_t>(c.res()) * c.res();
        std::vector<cl_int> st(2 * npx);
        c.rt.queue().enqueueReadBuffer(c.named.at("stats"), CL_TRUE, 0, st.size() * sizeof(cl_int), st.data());
        double tris = 0, flips = 0;
        int tmax = 0, fmax = 0;
        for (size_t i = 0; i < npx; ++i) {
            tris += st[2 * i];
            flips += st[2 * i + 1];
            tmax = std::max(tmax, st[2 * i]);
            fmax = std::max(fmax, st[2 * i + 1]);
        }
        c.stats["triangles_per_pixel"] = tris / double(npx);
        c.stats["triangles_max"] = tmax;
        c.stats["flips_per_pixel"] = flips / double(npx);
        c.stats["flips_max"] = fmax;
    };
    return f;
}

}  // namespace

void registerCubature(Registry& r) { r.add(cubatureFamily()); }

// robust: the cubature where it is best (near the light, in front of it) and
// the area form where it is not (far field, the light's own plane): the
// recommended variant of docs/robust.md. Every cubature parameter applies;
// only the defaults differ.
void registerRobust(Registry& r)
{
    Family f = cubatureFamily();
    f.name = "robust";
    f.summary = "cubature blended with the area-form Gauss rule away from the light (docs/robust.md)";
    const std::map<std::string, std::string> defaults = kRobustDefaults;
    for (auto& p : f.params)
        if (auto it = defaults.find(p.name); it != defaults.end()) p.def = it->second;
    f.benchSpecs = {};
    r.add(f);
}

}  // namespace lb::methods
