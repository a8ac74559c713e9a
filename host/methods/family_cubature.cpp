// cubature: scattered sampling (paper 5, thesis 5.2) -- kernels/cubature.cl,
// math in kernels/common/cubature.h, spec keys -> defines in cubature_options.h.
#include "methods/cubature_options.h"
#include "methods/registry.h"
#include "methods/spec.h"
#include "methods/specialize.h"
#include "methods/straight.h"
#include "photometry/lut.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>

namespace lb::methods {

// The defaults `robust` changes (docs/studies/robust.md).
const std::map<std::string, std::string> kRobustDefaults = {{"area", "gauss3"}};
// `tuned`: robust with what `lumibench tune experiments/tune-all-cv-geomean-res32.json` recommends (docs/tuning.md).
const std::map<std::string, std::string> kTunedDefaults = {
    {"area", "gauss3"}, {"corner_inset", "0.58125"}, {"dyn_weight", "0"}};

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

// On a disk the cubature is the fan around the closest point (kernels/common/disk.h
// lb_disk_fan): the rectangle's structural choices and corner tunables have no
// meaning there, and one that differs from the default is refused.
void checkDiskOptions(const MethodSpec& s, const CubatureOptions& o)
{
    std::vector<std::string> bad;
    if (o.triangulation != 0) bad.push_back("triangulation");
    if (o.weighting != 1) bad.push_back("weighting");
    if (o.formfactor) bad.push_back("normalize");
    if (o.dynamic != LB_CUB_CP) bad.push_back("dynamic");
    if (o.staticSamples != 0) bad.push_back("static");
    const MethodSpec d = parseSpec(s.name, s.kind);  // the family's defaults
    for (const char* name : {"blend_dist", "plane_eps", "horizon_eps", "corner_inset", "dyn_weight"})
        if (s.num(name) != d.num(name)) bad.push_back(name);
    if (bad.empty()) return;
    std::string names;
    for (const auto& b : bad) names += (names.empty() ? "" : ", ") + b;
    throw InputError(fmt::format("method {}: on a disk light (shape=disk) the cubature is the fan around the closest "
                                 "point with average weighting (kernels/common/disk.h); {} cannot be set there "
                                 "(spec {})",
                                 s.name, names, s.canonical()));
}

// Triangles and Lawson flips per pixel, from the one untimed launch with
// want_stats = 1 (the timed launches write only the image).
void cubatureStats(LaunchContext& c)
{
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
}

// The spec parsed once and the scene analysed once: the program's defines,
// the lanes, the lookup table, every kernel argument by name, the
// statistics switch and the finish.
Plan cubaturePlan(const MethodSpec& s, const Scene& scene, const photometry::Table& t, const ocl::DeviceInfo& dev,
                  Precision p)
{
    const CubatureOptions o = options(s);
    const Specialization sp = analyseCubature(scene, t, o);
    Plan plan;
    plan.defines = o.defines() + sp.defines();
    plan.lanes = cubatureLanes(sp, o, dev.type, p == Precision::Double);
    if (scene.shape == LightShape::Disk) {
        checkDiskOptions(s, o);
        plan.defines += " -DLB_CUB_DISK";
        // specialize=auto: the straight-line form, eight lanes as the rectangle's forms (float, LUT)
        if (o.specialize) plan.defines += std::string(" ") + kDiskStraightDefine;
        plan.lanes = o.specialize && o.lut && p != Precision::Double ? lanesFor(o.lanes, dev.type) : 1;
    }
    plan.lum = [lut = o.lut, &t] { return lut ? photometry::buildLut(t).packed : t.packed(); };
    // per pixel of the whole image: triangles and flips (cubatureStats)
    PlanArg stats{"stats", PlanArg::Kind::OutputInts};
    stats.count = 2 * static_cast<size_t>(scene.res) * scene.res;
    plan.args = {stats, {"want_stats", PlanArg::Kind::Int, 0}};
#define LB_PLAN_TUNABLE(name) plan.args.push_back({#name, PlanArg::Kind::Real, o.tunables.name});
    LB_CUB_TUNABLES(LB_PLAN_TUNABLE)
#undef LB_PLAN_TUNABLE
    plan.statsSwitch = "want_stats";
    plan.finish = cubatureStats;
    return plan;
}

Family cubatureFamily()
{
    Family f;
    f.name = "cubature";
    f.summary = "scattered sampling: horizon clip, dynamic points, fan or Delaunay spherical-triangle cubature";
    f.file = "cubature.cl";
    f.shapes = {LightShape::Rect, LightShape::Disk};
    f.params = cubatureParams();
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
        // Static samples are inserted like further dynamic points: into a
        // fan they would jump between pixels in the same way.
        if (o.triangulation == 0 && o.staticSamples > 0)
            throw InputError(fmt::format("method {}: static={} needs triangulation=delaunay (inserted into a fan, "
                                         "a sample jumps between fan triangles from pixel to pixel)",
                                         s.name, o.staticSamples));
        // A preset file is read and checked where the SPEC is given (exit 2
        // before any render); the luminaire's entry is picked when it renders.
        if (const std::string& file = s.str("preset"); file != "none") try {
                readPresets(file, s.name, s.kind);
            } catch (const InputError& err) {
                throw InputError(fmt::format("method {}: bad value '{}' for preset: expected {} naming a presets "
                                             "file; {}",
                                             s.name, file, Param::text("preset", "none", "").allowed(), err.what()));
            }
    };
    f.unused = [](const MethodSpec& s, const std::string& name) { return cubatureParamUnused(options(s), name); };
    f.plan = cubaturePlan;
    f.args = {"stats", "want_stats"};
    for (const auto& name : cubatureTunableNames()) f.args.push_back(name);
    f.straightDefines = cubatureFormDefines();
    f.variants = cubatureVariants;
    f.benchSpecs = {"cubature:lanes=1",
                    "cubature:specialize=none,lookup=exact",
                    "cubature:triangulation=delaunay,dynamic=cp+barycentre",
                    "cubature:triangulation=delaunay,dynamic=cp+np+mrp+barycentre",
                    "cubature:triangulation=delaunay,static=1,s1=0.485,t1=0.11",
                    "cubature:normalize=formfactor,weighting=sample"};
    return f;
}

}  // namespace

void registerCubature(Registry& r) { r.add(cubatureFamily()); }

Plan robustPlan(const Scene& scene, const photometry::Table& table, const ocl::DeviceInfo& device, Precision precision)
{
    return cubaturePlan(parseSpec("robust", scene.kind), scene, table, device, precision);
}

// robust: the cubature where it is best (near the light, in front of it) and
// the area form where it is not (far field, the light's own plane): the
// recommended variant of docs/studies/robust.md. Every cubature parameter applies;
// only the defaults differ. With it `tuned`, robust's defaults changed again.
void registerRobust(Registry& r)
{
    Family f = cubatureFamily();
    f.name = "robust";
    f.summary = "cubature blended with the area-form Gauss rule away from the light (docs/studies/robust.md)";
    const std::map<std::string, std::string> defaults = kRobustDefaults;
    for (auto& p : f.params)
        if (auto it = defaults.find(p.name); it != defaults.end()) p.def = it->second;
    f.benchSpecs = {};
    r.add(f);
    f.name = "tuned";
    f.summary = "robust with the parameters tuned on the suite's 20 luminaires (docs/tuning.md)";
    for (auto& p : f.params)
        if (auto it = kTunedDefaults.find(p.name); it != kTunedDefaults.end()) p.def = it->second;
    r.add(f);
}

}  // namespace lb::methods
