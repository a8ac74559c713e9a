// mc: one fixed point set for every pixel (kernels/mc.cl, host/methods/samples.h).
#include "methods/mc_denoise.h"
#include "methods/mc_options.h"
#include "methods/mc_table.h"
#include "methods/registry.h"
#include "methods/samples.h"
#include "methods/specialize.h"
#include "methods/straight.h"

#include <fmt/format.h>

#include <cstdint>

namespace lb::methods {

namespace {

// mcpoints: mc's kernel on N points whose positions are parameters (s_k, t_k),
// so that `lumibench tune` can place them against the error at fixed N: the
// upper bound of what a fixed point set can do at mc's cost per sample.
// Defaults: the first N points of the R2 sequence (Roberts 2018,
// (0.5 + k / g, 0.5 + k / g^2) mod 1, g the plastic number), rounded to 4
// digits: nested, so the defaults of every N are a low-discrepancy set.
constexpr int kMcPointsMax = 16;

// mc.cl's arguments after P, lum, out, row0.
const std::vector<std::string> kMcArgs = {"st", "n", "extra", "seed", "np", "lg", "min_solid", "var", "tab"};

// The sampling arguments of the extended path (kernels/mc.cl: mc_ext); `var`
// gets the per-pixel variance where the a-trous filter needs it, `tab` the
// table sampler where the domain samples by the table (else one float).
std::vector<PlanArg> samplingArgs(const McOptions& o, int n, bool extra, std::uint64_t seed, int res,
                                  const photometry::Table* t = nullptr)
{
    size_t npx = o.denoise == "atrous" ? static_cast<size_t>(res) * res : 1;
    const bool byTable = t && o.domain.rfind("table") != std::string::npos;
    return {PlanArg::integer("seed", static_cast<std::int32_t>(static_cast<std::uint32_t>(seed))),
            PlanArg::integer("np", o.projectedOf(n)),
            PlanArg::integer("lg", mcLog2(n + (extra ? 1 : 0))),
            PlanArg::real("min_solid", o.minSolid),
            PlanArg::outputReals("var", npx),
            PlanArg::floatBuffer("tab", byTable ? mcTableSampler(*t) : std::vector<float>{0.0f})};
}

// mc.cl's point-set arguments, then the sampling arguments.
std::vector<PlanArg> mcArgs(std::vector<double> st, int n, double extra, std::vector<PlanArg> sampling)
{
    std::vector<PlanArg> a = {PlanArg::realBuffer("st", std::move(st)), PlanArg::integer("n", n),
                              PlanArg::single("extra", static_cast<float>(extra))};
    a.insert(a.end(), sampling.begin(), sampling.end());
    return a;
}
constexpr double kR2[kMcPointsMax][2] = {{0.5, 0.5},       {0.2549, 0.0698}, {0.0098, 0.6397}, {0.7646, 0.2095},
                                         {0.5195, 0.7794}, {0.2744, 0.3492}, {0.0293, 0.919},  {0.7841, 0.4889},
                                         {0.539, 0.0587},  {0.2939, 0.6286}, {0.0488, 0.1984}, {0.8037, 0.7682},
                                         {0.5585, 0.3381}, {0.3134, 0.9079}, {0.0683, 0.4778}, {0.8232, 0.0476}};

// k (1-based) of a parameter named s<k> or t<k>, else 0.
int pointIndex(const std::string& name)
{
    if (name.size() < 2 || (name[0] != 's' && name[0] != 't')) return 0;
    int k = 0;
    for (size_t i = 1; i < name.size(); ++i) {
        if (name[i] < '0' || name[i] > '9') return 0;
        k = 10 * k + (name[i] - '0');
    }
    return k;
}

void registerMcPoints(Registry& r, const Family& mc)
{
    Family f;
    f.name = "mcpoints";
    f.summary = "MCI-N at N tunable points (s_k, t_k) on the light, mc's kernel: tuned, a bound of fixed point sets";
    f.file = mc.file;
    f.shapes = mc.shapes;
    f.params = {Param::integer("n", 8, 1, kMcPointsMax, Scale::Linear, "number of points on the light")};
    for (int k = 1; k <= kMcPointsMax; ++k) {
        f.params.push_back(Param::real(fmt::format("s{}", k), kR2[k - 1][0], 0, 1, Scale::Linear,
                                       fmt::format("point {} along the light's u (0..1; used when n >= {})", k, k)));
        f.params.push_back(Param::real(fmt::format("t{}", k), kR2[k - 1][1], 0, 1, Scale::Linear,
                                       fmt::format("point {} along the light's v (0..1; used when n >= {})", k, k)));
    }
    for (const auto& name : {"lookup", "specialize"})
        for (const auto& p : mc.params)
            if (p.name == name) f.params.push_back(p);
    f.unused = [](const MethodSpec& s, const std::string& name) {
        int k = pointIndex(name);
        return k > s.integer("n");
    };
    f.args = kMcArgs;
    f.plan = [](const MethodSpec& s, const Scene& scene, const photometry::Table& t, const ocl::DeviceInfo&,
                Precision) {
        Plan plan;
        plan.defines = analyse(scene, t, s.str("lookup") == "lut", s.str("specialize") == "auto").defines();
        plan.lum = [s, &t] { return lookupBuffer(s, t); };
        const int n = static_cast<int>(s.integer("n"));
        std::vector<double> st;
        for (int k = 1; k <= n; ++k) {
            st.push_back(s.num(fmt::format("s{}", k)));
            st.push_back(s.num(fmt::format("t{}", k)));
        }
        if (scene.shape == LightShape::Disk) mapToDisk(st);
        plan.args = mcArgs(st, n, 0, samplingArgs(McOptions{}, n, false, 0, scene.res));
        return plan;
    };
    r.add(f);
}

// mc's render plan: the kernel's defines (the straight-line form where it
// applies), the lookup, the point set (shared sequence) and the arguments.
Plan mcPlan(const MethodSpec& s, const Scene& scene, const photometry::Table& t, const ocl::DeviceInfo& dev,
            Precision p)
{
    const McOptions o = mcOptions(s);
    const int n = static_cast<int>(s.integer("n"));
    const double extra = s.num("extra");
    const auto seed = static_cast<std::uint64_t>(s.integer("seed"));
    const bool lut = s.str("lookup") == "lut", specialize = s.str("specialize") == "auto";
    Plan plan;
    plan.defines = mcDefines(o) + analyse(scene, t, lut, specialize).defines() + mcSceneDefines(o, scene, n);
    if (mcStraight(o, scene, lut, specialize)) {
        // the straight-line form: eight pixels per work-item in float on CPUs
        plan.defines += " -DLB_MC_STRAIGHT";
        plan.lanes = p == Precision::Double ? 1 : lanesFor("auto", dev.type);
    }
    plan.lum = [s, &t] { return lookupBuffer(s, t); };
    std::vector<double> st;
    if (o.sequence == "shared") {
        st = samplePoints(o.pattern, n, seed);
        if (extra > 0) {  // the N + 1 point set after the N points (kernels/mc.cl)
            auto more = samplePoints(o.pattern, n + 1, seed);
            st.insert(st.end(), more.begin(), more.end());
        }
        // area samples of a disk: the set mapped onto it (solid angle maps
        // the unit square itself, common/disk_sample.h)
        if (scene.shape == LightShape::Disk && o.domain == "area") mapToDisk(st);
    }
    const int renderRes = mcRenderRes(s.num("scale"), scene.res);
    if (renderRes != scene.res) plan.renderRes = renderRes;
    plan.args = mcArgs(st, n, extra, samplingArgs(o, n, extra > 0, seed, renderRes, &t));
    plan.bind = [o](LaunchContext& c) { bindDenoise(c, o); };
    plan.postPasses = [](LaunchContext& c) {
        std::vector<StageEvent> ev =
            denoisePasses(c, mcOptions(c.spec), c.spec.num("atrous_sigma"), c.spec.integer("n"));
        if (c.res() != c.imageRes) ev.push_back(upsamplePass(c));
        return ev;
    };
    return plan;
}

}  // namespace

void registerMc(Registry& r)
{
    Family f;
    f.name = "mc";
    f.summary = "Monte Carlo with N samples: MCI-N (the same N points on the light for every pixel, area form) by "
                "default; solid-angle, projected-solid-angle or MIS sampling with per-pixel sequences";
    f.file = "mc.cl";
    f.shapes = {LightShape::Rect, LightShape::Disk};
    f.params = {
        Param::integer("n", 24, 1, 1 << 20, Scale::Log, "number of points on the light", true),
        Param::real("extra", 0, 0, 0.999, Scale::Linear,
                    "fractional sample count N + extra: that share of the work-group tiles, spread evenly, takes "
                    "the N + 1 point set (the equal-time MCI's fine step)",
                    false),
        Param::real("scale", 1, kMinScale, 1, Scale::Linear,
                    "render at round(scale x res) pixels per side, then upsample bilinearly: MC below one sample "
                    "per pixel (the equal-time search's step under N = 1, its protocol's subpixel); a filter runs "
                    "at the smaller size, its footprint kept in metres",
                    false),
        Param::choice("pattern", "poisson", {"poisson", "halton", "stratified", "random"},
                      "point set of sequence=shared"),
        Param::integer("seed", 0, 0, 4294967295L, Scale::Linear,
                       "seed of every randomised sequence and of the shared set (halton: 0 = unshifted)"),
        Param::choice("domain", "area", {"area", "solid", "projected", "mis", "table", "mis_table", "mis_table_solid"},
                      "sampling: uniform on the light's area; uniform in solid angle (spherical rectangle, Urena et "
                      "al. 2013); by the receiver's cosine (projected solid angle); area + projected by the balance "
                      "heuristic; by the luminaire's intensity table over the light's window of directions; table + "
                      "projected, table + solid angle by the balance heuristic. All but area sample the part above the "
                      "horizon. A disk takes area and solid (uniform in solid angle over the whole disk)"),
        Param::choice("sequence", "shared", {"shared", "random", "sobol", "zsobol"},
                      "points: one set for every pixel (pattern); hashed per pixel; Owen-scrambled Sobol per pixel "
                      "(Burley 2020); Morton-ordered digit-permuted Sobol (Ahmed and Wonka 2020, pbrt-v4 ZSobol)"),
        Param::integer("shift", 0, 0, 1, Scale::Linear, "sequence=shared: a random shift of the set per pixel"),
        Param::integer("cosine_warp", 0, 0, 1, Scale::Linear,
                       "domain=solid: warp by the receiver cosine at the corners (Hart et al. 2020)"),
        Param::real("min_solid", 1e-3, 0, 1, Scale::Log,
                    "domain=solid, mis_table_solid: area sampling (exact pdf) below this solid angle (sr)", false),
        Param::real("mis_split", 0.5, 0, 1, Scale::Linear,
                    "domain=mis, mis_table: share of the N samples that are projected (mis_table_solid: by solid "
                    "angle)",
                    false),
        Param::choice(
            "denoise", "none", {"none", "gauss16", "atrous"},
            "image filter after the render, timed with it: the paper's separable Gaussian (DN 2 x 16), or the "
            "edge-avoiding a-trous wavelet filter on the per-pixel variance (Dammertz et al. 2010); "
            "footprint fixed in metres (methods/mc_denoise.h)"),
        Param::real("gauss_sigma", 0, 0, 64, Scale::Linear,
                    "denoise=gauss16: sigma in pixels of the filtered image (0: 4 pixels at 512^2, scaled with the "
                    "resolution; methods/mc_denoise.h)",
                    false),
        Param::integer("gauss_radius", 0, 0, 128, Scale::Linear,
                       "denoise=gauss16: taps -radius .. radius in pixels (0: ceil(2 sigma); given alone, sigma = "
                       "radius / 2: gauss_radius=16 is the paper's filter at 1920 x 1080)"),
        Param::real("atrous_sigma", 4, 0.1, 100, Scale::Log,
                    "denoise=atrous: edge stop, in standard deviations of a pixel's estimate", false),
        Param::integer("paper", 0, 0, 1, Scale::Linear,
                       "the paper's MC as its code runs it: solid angle, Halton points shared by the pixels with a "
                       "per-pixel random shift, area sampling below 1e-3 sr"),
        lookupParam("lut", "intensity lookup: trig-free table (photometry/lut.h) or the exact bilinear one"),
        specializeParam("auto: smallest kernel for the scene (methods/specialize.h); none: the general one"),
    };
    f.validate = [](const MethodSpec& s) {
        validateMc(s);
        validateDenoise(s);
    };
    f.args = kMcArgs;
    f.plan = mcPlan;
    f.benchSpecs = {"mc:n=8", "mc:n=32", "mc:n=32,lookup=exact"};
    r.add(f);
    registerMcPoints(r, f);
}

}  // namespace lb::methods
