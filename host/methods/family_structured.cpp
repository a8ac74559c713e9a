// structured: corners + barycentre of the clipped light (kernels/structured.cl).
#include "methods/registry.h"
#include "methods/specialize.h"
#include "methods/straight.h"

namespace lb::methods {

void registerStructured(Registry& r)
{
    Family f;
    f.name = "structured";
    f.summary = "structured sampling: corners + barycentre of the clipped light (paper Eq. 4)";
    f.file = "structured.cl";
    f.shapes = {LightShape::Rect, LightShape::Disk};
    // the straight-line form samples the whole rectangle: only where nothing is clipped
    const StraightLine straight = addStraightLineOptions(
        f, "-DLB_STRUCT_RECT", [](const Scene& scene, const MethodSpec&) { return lightAboveEveryHorizon(scene); });
    f.plan = [straight](const MethodSpec& s, const Scene& scene, const photometry::Table& t, const ocl::DeviceInfo& dev,
                        Precision p) { return straight.plan(s, scene, t, dev, p); };
    r.add(f);
}

}  // namespace lb::methods
