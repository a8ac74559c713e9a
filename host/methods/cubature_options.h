// cubature_options.h -- the `cubature` method's parameters (docs/design.md section 4),
// declared once in cubatureParams() (name, choices, default, range,
// meaning): the SPEC parser, the tuner and the result files read that table,
// and CubatureOptions is derived from it -- the kernel's structural -D
// defines (kernels/cubature.cl) and its continuous arguments.
#pragma once

#include "math/kmath.h"
#include "methods/param.h"

#include <map>
#include <string>
#include <vector>

namespace lb::methods {

// Default of area_q (docs/studies/robust.md): the area rule alone from half a light
// size on, where the 3 x 3 rule's derived bound 2/700 (a/rho)^6 is 18 % at
// worst and falls to 0.3 % at one light size; the cubature alone within a
// quarter. Measured best of 0.1, 0.5 and 1 on the published luminaires.
inline constexpr double kDefaultAreaQ = 0.5;
// Default of area_sin: the cubature alone where its samples' 1/|n_L . d|
// amplifies the table at most twofold (the farthest corner at 30 degrees
// elevation or more).
inline constexpr double kDefaultAreaSin = 0.5;
// Static samples at most (the `static` parameter; LB_CUB_STATIC of
// kernels/common/cubature.h, which sizes the triangulation for them).
inline constexpr int kMaxStaticSamples = 4;

// The cubature family's parameters, in SPEC order: triangulation, weighting,
// normalize, dynamic, plane_eps, horizon_eps, corner_inset, dyn_weight,
// blend_dist, lookup, specialize, lanes, area, area_q, area_sin, static,
// s1, t1, .., s4, t4, preset
// (resolved per luminaire before the options are read: methods/spec.h
// resolvePreset).
const std::vector<Param>& cubatureParams();

// The names of the kernel's real-valued arguments, in kernel order: the
// fields of lb_cub_tunables (kernels/common/cubature.h LB_CUB_TUNABLES), each
// a Real parameter of cubatureParams().
std::vector<std::string> cubatureTunableNames();

// A cubature SPEC's values as the kernel takes them. Every field is read
// from the parameter of the same name (cubatureParams: its meaning there).
struct CubatureOptions {
    int triangulation;  // index of the choice: 0 fan (paper 5.2), 1 delaunay (thesis 5.2)
    int weighting;  // 0 sample (paper Eq. 9), 1 average (Eq. 10), 2 dotout
    bool formfactor;  // normalize=formfactor (thesis Eq. 5.11)
    int dynamic;  // bit set of kernels/common/cubature.h: LB_CUB_CP, _NP, _MRP, _BARY
    lb::f64::lb_cub_tunables tunables;  // the kernel's real arguments, by the parameters' names
    bool lut;  // lookup=lut
    bool specialize;  // specialize=auto
    std::string lanes;  // auto | 1 | 8 (lanesFor, methods/straight.h)
    int area;  // Gauss-Legendre points per side: 0 (none), 2 or 3
    int staticSamples;  // static: 0 .. kMaxStaticSamples (LB_CUB_STATIC)

    // The defaults of cubatureParams().
    CubatureOptions();
    // Key=value pairs (a MethodSpec's values, or some of them: the rest take
    // their defaults), each checked against its parameter; an unknown key or
    // a bad value throws lb::InputError naming the key and what is allowed.
    static CubatureOptions parse(const std::map<std::string, std::string>& kv);

    // "-DLB_CUB_TRI=.. -DLB_CUB_WEIGHT=.. -DLB_CUB_NORMALIZE=.. -DLB_CUB_DYNAMIC=.. [-DLB_CUB_AREA=..]
    // [-DLB_CUB_STATIC=..]" (the last only with static samples, so that the
    // programs without them keep their options)
    std::string defines() const;

private:
    struct NoDefaults {};
    explicit CubatureOptions(NoDefaults) {}
};

// "cp+barycentre" -> LB_CUB_CP | LB_CUB_BARY; "none" -> 0 (alone only);
// throws lb::InputError on anything else.
int parseDynamicSet(const std::string& s);
std::string dynamicSetName(int mask);

// Whether cubature parameter `name` has no effect under options o: s_k and
// t_k beyond o.staticSamples, area_q and area_sin without `area` (a tuner
// does not search them).
bool cubatureParamUnused(const CubatureOptions& o, const std::string& name);

}  // namespace lb::methods
