#include "bench/bench.h"

#include "equaltime/equaltime.h"
#include "experiments/results.h"
#include "methods/cubature_options.h"
#include "methods/mc_denoise.h"
#include "methods/registry.h"
#include "methods/render.h"
#include "methods/samples.h"
#include "methods/specialize.h"
#include "photometry/lut.h"
#include "util/error.h"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <memory>
#include <sstream>

namespace lb::bench {

namespace {

// Kernels timed over the whole image: every family through methods::Prepared
// (the renderer's own build and bind), and the naive MC kernel, which is no
// family, bound here.
struct Bench {
    ocl::Runtime& rt;
    const photometry::Table& table;
    const Scene& scene;
    const Options& opt;
    const equaltime::Protocol& protocol;

    struct Timed {
        double ms = 0;
        std::string defines;
        int lanes = 1;
    };

    Timed spec(const std::string& text)
    {
        methods::MethodSpec s = methods::parseSpec(text);
        methods::Prepared p(rt, table, scene, s, methods::Precision::Float);
        p.setLocal(opt.lx, opt.ly);
        return {p.time(opt.reps).median_ms, p.options(), p.lanes()};
    }
    double mc(int n) { return spec(fmt::format("mc:n={}", n)).ms; }

    // t(a) / t(b) as the median of per-round ratios, the two launched in
    // alternation (Runtime::timeInterleaved): a drift of the machine's speed
    // hits both sides of every ratio alike. The protocol's rounds.
    double ratio(const std::string& a, const std::string& b) { return paired(scene, a, scene, b).ratio; }

    struct Paired {
        double ratio;  // median of the rounds' ratios
        double msA, msB;  // the medians of each side
        int rounds;
    };
    // a on scene sa against b on scene sb, in alternating rounds.
    Paired paired(const Scene& sa, const std::string& a, const Scene& sb, const std::string& b)
    {
        methods::Prepared pa(rt, table, sa, methods::parseSpec(a, sa.kind), methods::Precision::Float);
        methods::Prepared pb(rt, table, sb, methods::parseSpec(b, sb.kind), methods::Precision::Float);
        pa.setLocal(opt.lx, opt.ly);
        pb.setLocal(opt.lx, opt.ly);
        const int rounds = protocol.rounds;
        auto t = rt.timeInterleaved({[&] { return pa.launchMs(); }, [&] { return pb.launchMs(); }}, rounds, 1);
        return {equaltime::medianRatio({t[1], t[0]}, 1), t[0].median_ms, t[1].median_ms, rounds};  // t(a) / t(b)
    }

    // naive.cl: render(P, lum, out, row0, st, n), the exact packed table.
    double naive(int n)
    {
        cl::Kernel k = rt.kernel("naive.cl", "render", "");
        auto floats = [&](const std::vector<float>& v) {
            return cl::Buffer(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, v.size() * sizeof(float),
                              const_cast<float*>(v.data()));
        };
        auto st = methods::samplePoints("poisson", n, 0);
        const std::vector<double> params = scene.params();
        cl::Buffer P = floats(std::vector<float>(params.begin(), params.end()));
        cl::Buffer L = floats(table.packed()), S = floats(std::vector<float>(st.begin(), st.end()));
        cl::Buffer out(rt.context(), CL_MEM_WRITE_ONLY, sizeof(float) * scene.res * scene.res);
        k.setArg(0, P);
        k.setArg(1, L);
        k.setArg(2, out);
        k.setArg(3, cl_int(0));
        k.setArg(4, S);
        k.setArg(5, cl_int(n));
        return rt.time([&] { return rt.launch2D(k, scene.res, scene.res, opt.lx, opt.ly); }, opt.reps, 1).median_ms;
    }
};

// The specs one run times: per family of the registry (the expensive
// reference aside) its default, its specialize=none form where it has one,
// and its Family::benchSpecs. --quick keeps the defaults. The diffuse scene's
// families only: the bench scene is the diffuse one.
std::vector<std::string> benchSpecs(bool quick)
{
    std::vector<std::string> v;
    for (const auto& f : methods::registry().all()) {
        if (f.expensive || !methods::renders(f, SceneKind::Diffuse)) continue;
        v.push_back(f.name);
        if (quick) continue;
        for (const auto& p : f.params)
            if (p.name == "specialize") v.push_back(f.name + ":specialize=none");
        v.insert(v.end(), f.benchSpecs.begin(), f.benchSpecs.end());
    }
    return v;
}

// The run's header: device, context, scene, the specialisation and the LUT.
nlohmann::json header(Bench& b)
{
    const auto lut = photometry::buildLut(b.table);
    nlohmann::json doc;
    doc["device"] = b.rt.info().name;
    doc["driver"] = b.rt.info().platform + " " + b.rt.info().driver;
    // commit, date, host, compiler (as the experiments' result files)
    doc["context"] = results::makeContext(b.rt.info().name, doc["driver"].get<std::string>(), nullptr);
    doc["res"] = b.scene.res;
    doc["reps"] = b.opt.reps;
    doc["local"] = {b.opt.lx, b.opt.ly};
    doc["luminaire"] = b.table.source.empty() ? b.table.format : b.table.source;
    doc["scene"] = b.scene.describe();
    doc["specialization"] = methods::analyse(b.scene, b.table, true, true).json();
    doc["lut"] = {{"ng", lut.ng}, {"na", lut.na}, {"error_bound_rel", lut.errorBound / b.table.maxCd()}};
    return doc;
}

// 1. Samples per second: naive against the fast kernel, same N, same run.
// The machine may be shared: naive and fast alternate in `rounds` rounds
// and each keeps its median, so a burst of load hits both alike.
nlohmann::json samplesPerSecond(Bench& b)
{
    const int n = b.opt.samples;
    const double px = double(b.scene.res) * b.scene.res;
    std::vector<double> naives, fasts;
    for (int r = 0; r < b.opt.rounds; ++r) {
        naives.push_back(b.naive(n));
        fasts.push_back(b.mc(n));
    }
    double naive = ocl::summarize(naives).median_ms, fast = ocl::summarize(fasts).median_ms;
    double fastExact = b.spec(fmt::format("mc:n={},lookup=exact", n)).ms;
    double generalLut = b.spec(fmt::format("mc:n={},specialize=none", n)).ms;
    auto sps = [&](double ms) { return px * n / (ms * 1e-3); };
    double ratio = naive / fast;
    return {{"n", n},
            {"rounds", b.opt.rounds},
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
}

// 2. The partner's time against N at the protocol's fit (docs/design.md
// section 6: not linear in N on every device; the search interpolates it).
struct McFit {
    double mc8 = 0;  // t(8) of mc:n=8, measured
    equaltime::Curve points;  // (N, ms) as measured
    nlohmann::json json;
};

McFit mcFit(Bench& b)
{
    nlohmann::json pts = nlohmann::json::array();
    McFit f;
    for (long k : b.protocol.fit) {
        double t = b.spec(equaltime::specAt(b.protocol.mc, k)).ms;
        if (k == 8 && b.protocol.mc == "mc") f.mc8 = t;
        pts.push_back({k, t});
        f.points.emplace_back(k, t);
    }
    if (f.mc8 == 0) f.mc8 = b.mc(8);
    f.json = {{"points", pts}};
    return f;
}

// 3. Every method's time per pixel, each as render() builds it; into doc's
// "methods", "cubature_specialization" and "cubature_lanes". Returns the
// cubature's time.
double methodTimes(Bench& b, double naiveMs, const McFit& fit, nlohmann::json& doc)
{
    const double px = double(b.scene.res) * b.scene.res;
    nlohmann::json methods = nlohmann::json::array();
    std::map<std::string, double> ms;
    auto add = [&](const std::string& name, double t, const std::string& defines) {
        ms[name] = t;
        methods.push_back({{"method", name}, {"time_ms", t}, {"ns_per_pixel", t * 1e6 / px}, {"defines", defines}});
    };
    add(fmt::format("naive mc:n={}", b.opt.samples), naiveMs, "");
    int cubLanes = 1;
    const std::string mcDefines = methods::analyse(b.scene, b.table, true, true).defines();
    for (const auto& s : benchSpecs(b.opt.quick)) {
        if (ms.count(s)) continue;
        Bench::Timed t = s == "mc:n=8" ? Bench::Timed{fit.mc8, mcDefines, 1} : b.spec(s);
        add(s, t.ms, t.defines + (t.lanes > 1 ? fmt::format(" -DLB_LANES={}", t.lanes) : ""));
        if (s == "cubature") cubLanes = t.lanes;
    }
    methods::CubatureOptions co;
    doc["cubature_specialization"] = methods::analyseCubature(b.scene, b.table, co).json();
    doc["cubature_lanes"] = cubLanes;
    doc["methods"] = methods;
    return ms.at("cubature");
}

// 4. Cubature against MC 8, and its equal-time sample count by the
// protocol's search (cubatureEqualTime).
nlohmann::json cubatureAgainstMc(Bench& b, double cub, const McFit& fit)
{
    return cubatureEqualTime(
        b.protocol, equaltime::preparedFrames(b.rt, b.table, b.scene, methods::Precision::Float, b.opt.lx, b.opt.ly),
        fit.points, cub, fit.mc8);
}

// 5. The fair-equal-time goals: every variant in its fastest form before
// its verdict. Each ratio from its own alternating rounds (Bench::ratio).
nlohmann::json goals(Bench& b)
{
    struct Goal {
        const char* name;
        const char* num;
        const char* den;
        double target;
    };
    nlohmann::json out = nlohmann::json::array();
    for (Goal g : {Goal{"delaunay cp+barycentre / fan", "cubature:triangulation=delaunay,dynamic=cp+barycentre",
                        "cubature", 1.5},
                   Goal{"delaunay cp+np+mrp+barycentre / fan",
                        "cubature:triangulation=delaunay,dynamic=cp+np+mrp+barycentre", "cubature", 2.5},
                   Goal{"np / cp", "np", "cp", 2.0}, Goal{"mrp / cp", "mrp", "cp", 2.0},
                   Goal{"cubature / mc 8", "cubature", "mc:n=8", 1.0}}) {
        double r = b.ratio(g.num, g.den);
        out.push_back({{"name", g.name},
                       {"numerator", g.num},
                       {"denominator", g.den},
                       {"ratio", r},
                       {"rounds", b.protocol.rounds},
                       {"target", g.target},
                       {"ok", r <= g.target}});
    }
    return out;
}

// 6. The indirect scene's RSM methods (docs/design.md section 9): each method's time and
// its stages (RSM, clustering, evaluation: Prepared::stageMs) at the
// bench's resolution, the same light in the room (at h = 1.1 where the
// bench's height does not fit it).
nlohmann::json indirectTimes(Bench& b)
{
    Scene ind = b.scene;
    ind.kind = SceneKind::Indirect;
    try {
        ind.validate();
    } catch (const InputError&) {
        ind.height = 1.1;
    }
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& f : methods::registry().all()) {
        if (f.expensive || f.name == "mc" || !methods::renders(f, SceneKind::Indirect)) continue;
        std::vector<std::string> specs{f.name};
        if (!b.opt.quick) specs.insert(specs.end(), f.benchSpecs.begin(), f.benchSpecs.end());
        for (const auto& text : specs) {
            methods::MethodSpec s = methods::parseSpec(text, SceneKind::Indirect);
            methods::Prepared p(b.rt, b.table, ind, s, methods::Precision::Float);
            p.setLocal(b.opt.lx, b.opt.ly);
            double t = p.time(b.opt.reps).median_ms;
            rows.push_back({{"method", text}, {"time_ms", t}, {"stage_ms", p.stageMs()}});
        }
    }
    return {{"scene", ind.describe()}, {"methods", rows}};
}

// 7. The specular extension (paper Table 1: Cubature + LTC 0.77 ms against
// Cubature 0.41 ms at 1080p on an RTX 2080 Ti, 1.9x): `ltc` on the
// specular scene of the same light over `cubature` on the diffuse scene,
// in alternating rounds as the goals above; once against the cubature as
// render() runs it (both in their straight-line forms where the scene
// allows: ltc's is kernels/common/ltc_lanes.inc over the same fan) and once
// against the cubature's general kernel.
nlohmann::json specularTimes(Bench& b)
{
    Scene sp = b.scene;
    sp.kind = SceneKind::Specular;
    nlohmann::json rows = nlohmann::json::array();
    for (const char* den : {"cubature", "cubature:specialize=none"}) {
        Bench::Paired t = b.paired(sp, "ltc", b.scene, den);
        rows.push_back({{"numerator", "ltc (specular scene)"},
                        {"denominator", std::string(den) + " (diffuse scene)"},
                        {"ratio", t.ratio},
                        {"ltc_ms", t.msA},
                        {"cubature_ms", t.msB},
                        {"rounds", t.rounds},
                        {"paper", 0.77 / 0.41}});
    }
    return rows;
}

// 8. Monte Carlo samplers' cost per sample against area sampling (today's
// mc): (t(64) - t(8)) / 56 per sampler, so that the per-pixel set-up (the
// spherical rectangle's angles, the projected polygon's arcs) stays out of
// it; the goals compare each domain with area sampling on the same shared
// points. Also each sampler's t(8) against mc:n=8 (set-up included).
// --quick: the two samplers with goals.
nlohmann::json mcSamplers(Bench& b)
{
    struct Row {
        const char* spec;
        double goal;  // 0: no goal
    };
    const int lo = 8, hi = 64;
    auto perSample = [&](const std::string& spec, double* t8) {
        double a = b.spec(fmt::format("mc:n={},{}", lo, spec)).ms;
        double c = b.spec(fmt::format("mc:n={},{}", hi, spec)).ms;
        *t8 = a;
        return (c - a) / (hi - lo);
    };
    double area8 = 0;
    const double area = perSample("domain=area", &area8);
    nlohmann::json rows = nlohmann::json::array();
    const std::vector<Row> quick = {Row{"domain=solid", 2}, Row{"domain=projected", 3}};
    const std::vector<Row> all = {Row{"domain=area,sequence=random", 0},
                                  Row{"domain=area,sequence=sobol", 0},
                                  Row{"domain=area,sequence=zsobol", 0},
                                  Row{"domain=solid", 2},
                                  Row{"domain=solid,cosine_warp=1", 0},
                                  Row{"domain=solid,sequence=sobol", 0},
                                  Row{"paper=1", 0},
                                  Row{"domain=projected", 3},
                                  Row{"domain=projected,sequence=sobol", 0},
                                  Row{"domain=mis,sequence=sobol", 0},
                                  Row{"domain=table,sequence=sobol", 0},
                                  Row{"domain=mis_table,sequence=sobol", 0},
                                  Row{"domain=mis_table_solid,sequence=sobol", 0}};
    for (const Row& r : b.opt.quick ? quick : all) {
        double t8 = 0;
        double c = perSample(r.spec, &t8);
        nlohmann::json row = {
            {"spec", r.spec}, {"ms_per_sample", c}, {"ratio", c / area}, {"t8_ms", t8}, {"t8_ratio", t8 / area8}};
        if (r.goal > 0) row["goal"] = r.goal, row["ok"] = c / area <= r.goal;
        rows.push_back(row);
    }
    return {{"area_ms_per_sample", area}, {"area_t8_ms", area8}, {"n", {lo, hi}}, {"samplers", rows}};
}

// The device's limits for the filters' rows: copy bandwidth (a 64 MiB
// buffer copied, read + write counted, median of 5) and a nominal peak of one
// float FMA per lane per cycle (compute units x clock x native float width x 2).
struct Limits {
    double gbps, gflops;
};
Limits deviceLimits(Bench& b)
{
    const size_t bytes = size_t(64) << 20;
    cl::Buffer a(b.rt.context(), CL_MEM_READ_WRITE, bytes), c(b.rt.context(), CL_MEM_READ_WRITE, bytes);
    auto t = b.rt.time(
        [&] {
            cl::Event e;
            b.rt.queue().enqueueCopyBuffer(a, c, 0, 0, bytes, nullptr, &e);
            return e;
        },
        5, 1);
    const cl::Device& d = b.rt.info().device;
    const double ghz = d.getInfo<CL_DEVICE_MAX_CLOCK_FREQUENCY>() * 1e-3;
    const double lanes = d.getInfo<CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT>();
    return {2.0 * bytes / (t.median_ms * 1e6), b.rt.info().computeUnits * ghz * std::max(1.0, lanes) * 2};
}

// 7. The filters (kernels/common/denoise.h) after one solid + sobol MC pass
// at N = 1: each pass's time per pixel (Prepared::stageMs, the medians of the
// same launches), the machine's limit for it (bytes over bandwidth, flops
// over the nominal peak; the larger), and the passes over the MC pass of the
// same launches (goals: the Gaussian <= 1, the a-trous filter <= 3); and the
// upsampling of MC below one sample per pixel (scale 0.5: the image rendered
// at half its side) over the full-size MC pass of the first row (goal <= 0.25).
nlohmann::json filterTimes(Bench& b)
{
    const Limits lim = deviceLimits(b);
    const double px = double(b.scene.res) * b.scene.res;
    const int radius = methods::gaussShape(0, 0, b.scene.res).radius;
    // per pixel: reals read + written, flops (a Gaussian tap folded: r + 1
    // products, 2 r sums; an a-trous tap ~ 14: the difference, its magnitude,
    // the scale, the cut, the exp2 from the bits (a product, a conversion, an
    // integer sum), the B3 weight and the three sums (5); the prefilter and
    // divisions 30; the 7 x 7 moments 3 per tap)
    auto cost = [&](const std::string& stage, double* reals, double* flops) {
        if (stage == "denoise_row" || stage == "denoise_col")
            *reals = 2, *flops = 3.0 * radius + 1;
        else if (stage == "denoise_var")
            *reals = 3, *flops = 49 * 3 + 5;
        else if (stage == "upsample")  // one written, a quarter read (the four taps' rows cached); two lerps, x
            *reals = 1.25, *flops = 12;
        else
            *reals = 4, *flops = 25 * 14 + 30;
    };
    const size_t realBytes = 4;  // float
    nlohmann::json out = {
        {"bandwidth_gbps", lim.gbps}, {"peak_gflops", lim.gflops}, {"filters", nlohmann::json::array()}};
    for (auto [key, goal] :
         {std::pair<const char*, double>{"denoise=gauss16", 1.0}, {"denoise=atrous", 3.0}, {"scale=0.5", 0.25}}) {
        const std::string spec = fmt::format("mc:n=1,domain=solid,sequence=sobol,{}", key);
        methods::Prepared p(b.rt, b.table, b.scene, methods::parseSpec(spec), methods::Precision::Float);
        p.setLocal(b.opt.lx, b.opt.ly);
        const auto t = p.time(b.protocol.rounds);
        const auto st = p.stageMs();
        nlohmann::json passes = nlohmann::json::array();
        double sum = 0;
        for (auto& [stage, ms] : st.items()) {
            if (stage == "eval") continue;
            double reals = 0, flops = 0;
            cost(stage, &reals, &flops);
            const double limNs = std::max(reals * realBytes / lim.gbps, flops / lim.gflops);
            sum += ms.get<double>();
            passes.push_back({{"stage", stage},
                              {"ms", ms},
                              {"ns_per_pixel", ms.get<double>() * 1e6 / px},
                              {"limit_ns_per_pixel", limNs},
                              {"bytes_per_pixel", reals * realBytes},
                              {"flops_per_pixel", flops}});
        }
        // the upsampling against the full-size pass: the first row's
        const bool scaled = std::string(key).rfind("scale=", 0) == 0;
        const double mc = scaled ? out["filters"][0]["mc_ms"].get<double>() : st["eval"].get<double>();
        out["filters"].push_back({{"spec", spec},
                                  {"total_ms", t.median_ms},
                                  {"mc_ms", mc},
                                  {"passes_ms", sum},
                                  {"ratio", sum / mc},
                                  {"goal", goal},
                                  {"ok", sum / mc <= goal},
                                  {"passes", passes}});
    }
    return out;
}

}  // namespace

equaltime::Protocol benchProtocol(bool quick, int reps)
{
    equaltime::Protocol p;
    p.reps = reps;
    p.rounds = std::max(reps, 11);
    p.fit = quick ? std::vector<long>{1, 8, 32} : std::vector<long>{1, 4, 8, 16, 32, 64, 128};
    return p;
}

nlohmann::json cubatureEqualTime(const equaltime::Protocol& p, const equaltime::Frames& frames,
                                 const equaltime::Curve& fit, double cubMs, double mc8Ms)
{
    const equaltime::Result q = equaltime::pairUp(
        p, frames, methods::parseSpec("cubature"),
        [&](long n, double extra) { return methods::parseSpec(equaltime::specAt(p.mc, n, extra)); }, fit, cubMs);
    const double cr = cubMs / mc8Ms;
    return {{"time_ms", cubMs},
            {"mc8_ms", mc8Ms},
            {"ratio", cr},
            {"target", 1.0},
            {"ok", cr <= 1.0},
            {"equal_time_n", q.n},
            {"equal_time_extra", q.extra},
            {"equal_time_scale", q.scale},
            {"verify_ms", q.partner.median_ms},
            {"paired_ms", q.method.median_ms},
            {"equal_time_ratio", q.ratio},
            {"equal_time_ok", q.ok},
            {"equal_time_bracketed", q.bracketed},
            {"equal_time_candidates", q.candidates}};
}

nlohmann::json run(ocl::Runtime& rt, const photometry::Table& table, const Scene& scene0, const Options& opt)
{
    Scene scene = scene0;
    scene.res = opt.res;
    equaltime::Protocol protocol = opt.protocol ? *opt.protocol : benchProtocol(opt.quick, opt.reps);
    protocol.reps = opt.reps;
    protocol.timeRes = opt.res;
    Bench b{rt, table, scene, opt, protocol};
    nlohmann::json doc = header(b);
    doc["protocol"] = protocol.json();
    if (opt.filtersOnly) {
        doc["filters"] = filterTimes(b);
        return doc;
    }
    doc["mc"] = samplesPerSecond(b);
    const McFit fit = mcFit(b);
    doc["mc_fit"] = fit.json;
    const double cub = methodTimes(b, doc["mc"]["naive_ms"].get<double>(), fit, doc);
    doc["cubature"] = cubatureAgainstMc(b, cub, fit);
    doc["goals"] = goals(b);
    doc["indirect"] = indirectTimes(b);
    doc["specular"] = specularTimes(b);
    doc["mc_samplers"] = mcSamplers(b);
    doc["filters"] = filterTimes(b);
    return doc;
}

// The filters' rows of run()'s document (none: nothing).
void formatFilters(std::ostream& o, const nlohmann::json& d)
{
    if (!d.contains("filters")) return;
    const auto& flt = d["filters"];
    o << fmt::format("Filters after one solid + sobol MC pass at N = 1 (limits: {:.1f} GB/s copy, {:.0f} GFLOP/s "
                     "nominal):\n",
                     flt["bandwidth_gbps"].get<double>(), flt["peak_gflops"].get<double>());
    for (const auto& r : flt["filters"]) {
        o << fmt::format("  {}: passes {:.3f} ms / MC {:.3f} ms = {:.2f}x (target <= {:g}: {})\n",
                         r["spec"].get<std::string>(), r["passes_ms"].get<double>(), r["mc_ms"].get<double>(),
                         r["ratio"].get<double>(), r["goal"].get<double>(), r["ok"].get<bool>() ? "met" : "MISSED");
        for (const auto& p : r["passes"])
            o << fmt::format("    {:<12} {:7.2f} ns/pixel (limit {:5.2f})\n", p["stage"].get<std::string>(),
                             p["ns_per_pixel"].get<double>(), p["limit_ns_per_pixel"].get<double>());
    }
}

std::string format(const nlohmann::json& d)
{
    std::ostringstream o;
    if (!d.contains("mc")) {  // --filters
        o << fmt::format("device: {} ({}), {}^2 pixels\n", d["device"].get<std::string>(),
                         d["driver"].get<std::string>(), d["res"].get<int>());
        formatFilters(o, d);
        return o.str();
    }
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
    o << fmt::format("{:<62} {:>10} {:>12}\n", "method", "ms", "ns/pixel");
    for (const auto& m : d["methods"])
        o << fmt::format("{:<62} {:>10.3f} {:>12.2f}\n", m["method"].get<std::string>(), m["time_ms"].get<double>(),
                         m["ns_per_pixel"].get<double>());
    std::string curve;
    for (const auto& p : d["mc_fit"]["points"])
        curve += fmt::format(" N={} {:.3f} ms", p[0].get<long>(), p[1].get<double>());
    o << "MC t(N):" << curve << "\n";
    const auto& c = d["cubature"];
    o << fmt::format("cubature / MC 8 = {:.2f} (target <= 1: {}); equal-time MC N = {:g} (paired: {:.3f} ms vs "
                     "cubature {:.3f} ms)\n",
                     c["ratio"].get<double>(), c["ok"].get<bool>() ? "met" : "MISSED",
                     c["equal_time_n"].get<double>() + c.value("equal_time_extra", 0.0), c["verify_ms"].get<double>(),
                     c.value("paired_ms", c["time_ms"].get<double>()));
    if (d.contains("goals"))
        for (const auto& g : d["goals"])
            o << fmt::format("{:<36} {:>6.2f} (target <= {:g}: {})\n", g["name"].get<std::string>(),
                             g["ratio"].get<double>(), g["target"].get<double>(),
                             g["ok"].get<bool>() ? "met" : "MISSED");
    if (d.contains("indirect")) {
        o << fmt::format("indirect scene ({}): ms total = rsm + cluster + eval\n",
                         d["indirect"]["scene"].get<std::string>());
        for (const auto& m : d["indirect"]["methods"]) {
            auto st = [&](const char* k) { return m["stage_ms"].value(k, 0.0); };
            o << fmt::format("  {:<28} {:9.3f} = {:8.3f} + {:8.3f} + {:8.3f}\n", m["method"].get<std::string>(),
                             m["time_ms"].get<double>(), st("rsm"), st("cluster"), st("eval"));
        }
    }
    if (d.contains("specular"))
        for (const auto& sp : d["specular"])
            o << fmt::format("Cubature + LTC / {} = {:.2f} ({:.3f} ms / {:.3f} ms; paper Table 1: {:.2f})\n",
                             sp["denominator"].get<std::string>(), sp["ratio"].get<double>(),
                             sp["ltc_ms"].get<double>(), sp["cubature_ms"].get<double>(), sp["paper"].get<double>());
    if (d.contains("mc_samplers")) {
        const auto& m = d["mc_samplers"];
        o << fmt::format("MC samplers, cost per sample against area sampling ({:.3g} ms/sample; t(8) {:.3f} ms):\n",
                         m["area_ms_per_sample"].get<double>(), m["area_t8_ms"].get<double>());
        for (const auto& r : m["samplers"]) {
            std::string goal = r.contains("goal")
                ? fmt::format(" (target <= {:g}: {})", r["goal"].get<double>(), r["ok"].get<bool>() ? "met" : "MISSED")
                : "";
            o << fmt::format("  {:<36} {:6.2f}x per sample, t(8) {:6.2f}x{}\n", r["spec"].get<std::string>(),
                             r["ratio"].get<double>(), r["t8_ratio"].get<double>(), goal);
        }
    }
    formatFilters(o, d);
    return o.str();
}

}  // namespace lb::bench
