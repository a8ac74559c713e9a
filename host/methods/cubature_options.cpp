// cubature_options.cpp -- see cubature_options.h.
#include "methods/cubature_options.h"

#include "math/kmath.h"
#include "methods/straight.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>

namespace lb::methods {

namespace {

// s_k / t_k: a static sample's coordinate in the light's unit square.
Param staticCoordinate(const std::string& name, double def)
{
    const bool s = name[0] == 's';
    return Param::real(name, def, 0.0, 1.0, Scale::Linear,
                       fmt::format("with static >= {}: static sample {}'s coordinate along the light's {} ({}, "
                                   "0 .. 1: the light's edges; the whole square is the light)",
                                   name.substr(1), name.substr(1), s ? "width u" : "length v", s ? "s" : "t"));
}

}  // namespace

const std::vector<Param>& cubatureParams()
{
    // Ranges from geometry (a tuner searches them; tune.json "search" and its
    // near_bound list show them): each meaning says why its range ends where
    // it does. area_q from 0.1 (the area rule only within a tenth of the
    // light's size: its error there exceeds 100 %) to 10 (far field only);
    // area_sin over the whole range of an elevation's sine.
    static const std::vector<Param> params = {
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
        Param::real(
            "plane_eps", 1e-3, 1e-6, 1.0, Scale::Log,
            "receivers closer than this (m) to the light's plane are moved to this distance (paper 5.3); range 1e-6 .. "
            "1 m: at most the side of the normalized scene's light (1 m), since a larger shift moves the "
            "receiver farther from the light than the light is wide and the rule then integrates a "
            "different, far-field light; at least 1e-6 m, ~16 float ulps of a 1 m scene"),
        Param::real("horizon_eps", 0.0, 0.0, 0.5, Scale::Linear,
                    "clip the light at n_x . (p - x) >= this (m): the tilted horizon of thesis 5.2.4 (it used 0.1)"),
        Param::real("corner_inset", 0.0, 0.0, 1.0, Scale::Linear,
                    "the corner samples look the radiance up this fraction of the way towards the clipped light's "
                    "corner mean (0 = at the corners; the triangles keep their weights); range 0 .. 1: at 1 every "
                    "corner collapses onto the corner mean (one radiance value for the whole light), beyond 1 the "
                    "lookups would cross the centre and leave the light"),
        Param::real("dyn_weight", 1.0, 0.0, 4.0, Scale::Linear,
                    "scale of the dynamic samples' weights, all weights rescaled to the same sum (1 = the "
                    "triangulation's weights)"),
        Param::real(
            "blend_dist", 1e6, 0.4, 1e6, Scale::Log,
            "beyond this distance (m) from the light's centre the result blends linearly into a 3 x 3 grid "
            "MC estimate, fully MC from 1.5x on (thesis 6.6; the default 1e6 = never: beyond every scene of the "
            "suite, the h = 1000 far-field stability cases included); range from 0.4 m, 2/3 of the nearest "
            "light-centre distance of the published scenes (0.6 m at h = 0.1): below it every pixel is "
            "already pure grid MC and the objective is flat"),
        lookupParam("lut", "intensity lookup: trig-free table (photometry/lut.h, as mc) or the exact bilinear one"),
        specializeParam("auto: smallest kernel for the scene (methods/specialize.h: the straight-line fan, or "
                        "Delaunay over cp+barycentre, of an unclipped rectangle; the disk's straight-line fan; 1D "
                        "table); none: the general one"),
        lanesParam("pixels per work-item of the straight-line forms (float, lut): 8 = float8 code, "
                   "auto = 8 on CPU devices (PoCL), 1 elsewhere"),
        Param::choice("area", "none", {"none", "gauss2", "gauss3"},
                      "blend in the area form of the integral (I cos / r^2 over the light, no 1/cos: finite in the "
                      "light's plane) by the n x n Gauss-Legendre rule, n = 2 or 3, away from the light"),
        Param::real("area_q", kDefaultAreaQ, 0.1, 10.0, Scale::Log,
                    "with area: the cubature alone within area_q/2 light sizes (longer side) of the light, the area "
                    "rule alone beyond area_q, smoothstep between"),
        Param::real("area_sin", kDefaultAreaSin, 0.0, 1.0, Scale::Linear,
                    "with area: the cubature alone where the light's farthest point is seen at an elevation "
                    "sin(beta) >= area_sin above the light's plane, the area rule alone below area_sin/2 (0: never "
                    "by elevation)"),
        Param::integer("static", 0, 0, kMaxStaticSamples, Scale::Linear,
                       "static samples: this many more samples at fixed positions (s_k, t_k) of the light's unit "
                       "square (s along its width u, t along its length v), inserted into the triangulation after "
                       "the dynamic points (robustly: a sample on a corner, an edge or another sample merges with it; "
                       "one outside what the horizon leaves is dropped); structural (-DLB_CUB_STATIC); > 0 runs the "
                       "general kernel"),
        staticCoordinate("s1", 0.5),
        staticCoordinate("t1", 0.5),
        staticCoordinate("s2", 0.25),
        staticCoordinate("t2", 0.25),
        staticCoordinate("s3", 0.75),
        staticCoordinate("t3", 0.75),
        staticCoordinate("s4", 0.25),
        staticCoordinate("t4", 0.75),
        Param::text("preset", "none",
                    "a presets file (JSON: luminaire file name -> SPEC of this method, as `lumibench tune` writes "
                    "with \"presets\": true): each luminaire renders with its entry, the keys given beside preset "
                    "on top; none = no presets"),
    };
    return params;
}

namespace {

// The kernel's bit of each of the `dynamic` parameter's points, in the order
// of its choices (cubatureParams; "none" last, no bit).
constexpr int kDynamicBits[] = {LB_CUB_CP, LB_CUB_NP, LB_CUB_MRP, LB_CUB_BARY};

const Param& param(const std::string& key)
{
    const auto& ps = cubatureParams();
    auto it = std::find_if(ps.begin(), ps.end(), [&](const Param& p) { return p.name == key; });
    if (it == ps.end()) {
        std::string names;
        for (const auto& p : ps) names += (names.empty() ? "" : ", ") + p.name;
        throw InputError(fmt::format("method cubature: unknown parameter '{}'; valid: {}", key, names));
    }
    return *it;
}

int choiceIndex(const Param& p, const std::string& canonical)
{
    return static_cast<int>(std::find(p.choices.begin(), p.choices.end(), canonical) - p.choices.begin());
}

}  // namespace

int parseDynamicSet(const std::string& s)
{
    const Param& p = param("dynamic");
    const std::string c = p.canonical("cubature", s);
    if (c == "none") return 0;
    int mask = 0;
    std::stringstream in(c);
    std::string item;
    while (std::getline(in, item, '+')) {
        if (item == "none")
            throw InputError(fmt::format("method cubature: bad value '{}' for dynamic: none stands alone", s));
        mask |= kDynamicBits[choiceIndex(p, item)];
    }
    return mask;
}

std::string dynamicSetName(int mask)
{
    const Param& p = param("dynamic");
    std::string out;
    for (size_t i = 0; i < std::size(kDynamicBits); ++i)
        if (mask & kDynamicBits[i]) out += (out.empty() ? "" : "+") + p.choices[i];
    return out.empty() ? "none" : out;
}

CubatureOptions::CubatureOptions() { *this = parse({}); }

bool cubatureParamUnused(const CubatureOptions& o, const std::string& name)
{
    // the area form's distance and elevation switches act only where its Gauss rule is blended in
    if (name == "area_q" || name == "area_sin") return o.area == 0;
    if (name.size() != 2 || (name[0] != 's' && name[0] != 't') || name[1] < '1' || name[1] > '9') return false;
    return name[1] - '0' > o.staticSamples;
}

CubatureOptions CubatureOptions::parse(const std::map<std::string, std::string>& kv)
{
    std::map<std::string, std::string> v;  // canonical text of every key
    for (const auto& p : cubatureParams()) v[p.name] = p.def;
    for (const auto& [k, value] : kv) v[k] = param(k).canonical("cubature", value);
    auto index = [&](const char* k) { return choiceIndex(param(k), v.at(k)); };
    CubatureOptions o(NoDefaults{});
    o.triangulation = index("triangulation");
    o.weighting = index("weighting");
    o.formfactor = v.at("normalize") == "formfactor";
    o.dynamic = parseDynamicSet(v.at("dynamic"));
#define LB_READ_TUNABLE(name) o.tunables.name = std::stod(v.at(#name));
    LB_CUB_TUNABLES(LB_READ_TUNABLE)
#undef LB_READ_TUNABLE
    o.lut = v.at("lookup") == "lut";
    o.specialize = v.at("specialize") == "auto";
    o.lanes = v.at("lanes");
    o.area = v.at("area") == "none" ? 0 : v.at("area").back() - '0';  // gaussN
    o.staticSamples = static_cast<int>(std::stol(v.at("static")));
    return o;
}

std::vector<std::string> cubatureTunableNames()
{
#define LB_TUNABLE_NAME(name) #name,
    return {LB_CUB_TUNABLES(LB_TUNABLE_NAME)};
#undef LB_TUNABLE_NAME
}

std::string CubatureOptions::defines() const
{
    return fmt::format("-DLB_CUB_TRI={} -DLB_CUB_WEIGHT={} -DLB_CUB_NORMALIZE={} -DLB_CUB_DYNAMIC={}{}{}",
                       triangulation, weighting, formfactor ? 1 : 0, dynamic,
                       area ? fmt::format(" -DLB_CUB_AREA={}", area) : "",
                       staticSamples ? fmt::format(" -DLB_CUB_STATIC={}", staticSamples) : "");
}

}  // namespace lb::methods
