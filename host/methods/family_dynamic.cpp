// point, cp, np, mrp: the single-sample baselines of kernels/dynamic.cl.
#include "methods/registry.h"
#include "methods/specialize.h"
#include "methods/straight.h"

namespace lb::methods {

namespace {
// rect: the straight-line form's define ("" for none); needsNoClip: it holds
// only where nothing is clipped (cp samples the horizon-clipped light).
Family dynamicFamily(const std::string& name, const std::string& define, const std::string& summary, bool skew,
                     const std::string& rect, bool needsNoClip)
{
    Family f;
    f.name = name;
    f.summary = summary;
    f.file = "dynamic.cl";
    f.shapes = {LightShape::Rect, LightShape::Disk};
    if (skew)
        f.params.push_back(Param::real("skew", 0.1, 1e-3, 1.0, Scale::Log,
                                       "NP: receiver normal skewed to this component towards the light plane "
                                       "when it misses the plane (thesis 4.2)"));
    const StraightLine straight = addStraightLineOptions(f, rect, [needsNoClip](const Scene& scene, const MethodSpec&) {
        return !needsNoClip || lightAboveEveryHorizon(scene);
    });
    f.args = {"skew"};
    f.plan = [define, straight, skew](const MethodSpec& s, const Scene& scene, const photometry::Table& t,
                                      const ocl::DeviceInfo& dev, Precision p) {
        Plan plan = straight.plan(s, scene, t, dev, p);
        plan.defines = define + plan.defines;
        plan.args = {PlanArg::real("skew", skew ? s.num("skew") : 0.1)};
        return plan;
    };
    return f;
}
}  // namespace

void registerDynamic(Registry& r)
{
    r.add(dynamicFamily("point", "-DLB_DYN_POINT", "one photometric point light at the light's centroid", false,
                        "-DLB_DYN_RECT", false));
    r.add(dynamicFamily("cp", "-DLB_DYN_CP", "one sample at the closest point of the clipped light", false,
                        "-DLB_DYN_RECT", true));
    r.add(dynamicFamily("np", "-DLB_DYN_NP", "one sample at the (clamped) normal point", true, "-DLB_DYN_RECT", true));
    r.add(dynamicFamily("mrp", "-DLB_DYN_MRP", "one sample at the most representative point", true, "-DLB_DYN_RECT",
                        true));
}

}  // namespace lb::methods
