// sh: the analytic spherical-harmonics method (kernels/sh.cl): the luminaire's
// radiance fitted once in real SH (methods/sh_fit.h), integrated exactly with
// the receiver cosine over the clipped light (kernels/common/sh.h); where the
// fit's error exceeds `threshold`, robust's kernel instead (fallback=robust);
// per pixel, robust where the light subtends less than `near` (blended up to
// 2 near).
#include "methods/cubature_options.h"
#include "methods/registry.h"
#include "methods/spec.h"
#include "methods/sh_fit.h"
#include "photometry/lut.h"

#include <fmt/format.h>

#include <cstdio>

namespace lb::methods {

namespace {

ShFitOptions fitOptions(const MethodSpec& s)
{
    ShFitOptions o;
    o.L = static_cast<int>(s.integer("L"));
    o.kind = s.str("fit");
    o.ridge = s.num("ridge");
    o.hann = s.str("window") == "hann";
    return o;
}

// The statistics every sh render records, and the note where the fit is too coarse.
std::function<void(LaunchContext&)> shFinish(const ShFit& f, double threshold, bool fallback)
{
    const double err = f.error;
    const int L = f.opt.L;
    return [err, L, threshold, fallback](LaunchContext& c) {
        c.stats["sh_fit_error"] = err;
        c.stats["sh_fallback"] = fallback;
        if (err > threshold)
            std::fprintf(stderr,
                         "sh: the fit of degree %d misses this luminaire by %.3g (relative L2 of I; threshold "
                         "%.3g)%s\n",
                         L, err, threshold, fallback ? ": rendered by robust (sh:fallback=robust)" : "");
    };
}

Plan shPlan(const MethodSpec& s, const Scene& scene, const photometry::Table& t, const ocl::DeviceInfo& dev,
            Precision p)
{
    const ShFit& fit = shFit(t, fitOptions(s));
    const double threshold = s.num("threshold");
    if (s.str("fallback") == "robust" && fit.error > threshold) {
        Plan plan = robustPlan(scene, t, dev, p);
        plan.defines = "-DLB_SH_FALLBACK " + plan.defines;
        plan.args.push_back(PlanArg::realBuffer("zc", {0.0}));
        plan.args.push_back(PlanArg::real("far_size", s.num("far")));
        plan.finish = shFinish(fit, threshold, true);
        plan.statsSwitch.clear();  // sh's statistics are its fit's (shFinish): no statistics launch
        return plan;
    }
    Plan plan;
    plan.defines = fmt::format("-DLB_SH_L={}", fit.opt.L);
    const double near = s.num("near");
    const MethodSpec robust = parseSpec("robust", scene.kind);
    // near > 0: robust's general one-pixel kernel (its structural defines and its LUT) away from the light
    if (near > 0) {
        plan.defines += " -DLB_SH_NEAR -DLB_LUT " + CubatureOptions::parse(robust.values).defines();
        plan.lum = [&t] { return photometry::buildLut(t).packed; };
    }
    plan.args = {PlanArg::outputInts("stats", 2), PlanArg::integer("want_stats", 0)};
    for (const auto& name : cubatureTunableNames()) plan.args.push_back(PlanArg::real(name, robust.num(name)));
    plan.args.push_back(PlanArg::realBuffer("zc", shLobes(fit, scene)));
    plan.args.push_back(PlanArg::real("far_size", near > 0 ? near : s.num("far")));
    plan.finish = shFinish(fit, threshold, false);
    return plan;
}

}  // namespace

void registerSh(Registry& r)
{
    Family f;
    f.name = "sh";
    f.summary = "analytic: the radiance in real SH of degree L per hemisphere, integrated exactly over the clipped "
                "light";
    f.file = "sh.cl";
    f.params = {
        Param::integer("L", 8, 0, 16, Scale::Linear,
                       "degree of the fit of the radiance (per hemisphere of the light); the kernel integrates "
                       "degree L + 1 (with the receiver cosine) in 2 L + 4 zonal lobes"),
        Param::choice("fit", "lsq", {"lsq", "projection"},
                      "lsq: least squares of f cos(gamma) against I with a ridge term; projection: of the "
                      "hemisphere's radiance mirrored to the sphere (methods/sh_fit.h)"),
        Param::real("ridge", 1e-7, 1e-12, 1e-2, Scale::Log,
                    "lsq: ridge term, relative to the mean diagonal of the normal equations", false),
        Param::choice("window", "none", {"none", "hann"}, "hann: the coefficients times cos^2(pi l / (2 (L + 1)))"),
        Param::choice("fallback", "robust", {"robust", "none"},
                      "robust: where the fit's relative error exceeds `threshold`, render robust instead"),
        Param::real("far", 0.02, 1e-4, 1, Scale::Log,
                    "radians: where the light's diagonal subtends less than 2 far, E blends into engine's formula "
                    "(the exact table toward the centre times the form factor), fully below far; with near = 0 only",
                    false),
        Param::real("near", 1, 0, 10, Scale::Linear,
                    "radians: where the light's diagonal subtends less than 2 near, E blends per pixel into robust "
                    "(its general one-pixel kernel: robust's image), fully robust below near, and the fit's "
                    "integral runs only where the light subtends more than near (docs/studies/sh-engine.md); 0: "
                    "sh everywhere, with `far`'s blend",
                    false),
        Param::real("threshold", 0.3, 1e-4, 10, Scale::Log,
                    "the fit's relative L2 error of I over the sphere above which sh falls back", false),
    };
    f.args = {"stats", "want_stats"};
    for (const auto& name : cubatureTunableNames()) f.args.push_back(name);
    f.args.push_back("zc");
    f.args.push_back("far_size");
    f.plan = shPlan;
    r.add(f);
}

}  // namespace lb::methods
