// straight.h -- the lookup / specialize / lanes options shared by the
// families whose kernels have a straight-line form: point, cp,
// structured and voronoi (the cubature has its own rule set, analyseCubature).
//
// A straight-line form is the method for an unclipped rectangle in the light's
// frame, written once over the lane macros of kernels/common/lanes1.h, so it
// runs one pixel per work-item or, in float8, eight (*_lanes.inc). The family
// gets three parameters:
//   lookup=lut|exact       trig-free table (default, as mc and cubature) or the
//                          exact bilinear lookup of docs/design.md section 3;
//   specialize=auto|none   auto: the straight-line form where `applies` says
//                          the scene allows it (and the 1D table for
//                          rotational luminaires); none: the general kernel;
//   lanes=auto|1|8         pixels per work-item of the straight-line form
//                          (float, lut): auto = 8 on CPU devices, 1 elsewhere.
// With an empty `define` the family has no straight-line form and gets only
// `lookup` (np, mrp). The family's plan starts from StraightLine::plan.
#pragma once

#include "methods/registry.h"

#include <functional>
#include <string>
#include <vector>

namespace lb::methods {

// Whether the straight-line form holds for this scene and spec.
using StraightApplies = std::function<bool(const Scene&, const MethodSpec&)>;

// The part of a plan these options decide: the lookup and specialisation
// defines (the straight-line define where specialize=auto and `applies`
// holds), the lanes and the `lum` buffer (lookupBuffer). The family prepends
// its structural defines and adds its arguments.
struct StraightLine {
    std::string define;  // "" for none
    StraightApplies applies;
    // Whether the straight-line form runs for this spec and scene.
    bool uses(const MethodSpec& s, const Scene& scene) const;
    Plan plan(const MethodSpec& s, const Scene& scene, const photometry::Table& t, const ocl::DeviceInfo& dev,
              Precision p) const;
};

// Adds the parameters (and the straight-line define) to f; returns the part
// of the plan they decide.
StraightLine addStraightLineOptions(Family& f, const std::string& define, StraightApplies applies);

// The three parameters, each declared here once (choices, default); the
// meaning is the family's. lookup's default differs between families.
Param lookupParam(const std::string& def, const std::string& meaning);
Param specializeParam(const std::string& meaning);
Param lanesParam(const std::string& meaning);
// Pixels per work-item for lanes=auto|1|8 where a lane form applies:
// auto = 8 on CPU devices (ocl::DeviceInfo::type "CPU"), 1 elsewhere.
int lanesFor(const std::string& lanes, const std::string& deviceType);

// The `lum` buffer (Plan::lum) of a family with the `lookup`
// parameter: the trig-free table of photometry/lut.h for lookup=lut, else the
// exact one. These families (and mc, the specular mc and ltc) use it.
std::vector<float> lookupBuffer(const MethodSpec& s, const photometry::Table& t);

}  // namespace lb::methods
