// mc: one fixed point set for every pixel (kernels/mc.cl, host/methods/samples.h).
#include "methods/registry.h"
#include "methods/samples.h"
#include "methods/specialize.h"
#include "methods/straight.h"

#include <fmt/format.h>

namespace lb::methods {

namespace {

// mcpoints: mc's kernel on N points whose positions are parameters (s_k, t_k),
// so that `lumibench tune` can place them against the error at fixed N: the
// upper bound of what a fixed point set can do at mc's cost per sample.
// Defaults: the first N points of the R2 sequence (Roberts 2018,
// (0.5 + k / g, 0.5 + k / g^2) mod 1, g the plastic number), rounded to 4
// digits: nested, so the defaults of every N are a low-discrepancy set.
constexpr int kMcPointsMax = 16;
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
    f.defines = mc.defines;
    f.sceneDefines = mc.sceneDefines;
    f.lumBuffer = mc.lumBuffer;
    f.args = {"st", "n", "extra"};
    f.setArgs = [](LaunchContext& c) {
        int n = static_cast<int>(c.spec.integer("n"));
        std::vector<double> st;
        for (int k = 1; k <= n; ++k) {
            st.push_back(c.spec.num(fmt::format("s{}", k)));
            st.push_back(c.spec.num(fmt::format("t{}", k)));
        }
        c.arg("st", c.realBuffer(st));
        c.arg("n", cl_int(n));
        c.arg("extra", cl_float(0));
    };
    r.add(f);
}

}  // namespace

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
    registerMcPoints(r, f);
}

}  // namespace lb::methods
