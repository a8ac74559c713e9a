// reference: globally adaptive cubature of the area form (kernels/reference.cl),
// with a per-pixel error estimate; cached on disk by render(). Also the
// arguments and statistics every adaptive reference shares (registry.h).
#include "methods/registry.h"

#include <algorithm>
#include <numeric>

namespace lb::methods {

void referenceArgs(Plan& p, const MethodSpec& s, const Scene& scene)
{
    const size_t n = static_cast<size_t>(scene.res) * scene.res;
    p.args.push_back(PlanArg::outputReals("errout", n));
    p.args.push_back(PlanArg::outputInts("splits_out", n));
    p.args.push_back(PlanArg::real("rel_tol", s.num("tol")));
    p.args.push_back(PlanArg::integer("max_splits", s.integer("max_splits")));
}

void finishReference(LaunchContext& c)
{
    size_t n = static_cast<size_t>(c.res()) * c.res();
    Image err(c.res(), c.res());
    err.px = c.readReals(c.named.at("errout"), n);
    std::vector<cl_int> splits(n);
    c.rt.queue().enqueueReadBuffer(c.named.at("splits_out"), CL_TRUE, 0, n * sizeof(cl_int), splits.data());
    c.stats["splits_total"] = std::accumulate(splits.begin(), splits.end(), 0L);
    c.stats["splits_max"] = *std::max_element(splits.begin(), splits.end());
    c.stats["pixels_at_budget"] =
        std::count(splits.begin(), splits.end(), static_cast<cl_int>(c.spec.integer("max_splits")));
    c.stats["max_err_est"] = *std::max_element(err.px.begin(), err.px.end());
    c.extraImages["err"] = std::move(err);
}

void referenceIo(Family& f)
{
    f.args = {"errout", "splits_out", "rel_tol", "max_splits"};
    f.plan = [](const MethodSpec& s, const Scene& scene, const photometry::Table&, const ocl::DeviceInfo&, Precision) {
        Plan p;
        referenceArgs(p, s, scene);
        p.finish = finishReference;
        return p;
    };
    f.expensive = true;
}

void registerReference(Registry& r)
{
    Family f;
    f.name = "reference";
    f.summary = "converged area integral (adaptive 4x4 Gauss-Legendre cubature) with an error estimate";
    f.file = "reference.cl";
    f.shapes = {LightShape::Rect, LightShape::Disk};
    f.params = {
        Param::real("tol", 1e-5, 1e-9, 1e-1, Scale::Log, "target relative error per pixel", false),
        Param::integer("max_splits", 128, 0, 128, Scale::Linear,
                       "cell splits per pixel at most (the store holds 4 + 3 x 128 cells)"),
    };
    f.bandRows = 16;
    referenceIo(f);
    r.add(f);
}

}  // namespace lb::methods
