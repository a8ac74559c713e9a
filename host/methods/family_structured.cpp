// structured: corners + barycentre of the clipped light (kernels/structured.cl).
#include "methods/registry.h"

namespace lb::methods {

void registerStructured(Registry& r)
{
    Family f;
    f.name = "structured";
    f.summary = "structured sampling: corners + barycentre of the clipped light (paper Eq. 4)";
    f.file = "structured.cl";
    f.defines = [](const MethodSpec&) { return std::string(); };
    f.setArgs = [](LaunchContext&, int) {};
    r.add(f);
}

} // namespace lb::methods
