#include "methods/render.h"

#include "util/error.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace lb::methods {

namespace fs = std::filesystem;

namespace {

struct Fnv {
    std::uint64_t h = 1469598103934665603ull;
    void bytes(const void* p, size_t n)
    {
        auto* b = static_cast<const unsigned char*>(p);
        for (size_t i = 0; i < n; ++i) {
            h ^= b[i];
            h *= 1099511628211ull;
        }
    }
    void str(const std::string& s) { bytes(s.data(), s.size() + 1); }
};

long countNonfinite(const Image& img)
{
    long n = 0;
    for (double v : img.px)
        if (!std::isfinite(v)) ++n;
    return n;
}

nlohmann::json timingJson(const ocl::Timing& t)
{
    return {{"median", t.median_ms}, {"min", t.min_ms}, {"max", t.max_ms}, {"reps", t.reps}, {"samples", t.samples_ms}};
}

// A cached result: <key>.exr, <key>.<extra>.exr, <key>.json.
bool loadCached(const std::string& base, RenderResult& r)
{
    std::ifstream in(base + ".json");
    if (!in || !fs::exists(base + ".exr")) return false;
    try {
        nlohmann::json j = nlohmann::json::parse(in);
        r.image = readExr(base + ".exr");
        for (auto& name : j.at("extra")) r.extraImages[name] = readExr(base + "." + name.get<std::string>() + ".exr");
        auto& t = j.at("time_ms");
        r.timing.median_ms = t.at("median");
        r.timing.min_ms = t.at("min");
        r.timing.max_ms = t.at("max");
        r.timing.reps = t.at("reps");
        r.buildSeconds = j.at("build_s");
        r.stats = j.at("stats");
    } catch (const std::exception& e) {
        std::cerr << "lumibench: ignoring unreadable cache entry " << base << ": " << e.what() << '\n';
        return false;
    }
    r.nonfinite = countNonfinite(r.image);
    r.cached = true;
    return true;
}

void storeCached(const std::string& base, const RenderResult& r)
{
    fs::create_directories(fs::path(base).parent_path());
    writeExr(base + ".exr", r.image);
    nlohmann::json extra = nlohmann::json::array();
    for (auto& [name, img] : r.extraImages) {
        writeExr(base + "." + name + ".exr", img);
        extra.push_back(name);
    }
    nlohmann::json j = {{"time_ms", timingJson(r.timing)}, {"build_s", r.buildSeconds}, {"stats", r.stats},
                        {"extra", extra}};
    std::ofstream(base + ".json") << j.dump(1) << '\n';
}

} // namespace

std::string cacheDir(const RenderOptions& opt)
{
    if (!opt.cacheDir.empty()) return opt.cacheDir;
    if (const char* e = std::getenv("LUMIBENCH_CACHE"); e && *e) return e;
    const char* home = std::getenv("HOME");
    return (fs::path(home ? home : ".") / ".cache" / "lumibench").string();
}

std::string cacheKey(const photometry::Table& table, const Scene& scene, const MethodSpec& spec, Precision p)
{
    Fnv f;
    f.str("lumibench-render-v1");
    auto P = scene.params();
    f.bytes(P.data(), P.size() * sizeof(double));
    auto lum = table.packed();
    f.bytes(lum.data(), lum.size() * sizeof(float));
    f.str(precisionName(p));
    f.str(spec.canonical());
    return fmt::format("{:016x}", f.h);
}

RenderResult render(ocl::Runtime& rt, const photometry::Table& table, const Scene& scene, const MethodSpec& spec,
                    Precision precision, const RenderOptions& opt)
{
    const Family& fam = family(spec.name);
    if (scene.res < 1 || scene.res > 16384) throw InputError(fmt::format("--res must be in [1, 16384], got {}", scene.res));
    scene.validate();
    table.validate();
    bool dbl = precision == Precision::Double;
    if (dbl && !rt.fp64())
        throw InputError(fmt::format("device '{}' has no double precision (cl_khr_fp64)", rt.info().name));

    RenderResult result;
    std::string base;
    if (fam.expensive && opt.useCache) {
        base = (fs::path(cacheDir(opt)) / (spec.name + "-" + cacheKey(table, scene, spec, precision))).string();
        if (loadCached(base, result)) {
            result.stats["cached"] = true;
            return result;
        }
    }

    std::string options = fam.defines ? fam.defines(spec) : std::string();
    if (fam.sceneDefines) options += fam.sceneDefines(spec, scene, table);
    if (dbl) options += " -DLB_DOUBLE";
    const int lanes = fam.lanes ? fam.lanes(spec, scene, table, rt.info(), precision) : 1;
    if (lanes > 1) options += fmt::format(" -DLB_LANES={}", lanes);
    double b0 = rt.buildSeconds();
    LaunchContext ctx{rt, spec, scene, table, precision, rt.kernel(fam.file, fam.kernelName, options), {}, {}, {}, {}};
    ctx.stats = nlohmann::json::object();  // {} above made it null
    ctx.lanes = lanes;
    result.buildSeconds = rt.buildSeconds() - b0;

    const int res = scene.res;
    const size_t npx = static_cast<size_t>(res) * res;
    cl::Buffer P = ctx.realBuffer(scene.params());
    auto lum = fam.lumBuffer ? fam.lumBuffer(spec, table) : table.packed();
    cl::Buffer L(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, lum.size() * sizeof(float), lum.data());
    ctx.buffers.push_back(L);
    cl::Buffer out = ctx.outputReals(npx);
    ctx.kernel.setArg(0, P);
    ctx.kernel.setArg(1, L);
    ctx.kernel.setArg(2, out);
    ctx.kernel.setArg(3, cl_int(0));
    if (fam.setArgs) fam.setArgs(ctx, 4);

    if (fam.expensive) {
        // One run (no warm-up: minutes at large sizes, and deterministic) in
        // bands of rows, progress between them; the time is the sum of the
        // bands' device times.
        int band = fam.bandRows > 0 ? fam.bandRows : res;
        double total = 0;
        for (int r0 = 0; r0 < res; r0 += band) {
            int rows = std::min(band, res - r0);
            ctx.kernel.setArg(3, cl_int(r0));
            total += ocl::Runtime::eventMs(rt.launch2D(ctx.kernel, (res + lanes - 1) / lanes, rows));
            if (opt.progress)
                std::cerr << fmt::format("\r{}: {:3d}% ({:.1f} s)", spec.name, 100 * (r0 + rows) / res, total / 1e3)
                          << std::flush;
        }
        if (opt.progress) std::cerr << '\n';
        result.timing = ocl::summarize({total});
    } else {
        const size_t cols = (res + lanes - 1) / lanes;
        result.timing = rt.time([&] { return rt.launch2D(ctx.kernel, cols, res); }, std::max(1, opt.reps), 1);
    }

    result.image = Image(res, res);
    result.image.px = ctx.readReals(out, npx);
    if (fam.finish) fam.finish(ctx);
    result.extraImages = std::move(ctx.extraImages);
    result.stats = std::move(ctx.stats);
    result.nonfinite = countNonfinite(result.image);
    if (fam.expensive) {
        result.stats["cached"] = false;
        if (opt.useCache) storeCached(base, result);
    }
    return result;
}

} // namespace lb::methods
