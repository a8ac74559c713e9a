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
    f.defines = [](const MethodSpec&) { return std::string(); };
    // the straight-line form samples the whole rectangle: only where nothing is clipped
    addStraightLineOptions(f, "-DLB_STRUCT_RECT",
                           [](const Scene& scene, const MethodSpec&) { return lightAboveEveryHorizon(scene); });
    f.setArgs = [](LaunchContext&) {};
    r.add(f);
}

}  // namespace lb::methods
