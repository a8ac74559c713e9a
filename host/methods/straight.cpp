#include "methods/straight.h"

#include "methods/specialize.h"
#include "photometry/lut.h"

#include <fmt/format.h>

namespace lb::methods {

std::vector<float> lookupBuffer(const MethodSpec& s, const photometry::Table& t)
{
    return s.str("lookup") == "lut" ? photometry::buildLut(t).packed : t.packed();
}

Param lookupParam(const std::string& def, const std::string& meaning)
{
    return Param::choice("lookup", def, {"lut", "exact"}, meaning);
}

Param specializeParam(const std::string& meaning)
{
    return Param::choice("specialize", "auto", {"auto", "none"}, meaning);
}

Param lanesParam(const std::string& meaning) { return Param::choice("lanes", "auto", {"auto", "1", "8"}, meaning); }

int lanesFor(const std::string& lanes, const std::string& deviceType)
{
    if (lanes != "auto") return std::stoi(lanes);
    return deviceType == "CPU" ? 8 : 1;
}

void addStraightLineOptions(Family& f, const std::string& define, StraightApplies applies)
{
    f.params.push_back(
        lookupParam("lut", "intensity lookup: trig-free table (photometry/lut.h, as mc) or the exact bilinear one"));
    const bool straight = !define.empty();
    if (straight) f.straightDefines = {define};
    if (straight) {
        f.params.push_back(specializeParam("auto: the straight-line form where the scene allows it, 1D table for "
                                           "rotational luminaires (methods/straight.h); none: the general kernel"));
        f.params.push_back(lanesParam("pixels per work-item of the straight-line form (float, lut): 8 = float8 "
                                      "code, auto = 8 on CPU devices (PoCL), 1 elsewhere"));
    }
    auto uses = [straight, applies](const MethodSpec& s, const Scene& scene) {
        return straight && s.str("specialize") == "auto" && applies(scene, s);
    };
    f.sceneDefines = [uses, define](const MethodSpec& s, const Scene& scene, const photometry::Table& t) {
        Specialization sp;
        sp.set(Rule::Lut, s.str("lookup") == "lut");
        bool on = uses(s, scene);
        sp.set(Rule::Lut1d, sp.has(Rule::Lut) && on && photometry::isRotational(t));
        return sp.defines() + (on ? " " + define : std::string());
    };
    f.lumBuffer = lookupBuffer;
    f.lanes = [uses](const MethodSpec& s, const Scene& scene, const photometry::Table&, const ocl::DeviceInfo& dev,
                     Precision p) {
        if (!uses(s, scene) || s.str("lookup") != "lut" || p == Precision::Double) return 1;
        return lanesFor(s.str("lanes"), dev.type);
    };
}

}  // namespace lb::methods
