// mc: one fixed point set for every pixel (kernels/mc.cl, host/methods/samples.h).
#include "methods/registry.h"
#include "methods/samples.h"
#include "methods/specialize.h"
#include "methods/straight.h"

namespace lb::methods {

void registerMc(Registry& r)
{
    Family f;
    f.name = "mc";
    f.summary = "MCI-N: the same N points on the light for every pixel, area form";
    f.file = "mc.cl";
    f.params = {
        Param::integer("n", 24, 1, 1 << 20, Scale::Log, "number of points on the light", true),
        Param::real("extra", 0, 0, 0.999, Scale::Linear,
                    "fractional sample count N + extra: that share of the work-group tiles, spread evenly, takes "
                    "the N + 1 point set (the equal-time MCI's fine step)",
                    false),
        Param::choice("pattern", "poisson", {"poisson", "halton", "stratified", "random"}, "point set"),
        Param::integer("seed", 0, 0, 4294967295L, Scale::Linear, "seed of the point set (halton: 0 = unshifted)"),
        lookupParam("lut", "intensity lookup: trig-free table (photometry/lut.h) or the exact bilinear one"),
        specializeParam("auto: smallest kernel for the scene (methods/specialize.h); none: the general one"),
    };
    f.defines = [](const MethodSpec&) { return std::string(); };
    f.sceneDefines = [](const MethodSpec& s, const Scene& scene, const photometry::Table& t) {
        return analyse(scene, t, s.str("lookup") == "lut", s.str("specialize") == "auto").defines();
    };
    f.lumBuffer = lookupBuffer;
    f.args = {"st", "n", "extra"};
    f.setArgs = [](LaunchContext& c) {
        int n = static_cast<int>(c.spec.integer("n"));
        double extra = c.spec.num("extra");
        auto seed = static_cast<std::uint64_t>(c.spec.integer("seed"));
        auto st = samplePoints(c.spec.str("pattern"), n, seed);
        if (extra > 0) {  // the N + 1 point set after the N points (kernels/mc.cl)
            auto more = samplePoints(c.spec.str("pattern"), n + 1, seed);
            st.insert(st.end(), more.begin(), more.end());
        }
        c.arg("st", c.realBuffer(st));
        c.arg("n", cl_int(n));
        c.arg("extra", cl_float(extra));
    };
    f.benchSpecs = {"mc:n=8", "mc:n=32", "mc:n=32,lookup=exact"};
    r.add(f);
}

}  // namespace lb::methods
