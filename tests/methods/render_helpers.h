// render_helpers.h -- one untimed, uncached render and a scene at (h, R, res),
// shared by the method tests.
#pragma once

#include "methods/render.h"
#include "scene/scene.h"

#include <string>

namespace lb::test {

// One render (reps = 1, no disk cache) of `spec` on scene `sc`.
inline methods::RenderResult run(ocl::Runtime& rt, const photometry::Table& t, const Scene& sc, const std::string& spec,
                                 methods::Precision p = methods::Precision::Double)
{
    methods::RenderOptions opt;
    opt.reps = 1;
    opt.useCache = false;
    return methods::render(rt, t, sc, methods::parseSpec(spec, sc.kind), p, opt);
}

// The normalized scene at height h, rotation R, res x res pixels (other fields default).
inline Scene scene(double h, double R, int res)
{
    Scene s;
    s.height = h;
    s.rotation = R;
    s.res = res;
    return s;
}

}  // namespace lb::test
