// engine: the game engines' rect-light baseline (kernels/engine.cl): the exact
// form factor of the horizon-clipped light times the luminaire's radiance
// toward the light's centre.
#include "methods/registry.h"
#include "methods/specialize.h"
#include "methods/straight.h"

namespace lb::methods {

void registerEngine(Registry& r)
{
    Family f;
    f.name = "engine";
    f.summary = "the engines' rect light: exact form factor of the clipped light x radiance toward its centre";
    f.file = "engine.cl";
    f.shapes = {LightShape::Rect, LightShape::Disk};
    // the straight-line form is the unclipped rectangle's (the general kernel clips)
    const StraightLine straight = addStraightLineOptions(
        f, "-DLB_ENG_RECT", [](const Scene& scene, const MethodSpec&) { return lightAboveEveryHorizon(scene); });
    f.args = {};
    f.plan = [straight](const MethodSpec& s, const Scene& scene, const photometry::Table& t, const ocl::DeviceInfo& dev,
                        Precision p) { return straight.plan(s, scene, t, dev, p); };
    r.add(f);
}

}  // namespace lb::methods
