// specialize.h -- "leave out what a given scene does not need": the host
// analyses one scene and luminaire and picks the smallest kernel variant.
//
// Every rule is a row of a table below, with its -D define and its key in the
// records' JSON: the lookup rules (every family with `lookup`), mc's scene
// rules (mcRules), the cubature's straight-line forms (cubatureForms) and
// their modifiers. Each rule only drops work whose result is known to be 0 or
// the identity, so the specialised kernel equals the general one up to
// rounding (tests/methods/test_specialize.cpp). Why each rule holds (the
// proof that Delaunay over corners + CP never flips on an unclipped
// rectangle among them) and what it measured: docs/design.md, "Kernel
// specialisation".
#pragma once

#include "methods/cubature_options.h"

#include "photometry/table.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <bitset>
#include <string>
#include <vector>

namespace lb::methods {

// The rules beside the cubature's forms. Their defines are written in this
// order, the form's (at most one, a row of cubatureForms) after NoBack.
enum class Rule {
    Lut,  // trig-free table (common/lut.h)
    Lut1d,  // with Lut, every C plane equal: a 1D table over gamma
    NoHorizon,  // mc: every sample has a positive receiver cosine
    NoBack,  // mc: nothing emitted at gamma >= 90 deg
    RectClip,  // the form runs on the rectangle a clip along u leaves
    Blend,  // some pixel lies beyond blend_dist (the form then blends into the grid MC)
};
inline constexpr int kRuleCount = 6;

// A rule's or a form's names: the program's -D option and its key in the
// records' JSON (the specialisation objects of `bench --json`).
struct RuleName {
    const char* define;  // "-DLB_LUT"
    const char* json;  // "lut"
};

struct Specialization {
    std::bitset<kRuleCount> on;
    std::string form;  // the cubature's straight-line form that runs (its JSON name), "" for none

    bool has(Rule r) const { return on.test(static_cast<size_t>(r)); }
    void set(Rule r, bool v = true) { on.set(static_cast<size_t>(r), v); }
    // Whether a straight-line cubature form runs.
    bool rectForm() const { return !form.empty(); }
    std::string defines() const;  // " -DLB_LUT ..." (leading space when not empty)
    nlohmann::json json() const;  // every rule's and form's JSON key -> whether it holds
};

// The names of rule r.
const RuleName& ruleName(Rule r);

// mc's scene rules (kernels/mc.cl): each drops work the scene and luminaire
// make 0 or the identity.
struct McRule {
    Rule rule;
    bool (*applies)(const Scene&, const photometry::Table&);
};
const std::vector<McRule>& mcRules();

// The facts about one scene that the cubature's rules read, computed once.
struct CubatureScene {
    bool unclipped;  // every light corner above horizon_eps + plane_eps over every pixel
    bool alongU;  // horizonAlongU: a clip cuts the light along its u edges
    bool farPixel;  // some pixel lies beyond blend_dist from the light's centre
    CubatureScene(const Scene& scene, const CubatureOptions& o);
};

// One straight-line form of the cubature (kernels/cubature.cl): its names,
// for which methods (options) and scenes it holds on the unclipped rectangle,
// whether it also runs on what a clip along u leaves, and the cubature SPEC
// keys of the structures it is written for (the variants the kernel test
// builds). The conditions exclude each other: at most one form applies.
struct CubatureForm {
    RuleName name;
    bool (*applies)(const CubatureOptions&, const CubatureScene&);
    bool clipOk;
    std::vector<std::string> examples;  // "triangulation=delaunay,dynamic=cp+barycentre"
};
const std::vector<CubatureForm>& cubatureForms();

// The disk's straight-line form (kernels/common/disk_lanes.inc), with -DLB_CUB_DISK:
// the cubature on a disk with fixed sectors and nodes, one or eight pixels per work-item.
inline constexpr const char* kDiskStraightDefine = "-DLB_CUB_DISK_STRAIGHT";

// The defines of the cubature's straight-line forms and the disk's (Family::straightDefines).
std::vector<std::string> cubatureFormDefines();

// The program options the cubature kernel must build with (the `@variants`
// its test builds): the general kernel's structures, and each form of
// cubatureForms with the lookup, lanes, clip, blend and area on and off.
std::vector<std::string> cubatureVariants();

// mc's analysis; `lut` says whether the trig-free table is wanted, and
// `specialize` = false gives the general kernel (only the lookup choice).
Specialization analyse(const Scene& scene, const photometry::Table& table, bool lut, bool specialize = true);

// The cubature's analysis: lookup, lut1d, the forms and their modifiers.
// o.lut and o.specialize choose as for mc.
Specialization analyseCubature(const Scene& scene, const photometry::Table& table, const CubatureOptions& o);

// Pixels per work-item for the cubature: o.lanes (lanesFor, methods/straight.h)
// where a straight-line form (rectForm) runs in float with the LUT, else 1.
int cubatureLanes(const Specialization& s, const CubatureOptions& o, const std::string& deviceType, bool dbl);

// Whether the receiver normal is perpendicular to the light's u axis, exactly
// in float and double (every normalized scene): the horizon then cuts the
// light along its u edges (rule RectClip).
bool horizonAlongU(const Scene& scene);

// Whether every light corner is more than `margin` (m) above the receiver of
// every pixel.
bool lightAboveEveryHorizon(const Scene& scene, double margin = 0);

}  // namespace lb::methods
