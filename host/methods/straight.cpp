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

StraightLine addStraightLineOptions(Family& f, const std::string& define, StraightApplies applies)
{
    f.params.push_back(
        lookupParam("lut", "intensity lookup: trig-free table (photometry/lut.h, as mc) or the exact bilinear one"));
    if (!define.empty()) {
        f.straightDefines = {define};
        f.params.push_back(specializeParam("auto: the straight-line form where the scene allows it, 1D table for "
                                           "rotational luminaires (methods/straight.h); none: the general kernel"));
        f.params.push_back(lanesParam("pixels per work-item of the straight-line form (float, lut): 8 = float8 "
                                      "code, auto = 8 on CPU devices (PoCL), 1 elsewhere"));
    }
    return StraightLine{define, std::move(applies)};
}

bool StraightLine::uses(const MethodSpec& s, const Scene& scene) const
{
    // the straight-line forms are written for the rectangle
    return !define.empty() && s.str("specialize") == "auto" && scene.shape == LightShape::Rect && applies(scene, s);
}

Plan StraightLine::plan(const MethodSpec& s, const Scene& scene, const photometry::Table& t, const ocl::DeviceInfo& dev,
                        Precision p) const
{
    const bool lut = s.str("lookup") == "lut", on = uses(s, scene);
    Specialization sp;
    sp.set(Rule::Lut, lut);
    sp.set(Rule::Lut1d, lut && on && photometry::isRotational(t));
    Plan plan;
    plan.defines = sp.defines() + (on ? " " + define : std::string());
    plan.lanes = on && lut && p != Precision::Double ? lanesFor(s.str("lanes"), dev.type) : 1;
    plan.lum = [lut, &t] { return lut ? photometry::buildLut(t).packed : t.packed(); };
    return plan;
}

}  // namespace lb::methods
