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

Prepared::Prepared(ocl::Runtime& rt, const photometry::Table& table, const Scene& scene, const MethodSpec& spec,
                   Precision precision)
    : fam_(methods::family(spec.name)), spec_(spec), scene_(scene)
{
    if (scene_.res < 1 || scene_.res > 16384)
        throw InputError(fmt::format("--res must be in [1, 16384], got {}", scene_.res));
    scene_.validate();
    table.validate();
    const bool dbl = precision == Precision::Double;
    if (dbl && !rt.fp64())
        throw InputError(fmt::format("device '{}' has no double precision (cl_khr_fp64)", rt.info().name));
    options_ = fam_.defines ? fam_.defines(spec_) : std::string();
    if (fam_.sceneDefines) options_ += fam_.sceneDefines(spec_, scene_, table);
    if (dbl) options_ += " -DLB_DOUBLE";
    const int lanes = fam_.lanes ? fam_.lanes(spec_, scene_, table, rt.info(), precision) : 1;
    if (lanes > 1) options_ += fmt::format(" -DLB_LANES={}", lanes);
    double b0 = rt.buildSeconds();
    ctx_.reset(new LaunchContext{fam_, rt, spec_, scene_, table, precision,
                                 rt.kernel(fam_.file, fam_.kernelName, options_), {}, {}, {}, {}});
    ctx_->stats = nlohmann::json::object();  // {} above made it null
    ctx_->lanes = lanes;
    buildSeconds_ = rt.buildSeconds() - b0;

    const size_t npx = static_cast<size_t>(scene_.res) * scene_.res;
    cl::Buffer P = ctx_->realBuffer(scene_.params());
    auto lum = fam_.lumBuffer ? fam_.lumBuffer(spec_, table) : table.packed();
    cl::Buffer L(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, lum.size() * sizeof(float), lum.data());
    ctx_->buffers.push_back(L);
    out_ = ctx_->outputReals(npx);
    ctx_->kernel.setArg(0, P);
    ctx_->kernel.setArg(1, L);
    ctx_->kernel.setArg(2, out_);
    ctx_->kernel.setArg(3, cl_int(0));
    if (fam_.setArgs) fam_.setArgs(*ctx_);
    statsSwitch(false);
}

void Prepared::statsSwitch(bool on)
{
    if (!fam_.statsSwitch.empty()) ctx_->arg(fam_.statsSwitch, cl_int(on ? 1 : 0));
}

cl::Event Prepared::launch(int row0, int rows)
{
    ctx_->kernel.setArg(3, cl_int(row0));
    const size_t cols = (scene_.res + ctx_->lanes - 1) / ctx_->lanes;
    return ctx_->rt.launch2D(ctx_->kernel, cols, rows, lx_, ly_);
}

ocl::Timing Prepared::time(int reps)
{
    statsSwitch(false);
    return ctx_->rt.time([&] { return launch(0, scene_.res); }, std::max(1, reps), 1);
}

void Prepared::collect()
{
    if (!fam_.statsSwitch.empty()) {
        statsSwitch(true);
        launch(0, scene_.res).wait();
        statsSwitch(false);
    }
    if (fam_.finish) fam_.finish(*ctx_);
}

Image Prepared::image()
{
    Image img(scene_.res, scene_.res);
    img.px = ctx_->readReals(out_, static_cast<size_t>(scene_.res) * scene_.res);
    return img;
}

RenderResult render(ocl::Runtime& rt, const photometry::Table& table, const Scene& scene, const MethodSpec& spec,
                    Precision precision, const RenderOptions& opt)
{
    const Family& fam = family(spec.name);
    RenderResult result;
    std::string base;
    if (fam.expensive && opt.useCache) {
        scene.validate();
        base = (fs::path(cacheDir(opt)) / (spec.name + "-" + cacheKey(table, scene, spec, precision))).string();
        if (loadCached(base, result)) {
            result.stats["cached"] = true;
            return result;
        }
    }

    Prepared prep(rt, table, scene, spec, precision);
    result.buildSeconds = prep.buildSeconds();
    const int res = scene.res;
    std::string timeDefines;  // the timed kernel's options where they differ from the image's
    if (fam.expensive) {
        // One run (no warm-up: minutes at large sizes, and deterministic) in
        // bands of rows, progress between them; the time is the sum of the
        // bands' device times.
        int band = fam.bandRows > 0 ? fam.bandRows : res;
        double total = 0;
        for (int r0 = 0; r0 < res; r0 += band) {
            int rows = std::min(band, res - r0);
            total += ocl::Runtime::eventMs(prep.launch(r0, rows));
            if (opt.progress)
                std::cerr << fmt::format("\r{}: {:3d}% ({:.1f} s)", spec.name, 100 * (r0 + rows) / res, total / 1e3)
                          << std::flush;
        }
        if (opt.progress) std::cerr << '\n';
        result.timing = ocl::summarize({total});
        result.timeRes = res;
    } else if (opt.timeRes > 0 && opt.timeRes != res) {
        // Timed at its own resolution (DESIGN 6), so that a small error image
        // still gets an honest time; the image is one untimed launch.
        Scene ts = scene;
        ts.res = opt.timeRes;
        Prepared timed(rt, table, ts, spec, precision);
        result.buildSeconds += timed.buildSeconds();
        result.timing = timed.time(opt.reps);
        result.timeRes = opt.timeRes;
        if (timed.options() != prep.options()) timeDefines = timed.options();
        prep.launch(0, res).wait();
    } else {
        result.timing = prep.time(opt.reps);
        result.timeRes = res;
    }
    result.image = prep.image();
    prep.collect();
    result.extraImages = prep.extraImages();
    result.stats = prep.stats();
    if (!timeDefines.empty()) result.stats["time_defines"] = timeDefines;
    result.nonfinite = countNonfinite(result.image);
    if (fam.expensive) {
        result.stats["cached"] = false;
        if (opt.useCache) storeCached(base, result);
    }
    return result;
}

} // namespace lb::methods
