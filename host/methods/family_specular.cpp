// The specular scene's families (docs/design.md section 8, paper Sec. 7):
//   reference  kernels/specular_reference.cl (common/specref.h): adaptive
//              cubature of the area form with an error estimate;
//   mc         kernels/specular_mc.cl: light-sampled MC with a fixed point
//              set (the equal-time baseline), GGX VNDF sampling, their MIS;
//   ltc        kernels/specular_ltc.cl: energy-equivalent radiance (cubature,
//              structured, cp, point; estimated or exact G_Omega) times the
//              LTC integral of the light (the suite's table, host/ltc/ltc.h).
#include "ltc/ltc.h"
#include "methods/registry.h"
#include "methods/samples.h"
#include "methods/specialize.h"
#include "methods/straight.h"

namespace lb::methods {

namespace {

// reference: adaptive cubature of the area form with an error estimate.
Family specularReference()
{
    Family f;
    f.name = "reference";
    f.scenes = {SceneKind::Specular};
    f.summary = "specular scene: converged area integral of I f_r cos / r^2 (adaptive cubature, first mesh "
                "refined at the GGX lobe) with an error estimate";
    f.file = "specular_reference.cl";
    f.params = {
        Param::real("tol", 1e-5, 1e-9, 1e-1, Scale::Log, "target relative error per pixel", false),
        Param::integer("max_splits", 160, 0, 160, Scale::Linear,
                       "adaptive cell splits per pixel at most (the store holds 640 cells)"),
    };
    f.bandRows = 8;
    referenceIo(f);
    return f;
}

// mc: light-sampled MC with a fixed point set, GGX VNDF sampling, their MIS.
Family specularMc()
{
    Family f;
    f.name = "mc";
    f.scenes = {SceneKind::Specular};
    f.summary = "specular scene: MC with N samples: the same N light points for every pixel (light), GGX "
                "visible-normal sampling per pixel (vndf), or both with the balance heuristic (mis)";
    f.file = "specular_mc.cl";
    f.params = {
        Param::integer("n", 24, 1, 1 << 20, Scale::Log, "samples (mis: N light points + N VNDF samples)", true),
        Param::choice("sampling", "light", {"light", "vndf", "mis"},
                      "light: fixed point set on the light; vndf: GGX visible normals, per pixel; mis: both"),
        Param::choice("pattern", "poisson", {"poisson", "halton", "stratified", "random"}, "point set on the light"),
        Param::integer("seed", 0, 0, 2147483647L, Scale::Linear, "seed of the point set and the VNDF hash"),
    };
    // The straight-line form of sampling=light (kernels/common/smc_lanes.inc);
    // the lookup, specialize and lanes parameters as the diffuse families'.
    const StraightLine straight = addStraightLineOptions(
        f, "-DLB_SMC_RECT", [](const Scene&, const MethodSpec& s) { return s.str("sampling") == "light"; });
    f.args = {"st", "n", "seed"};
    f.plan = [straight](const MethodSpec& s, const Scene& scene, const photometry::Table& t, const ocl::DeviceInfo& dev,
                        Precision p) {
        Plan plan = straight.plan(s, scene, t, dev, p);
        const std::string& m = s.str("sampling");
        plan.defines =
            (m == "light" ? "" : (m == "vndf" ? "-DLB_SMC_SAMPLING=1" : "-DLB_SMC_SAMPLING=2")) + plan.defines;
        const int n = static_cast<int>(s.integer("n"));
        const long seed = s.integer("seed");
        plan.args = {PlanArg::realBuffer("st", samplePoints(s.str("pattern"), n, static_cast<std::uint64_t>(seed))),
                     PlanArg::integer("n", n), PlanArg::integer("seed", seed)};
        return plan;
    };
    f.benchSpecs = {"mc:n=8", "mc:n=32", "mc:n=8,sampling=vndf", "mc:n=8,sampling=mis"};
    return f;
}

// ltc's structural defines: the radiance estimator, the cubature's
// triangulation, the exact G_Omega.
std::string ltcDefines(const std::string& rad, const std::string& triangulation, const std::string& gOmega)
{
    std::string d;
    if (rad == "structured") d += " -DLB_LTC_RADIANCE=1";
    if (rad == "cp") d += " -DLB_LTC_RADIANCE=2";
    if (rad == "point") d += " -DLB_LTC_RADIANCE=3";
    if (rad == "cubature" && triangulation == "delaunay") d += " -DLB_CUB_TRI=1";
    if (gOmega == "exact") d += " -DLB_LTC_EXACT_G";
    return d.empty() ? d : d.substr(1);
}

// ltc: energy-equivalent radiance times the LTC integral of the light.
Family specularLtc()
{
    Family f;
    f.name = "ltc";
    f.scenes = {SceneKind::Specular};
    f.summary = "specular scene: energy-equivalent radiance (paper Eq. 13-16) times the LTC integral of the "
                "light (Heitz et al. 2016, the suite's fitted table)";
    f.file = "specular_ltc.cl";
    f.params = {
        Param::choice("radiance", "cubature", {"cubature", "structured", "cp", "point"},
                      "estimator of the diffuse integral and its G_Omega (paper Eq. 15-16)"),
        Param::choice("triangulation", "fan", {"fan", "delaunay"},
                      "cubature: fan around CP (paper 5.2) or Delaunay over CP + barycentre"),
        Param::choice("g_omega", "estimate", {"estimate", "exact"},
                      "G_Omega from the same estimator (paper Eq. 15) or exact (Lambert's polygon formula)"),
        Param::real("plane_eps", 1e-3, 1e-6, 1.0, Scale::Log,
                    "cubature: receivers closer than this (m) to the light's plane are moved to it (paper 5.3)"),
        Param::real("horizon_eps", 0.0, 0.0, 0.5, Scale::Linear,
                    "cubature: clip the light at n_x . (p - x) >= this (m) (thesis 5.2.4)"),
    };
    // The straight-line forms (kernels/common/ltc_lanes.inc): radiance=point, and
    // the cubature's fan where the diffuse cubature's rules rectFan / rectClip
    // hold (methods/specialize.h: nothing clipped, or the horizon cutting along
    // the light's u edges, LB_CUB_RECT_CLIP); both with their own G. The lookup,
    // specialize and lanes parameters as the diffuse families'.
    auto unclipped = [](const Scene& scene, const MethodSpec& s) {
        return lightAboveEveryHorizon(scene, s.num("horizon_eps") + s.num("plane_eps"));
    };
    const StraightLine straight =
        addStraightLineOptions(f, "-DLB_LTC_RECT", [unclipped](const Scene& scene, const MethodSpec& s) {
            if (s.str("g_omega") != "estimate") return false;
            if (s.str("radiance") == "point") return true;
            return s.str("radiance") == "cubature" && s.str("triangulation") == "fan" &&
                (unclipped(scene, s) || horizonAlongU(scene));
        });
    f.args = {"ltc", "plane_eps", "horizon_eps"};
    f.plan = [straight, unclipped](const MethodSpec& s, const Scene& scene, const photometry::Table& t,
                                   const ocl::DeviceInfo& dev, Precision p) {
        Plan plan = straight.plan(s, scene, t, dev, p);
        const std::string& rad = s.str("radiance");
        if (straight.uses(s, scene) && rad == "cubature" && !unclipped(scene, s)) plan.defines += " -DLB_CUB_RECT_CLIP";
        plan.defines = ltcDefines(rad, s.str("triangulation"), s.str("g_omega")) + plan.defines;
        plan.args = {PlanArg::floatBuffer("ltc", ltc::packed(ltc::defaultTable())),
                     PlanArg::real("plane_eps", s.num("plane_eps")),
                     PlanArg::real("horizon_eps", s.num("horizon_eps"))};
        return plan;
    };
    f.benchSpecs = {"ltc", "ltc:triangulation=delaunay", "ltc:radiance=point", "ltc:radiance=structured",
                    "ltc:g_omega=exact"};
    return f;
}

}  // namespace

void registerSpecular(Registry& r)
{
    r.add(specularReference());
    r.add(specularMc());
    r.add(specularLtc());
}

}  // namespace lb::methods
