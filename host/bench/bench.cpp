#include "bench/bench.h"

#include "experiments/results.h"
#include "methods/cubature_options.h"
#include "methods/registry.h"
#include "methods/samples.h"
#include "methods/specialize.h"
#include "photometry/lut.h"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

namespace lb::bench {

namespace {

// One kernel with its buffers, timed over the whole image.
struct Bench {
    ocl::Runtime& rt;
    const Scene& scene;
    const Options& opt;

    cl::Buffer floats(const std::vector<float>& v)
    {
        return cl::Buffer(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, v.size() * sizeof(float),
                          const_cast<float*>(v.data()));
    }
    cl::Buffer reals(const std::vector<double>& v)
    {
        std::vector<float> f(v.begin(), v.end());
        return floats(f);
    }
    // `lanes` pixels of a row per work-item (methods::Family::lanes).
    double time(cl::Kernel& k, int lanes = 1)
    {
        size_t cols = (scene.res + lanes - 1) / lanes;
        return rt.time([&] { return rt.launch2D(k, cols, scene.res, opt.lx, opt.ly); }, opt.reps, 1).median_ms;
    }

    // naive.cl or mc.cl: render(P, lum, out, row0, st, n).
    double mc(const std::string& file, const std::string& defines, const std::vector<float>& lum, int n)
    {
        cl::Kernel k = rt.kernel(file, "render", defines);
        auto st = methods::samplePoints("poisson", n, 0);
        cl::Buffer P = reals(scene.params()), L = floats(lum), S = reals(st);
        cl::Buffer out(rt.context(), CL_MEM_WRITE_ONLY, sizeof(float) * scene.res * scene.res);
        k.setArg(0, P);
        k.setArg(1, L);
        k.setArg(2, out);
        k.setArg(3, cl_int(0));
        k.setArg(4, S);
        k.setArg(5, cl_int(n));
        return time(k);
    }

    // cubature.cl: render(P, lum, out, row0, stats, want_stats, plane_eps, horizon_eps,
    // corner_inset, dyn_weight, blend_dist),
    // without the per-pixel statistics (want_stats = 0).
    double cubature(const std::string& defines, const std::vector<float>& lum, int lanes = 1)
    {
        cl::Kernel k = rt.kernel("cubature.cl", "render",
                                 lanes > 1 ? defines + fmt::format(" -DLB_LANES={}", lanes) : defines);
        methods::CubatureOptions co;
        cl::Buffer P = reals(scene.params()), L = floats(lum);
        cl::Buffer out(rt.context(), CL_MEM_WRITE_ONLY, sizeof(float) * scene.res * scene.res);
        cl::Buffer stats(rt.context(), CL_MEM_WRITE_ONLY, 2 * sizeof(cl_int));
        k.setArg(0, P);
        k.setArg(1, L);
        k.setArg(2, out);
        k.setArg(3, cl_int(0));
        k.setArg(4, stats);
        k.setArg(5, cl_int(0));
        ocl::setReal(k, 6, co.planeEps, false);
        ocl::setReal(k, 7, co.horizonEps, false);
        ocl::setReal(k, 8, co.cornerInset, false);
        ocl::setReal(k, 9, co.dynWeight, false);
        ocl::setReal(k, 10, co.blendDist, false);
        return time(k, lanes);
    }
};

} // namespace

nlohmann::json run(ocl::Runtime& rt, const photometry::Table& table, const Scene& scene0, const Options& opt)
{
    Scene scene = scene0;
    scene.res = opt.res;
    Bench b{rt, scene, opt};
    const double px = double(scene.res) * scene.res;
    const auto exact = table.packed();
    const auto lut = photometry::buildLut(table);
    const auto spec = methods::analyse(scene, table, true, true);
    const auto general = methods::analyse(scene, table, true, false);
    const auto specExact = methods::analyse(scene, table, false, true);

    nlohmann::json doc;
    doc["device"] = rt.info().name;
    doc["driver"] = rt.info().platform + " " + rt.info().driver;
    // commit, date, host, compiler (as the experiments' result files)
    doc["context"] = results::makeContext(rt.info().name, doc["driver"].get<std::string>(), nullptr);
    doc["res"] = scene.res;
    doc["reps"] = opt.reps;
    doc["local"] = {opt.lx, opt.ly};
    doc["luminaire"] = table.source.empty() ? table.format : table.source;
    doc["scene"] = scene.describe();
    doc["specialization"] = spec.json();
    doc["lut"] = {{"ng", lut.ng}, {"na", lut.na}, {"error_bound_rel", lut.errorBound / table.maxCd()}};

    // 1. Samples per second: naive against the fast kernel, same N, same run.
    // The machine may be shared: naive and fast alternate in `rounds` rounds
    // and each keeps its median, so a burst of load hits both alike.
    int n = opt.samples;
    std::vector<double> naives, fasts;
    for (int r = 0; r < opt.rounds; ++r) {
        naives.push_back(b.mc("naive.cl", "", exact, n));
        fasts.push_back(b.mc("mc.cl", spec.defines(), lut.packed, n));
    }
    double naive = ocl::summarize(naives).median_ms, fast = ocl::summarize(fasts).median_ms;
    double fastExact = b.mc("mc.cl", specExact.defines(), exact, n);
    double generalLut = b.mc("mc.cl", general.defines(), lut.packed, n);
    auto sps = [&](double ms) { return px * n / (ms * 1e-3); };
    double ratio = naive / fast;
    doc["mc"] = {{"n", n},
                 {"rounds", opt.rounds},
                 {"naive_rounds_ms", naives},
                 {"fast_rounds_ms", fasts},
                 {"naive_ms", naive},
                 {"fast_ms", fast},
                 {"fast_exact_ms", fastExact},
                 {"general_lut_ms", generalLut},
                 {"naive_sps", sps(naive)},
                 {"fast_sps", sps(fast)},
                 {"ratio", ratio},
                 {"target", 10},
                 {"ok", ratio >= 10}};

    // 2. MC time against N (near linear, DESIGN 6): least-squares line.
    std::vector<int> ns = opt.quick ? std::vector<int>{1, 8, 32} : std::vector<int>{1, 4, 8, 16, 32, 64, 128};
    nlohmann::json pts = nlohmann::json::array();
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    double mc8 = 0;
    for (int k : ns) {
        double t = b.mc("mc.cl", spec.defines(), lut.packed, k);
        if (k == 8) mc8 = t;
        pts.push_back({k, t});
        sx += k, sy += t, sxx += double(k) * k, sxy += k * t;
    }
    double m = double(ns.size());
    double slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
    double t0 = (sy - slope * sx) / m;
    doc["mc_fit"] = {{"points", pts}, {"t0_ms", t0}, {"ms_per_sample", slope}};

    // 3. Every method's time per pixel.
    nlohmann::json methods = nlohmann::json::array();
    auto add = [&](const std::string& name, double ms, const std::string& defines) {
        methods.push_back({{"method", name}, {"time_ms", ms}, {"ns_per_pixel", ms * 1e6 / px}, {"defines", defines}});
    };
    add(fmt::format("naive mc:n={}", n), naive, "");
    add(fmt::format("mc:n={} (exact lookup)", n), fastExact, specExact.defines());
    add(fmt::format("mc:n={} (lut, general)", n), generalLut, general.defines());
    add(fmt::format("mc:n={}", n), fast, spec.defines());
    add("mc:n=8", mc8, spec.defines());
    // Each family as `render` builds it: structural and scene defines, its
    // `lum` buffer, its lanes (methods::Family).
    for (const char* name : {"point", "structured", "cp", "np", "mrp", "voronoi", "voronoi:specialize=none"}) {
        if (opt.quick && std::string(name) != "point" && std::string(name) != "voronoi") continue;
        auto s = methods::parseSpec(name);
        const auto& fam = methods::family(s.name);
        std::string defs = fam.defines ? fam.defines(s) : std::string();
        if (fam.sceneDefines) defs += fam.sceneDefines(s, scene, table);
        int lanes = fam.lanes ? fam.lanes(s, scene, table, rt.info(), methods::Precision::Float) : 1;
        if (lanes > 1) defs += fmt::format(" -DLB_LANES={}", lanes);
        cl::Kernel k = rt.kernel(fam.file, fam.kernelName, defs);
        cl::Buffer P = b.reals(scene.params()), L = b.floats(fam.lumBuffer ? fam.lumBuffer(s, table) : exact);
        cl::Buffer out(rt.context(), CL_MEM_WRITE_ONLY, sizeof(float) * scene.res * scene.res);
        k.setArg(0, P);
        k.setArg(1, L);
        k.setArg(2, out);
        k.setArg(3, cl_int(0));
        methods::LaunchContext ctx{rt, s, scene, table, methods::Precision::Float, k, {}, {}, {}};
        ctx.lanes = lanes;
        if (fam.setArgs) fam.setArgs(ctx, 4);
        add(name, b.time(k, lanes), defs);
    }
    // The cubature as `render` builds it (methods/specialize.h
    // analyseCubature): specialised, then the general kernel with the same
    // LUT, then the exact lookup.
    auto cubDefines = [&](const methods::CubatureOptions& o) {
        return o.defines() + methods::analyseCubature(scene, table, o).defines();
    };
    methods::CubatureOptions co, coGeneral, coExact, co1;
    coGeneral.specialize = false;
    coExact.specialize = false;
    coExact.lut = false;
    co1.lanes = 1;
    const auto cubSpec = methods::analyseCubature(scene, table, co);
    const int lanes = methods::cubatureLanes(cubSpec, co, rt.info().type, false);
    double cub = b.cubature(cubDefines(co), lut.packed, lanes);
    double cubGeneral = b.cubature(cubDefines(coGeneral), lut.packed);
    double cubExact = b.cubature(cubDefines(coExact), exact);
    add("cubature (exact lookup, general)", cubExact, cubDefines(coExact));
    add("cubature (lut, general)", cubGeneral, cubDefines(coGeneral));
    if (cubSpec.rectFan && lanes > 1) add("cubature:lanes=1", b.cubature(cubDefines(co1), lut.packed), cubDefines(co1));
    add("cubature", cub, cubDefines(co) + (lanes > 1 ? fmt::format(" -DLB_LANES={}", lanes) : ""));
    doc["cubature_specialization"] = cubSpec.json();
    doc["cubature_lanes"] = lanes;
    if (!opt.quick) {
        methods::CubatureOptions cd;
        cd.triangulation = 1;
        add("cubature:triangulation=delaunay", b.cubature(cubDefines(cd), lut.packed), cubDefines(cd));
    }
    doc["methods"] = methods;

    // 4. Cubature against MC 8, and its equal-time sample count.
    // From the fit, then one secant correction on the measured t(N) (the fit
    // is only near linear, and the machine's load drifts).
    int neq = std::max(1, int(std::lround((cub - t0) / slope)));
    double verify = b.mc("mc.cl", spec.defines(), lut.packed, neq);
    int fitN = neq;
    if (verify > 0 && std::fabs(verify - cub) > 0.1 * cub) {
        neq = std::max(1, int(std::lround(neq * cub / verify)));
        verify = b.mc("mc.cl", spec.defines(), lut.packed, neq);
    }
    double cr = cub / mc8;
    doc["cubature"] = {{"time_ms", cub},   {"mc8_ms", mc8},        {"ratio", cr},        {"target", 1.0},
                       {"ok", cr <= 1.0},  {"equal_time_n", neq},  {"verify_ms", verify},
                       {"fit_n", fitN}};
    return doc;
}

std::string format(const nlohmann::json& d)
{
    std::ostringstream o;
    o << fmt::format("device: {} ({}), {}^2 pixels, local {}x{}, median of {} after 1 warm-up\n",
                     d["device"].get<std::string>(), d["driver"].get<std::string>(), d["res"].get<int>(),
                     d["local"][0].get<int>(), d["local"][1].get<int>(), d["reps"].get<int>());
    o << fmt::format("luminaire: {}  scene: {}\nspecialization: mc {}, cubature {}\n",
                     d["luminaire"].get<std::string>(), d["scene"].get<std::string>(), d["specialization"].dump(),
                     d["cubature_specialization"].dump());
    const auto& mc = d["mc"];
    o << fmt::format("MC n={}: naive {:.3g} samples/s, fast {:.3g} samples/s, ratio {:.1f} (target >= 10: {})\n",
                     mc["n"].get<int>(), mc["naive_sps"].get<double>(), mc["fast_sps"].get<double>(),
                     mc["ratio"].get<double>(), mc["ok"].get<bool>() ? "met" : "MISSED");
    o << fmt::format("{:<36} {:>10} {:>12}\n", "method", "ms", "ns/pixel");
    for (const auto& m : d["methods"])
        o << fmt::format("{:<36} {:>10.3f} {:>12.2f}\n", m["method"].get<std::string>(), m["time_ms"].get<double>(),
                         m["ns_per_pixel"].get<double>());
    const auto& f = d["mc_fit"];
    o << fmt::format("MC t(N) = {:.3f} ms + {:.4f} ms/sample\n", f["t0_ms"].get<double>(),
                     f["ms_per_sample"].get<double>());
    const auto& c = d["cubature"];
    o << fmt::format("cubature / MC 8 = {:.2f} (target <= 1: {}); equal-time MC N = {} (t = {:.3f} ms vs {:.3f} ms)\n",
                     c["ratio"].get<double>(), c["ok"].get<bool>() ? "met" : "MISSED", c["equal_time_n"].get<int>(),
                     c["verify_ms"].get<double>(), c["time_ms"].get<double>());
    return o.str();
}

} // namespace lb::bench
