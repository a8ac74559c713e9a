#include "methods/specialize.h"

#include "math/kmath.h"
#include "methods/spec.h"
#include "methods/straight.h"
#include "photometry/lut.h"

#include <algorithm>
#include <limits>

namespace lb::methods {

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

// The names of the rules, in Rule's order: the lookup (every family with
// the `lookup` parameter), mc's scene rules, the cubature form's modifiers.
const RuleName kRuleNames[kRuleCount] = {{"-DLB_LUT", "lut"},
                                         {"-DLB_LUT_1D", "lut1d"},
                                         {"-DLB_NO_HORIZON", "no_horizon"},
                                         {"-DLB_NO_BACK", "no_back"},
                                         {"-DLB_CUB_RECT_CLIP", "rect_clip"},
                                         {"-DLB_CUB_BLEND", "blend"}};

// ---- The cubature forms' conditions (docs/design.md, "Kernel specialisation") ----

// Fan around CP or corner 0, or Delaunay over corners + CP (which never flips
// on an unclipped rectangle: the fan around CP).
bool fanCp(const CubatureOptions& o, const CubatureScene&)
{
    const bool fan = o.triangulation == LB_CUB_FAN && (o.dynamic == LB_CUB_CP || o.dynamic == 0);
    const bool delCp = o.triangulation == LB_CUB_DELAUNAY && o.dynamic == LB_CUB_CP;
    return o.staticSamples == 0 && (fan || delCp);
}

bool delaunayCpBary(const CubatureOptions& o, const CubatureScene&)
{
    return o.staticSamples == 0 && o.triangulation == LB_CUB_DELAUNAY && o.dynamic == (LB_CUB_CP | LB_CUB_BARY);
}

// The three dynamic points on one line of constant u: the receiver normal
// perpendicular to u (exactly, as the clip along u needs).
bool delaunayAll(const CubatureOptions& o, const CubatureScene& sc)
{
    return o.staticSamples == 0 && o.triangulation == LB_CUB_DELAUNAY &&
        o.dynamic == (LB_CUB_CP | LB_CUB_NP | LB_CUB_MRP | LB_CUB_BARY) && sc.alongU;
}

// Static samples beside corners + CP, each at least 1 % inside the light (no
// merge with a corner, no split of a hull edge, whatever the pixel); beside
// other dynamic points, or on a clipped light, the general kernel renders them.
bool delaunayStatic(const CubatureOptions& o, const CubatureScene&)
{
    const double st[8] = {o.tunables.s1, o.tunables.t1, o.tunables.s2, o.tunables.t2,
                          o.tunables.s3, o.tunables.t3, o.tunables.s4, o.tunables.t4};
    bool inside = true;
    for (int i = 0; i < 2 * std::min(o.staticSamples, kMaxStaticSamples); ++i)
        inside = inside && st[i] >= 0.01 && st[i] <= 0.99;
    return o.staticSamples >= 1 && o.triangulation == LB_CUB_DELAUNAY && o.dynamic == LB_CUB_CP && inside;
}

// Where a clipped light still gets a straight-line form (with clipOk): the
// horizon cuts along u. dynamic=none fans from the clipped polygon's first
// vertex, which the clip decides; normalize=formfactor's clipped Lambert
// edge sum lost float accuracy at grazing receivers: both general.
bool clipAlongU(const CubatureOptions& o, const CubatureScene& sc)
{
    return !sc.unclipped && sc.alongU && o.dynamic != 0 && !o.formfactor;
}

bool noHorizon(const Scene& scene, const photometry::Table&) { return lightAboveEveryHorizon(scene); }
bool noBack(const Scene&, const photometry::Table& t) { return photometry::emitsNoBack(t); }

// The general kernel's structures the variants build (beside the forms').
const char* const kGeneralStructures[] = {"",
                                          "triangulation=delaunay",
                                          "triangulation=delaunay,weighting=sample,normalize=formfactor",
                                          "triangulation=delaunay,weighting=dotout,dynamic=cp+np+mrp+barycentre",
                                          "triangulation=delaunay,dynamic=cp+barycentre,normalize=formfactor",
                                          "dynamic=none",
                                          "area=gauss2",
                                          "triangulation=delaunay,static=4"};

// A cubature SPEC's keys (parsed and validated as on the command line).
CubatureOptions optionsOf(const std::string& kv)
{
    return CubatureOptions::parse(parseSpec("cubature" + (kv.empty() ? "" : ":" + kv)).values);
}

}  // namespace

const std::vector<McRule>& mcRules()
{
    static const std::vector<McRule> rules = {
        {Rule::NoHorizon, noHorizon},
        {Rule::NoBack, noBack},
    };
    return rules;
}

const std::vector<CubatureForm>& cubatureForms()
{
    static const std::vector<CubatureForm> forms = {
        {{"-DLB_CUB_RECT_FAN", "rect_fan"}, fanCp, true, {"", "dynamic=none"}},
        {{"-DLB_CUB_RECT_DEL", "rect_del"}, delaunayCpBary, true, {"triangulation=delaunay,dynamic=cp+barycentre"}},
        {{"-DLB_CUB_RECT_DELALL", "rect_del_all"},
         delaunayAll,
         true,
         {"triangulation=delaunay,dynamic=cp+np+mrp+barycentre"}},
        {{"-DLB_CUB_RECT_DELST", "rect_del_static"},
         delaunayStatic,
         false,
         {"triangulation=delaunay,static=1", "triangulation=delaunay,static=3", "triangulation=delaunay,static=4"}},
    };
    return forms;
}

const RuleName& ruleName(Rule r) { return kRuleNames[static_cast<size_t>(r)]; }

std::vector<std::string> cubatureFormDefines()
{
    std::vector<std::string> d;
    for (const auto& f : cubatureForms()) d.push_back(f.name.define);
    d.push_back(kDiskStraightDefine);
    return d;
}

namespace {

// Whether rule r's define is written: the 1D table is one of the LUT, and a
// form's modifiers need a form (the general kernel always clips and blends).
bool written(const Specialization& s, Rule r)
{
    if (!s.has(r)) return false;
    if (r == Rule::Lut1d) return s.has(Rule::Lut);
    if (r == Rule::RectClip || r == Rule::Blend) return s.rectForm();
    return true;
}

const CubatureForm* findForm(const std::string& json)
{
    for (const auto& f : cubatureForms())
        if (json == f.name.json) return &f;
    return nullptr;
}

}  // namespace

std::string Specialization::defines() const
{
    std::string d;
    auto add = [&d](const char* define) { d += std::string(" ") + define; };
    for (Rule r : {Rule::Lut, Rule::Lut1d, Rule::NoHorizon, Rule::NoBack})
        if (written(*this, r)) add(ruleName(r).define);
    if (rectForm()) add(findForm(form)->name.define);
    for (Rule r : {Rule::RectClip, Rule::Blend})
        if (written(*this, r)) add(ruleName(r).define);
    return d;
}

nlohmann::json Specialization::json() const
{
    // "blend" is the scene's fact (some pixel lies beyond blend_dist), with
    // or without a form; every other key says whether its define is written.
    nlohmann::json j = nlohmann::json::object();
    for (int i = 0; i < kRuleCount; ++i) {
        const Rule r = static_cast<Rule>(i);
        j[ruleName(r).json] = r == Rule::Blend ? has(r) : written(*this, r);
    }
    for (const auto& f : cubatureForms()) j[f.name.json] = form == f.name.json;
    return j;
}

CubatureScene::CubatureScene(const Scene& scene, const CubatureOptions& o)
    : unclipped(lightAboveEveryHorizon(scene, o.tunables.horizon_eps + o.tunables.plane_eps)),
      alongU(horizonAlongU(scene)),
      // lb_blend_weight is exactly 0 up to blend_dist; 1e-6 relative covers
      // the kernel's float rounding of the distance.
      farPixel(!(farthestPixel(scene) * (1 + 1e-6) < o.tunables.blend_dist))
{
}

Specialization analyseCubature(const Scene& scene, const photometry::Table& table, const CubatureOptions& o)
{
    Specialization s;
    s.set(Rule::Lut, o.lut);
    if (!o.specialize) return s;
    s.set(Rule::Lut1d, o.lut && photometry::isRotational(table));
    if (scene.shape != LightShape::Rect) return s;  // the forms are the rectangle's
    const CubatureScene sc(scene, o);
    const bool clip = clipAlongU(o, sc);
    for (const auto& f : cubatureForms()) {
        if (!f.applies(o, sc) || !(sc.unclipped || (f.clipOk && clip))) continue;
        s.form = f.name.json;
        s.set(Rule::RectClip, !sc.unclipped);
        break;
    }
    s.set(Rule::Blend, sc.farPixel);
    return s;
}

Specialization analyse(const Scene& scene, const photometry::Table& table, bool lut, bool specialize)
{
    Specialization s;
    s.set(Rule::Lut, lut);
    if (!specialize) return s;
    s.set(Rule::Lut1d, lut && photometry::isRotational(table));
    for (const auto& r : mcRules()) s.set(r.rule, r.applies(scene, table));
    return s;
}

int cubatureLanes(const Specialization& s, const CubatureOptions& o, const std::string& deviceType, bool dbl)
{
    if (!s.rectForm() || !s.has(Rule::Lut) || dbl) return 1;
    return lanesFor(o.lanes, deviceType);
}

std::vector<std::string> cubatureVariants()
{
    std::vector<std::string> v;
    // kv: the structure's SPEC keys; form: its JSON name ("" general); rules on; lanes8: 8 lanes
    auto add = [&v](const std::string& kv, const char* form, std::initializer_list<Rule> rules, bool lanes8) {
        Specialization s;
        s.form = form;
        for (Rule r : rules) s.set(r);
        v.push_back(optionsOf(kv).defines() + s.defines() + (lanes8 ? " -DLB_LANES=8" : ""));
    };
    // the general kernel: each structure with the LUT, every other one also with the exact lookup
    for (size_t i = 0; i < std::size(kGeneralStructures); ++i) {
        add(kGeneralStructures[i], "", {Rule::Lut}, false);
        if (i % 2 == 0) add(kGeneralStructures[i], "", {}, false);
    }
    for (const auto& f : cubatureForms())
        for (const auto& e : f.examples) {
            const std::string sep = e.empty() ? "" : ",";
            const char* form = f.name.json;
            add(e, form, {}, false);
            add(e + sep + "weighting=dotout,normalize=formfactor", form, {Rule::Lut, Rule::Blend}, true);
            if (!f.clipOk) continue;
            add(e + sep + "area=gauss3", form, {Rule::Lut, Rule::RectClip}, true);
            add(e, form, {Rule::Lut, Rule::RectClip, Rule::Blend}, false);
        }
    // the disk's fan (kernels/common/disk.h), alone and with robust's area rule
    add("", "", {Rule::Lut}, false);
    v.back() += " -DLB_CUB_DISK";
    add("area=gauss3", "", {}, false);
    v.back() += " -DLB_CUB_DISK";
    // and its straight-line form (kernels/common/disk_lanes.inc) in one and eight lanes
    const std::string straight = std::string(" -DLB_CUB_DISK ") + kDiskStraightDefine;
    add("", "", {}, false);
    v.back() += straight;
    add("area=gauss2", "", {Rule::Lut}, true);
    v.back() += straight;
    add("area=gauss3", "", {Rule::Lut}, true);
    v.back() += straight;
    return v;
}

}  // namespace lb::methods
