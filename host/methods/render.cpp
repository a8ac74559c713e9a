#include "methods/render.h"

#include "photometry/load.h"
#include "util/check.h"
#include "util/digest.h"
#include "util/error.h"
#include "util/fileio.h"
#include "util/json_file.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace lb::methods {

namespace fs = std::filesystem;

namespace {

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

// A cached result: <key>.exr, <key>.<extra>.exr and <key>.json, which records
// the key and, per image, its file name, size and content digest. An entry is
// served only when every image has the recorded digest and the scene's size;
// anything else (a damaged, foreign or resized image, an entry of an older
// version without digests) is reported, naming the cache, and rendered again.
bool loadCached(const std::string& base, const std::string& key, int res, RenderResult& r)
{
    const std::string meta = base + ".json";
    if (!fs::exists(meta)) return false;
    try {
        nlohmann::json j = util::readJson(meta, "a reference cache entry", 1u << 20);
        if (j.value("key", std::string()) != key || !j.contains("images"))
            throw Error("written by another version (no key and image digests)");
        auto readChecked = [&](const std::string& name) {
            const auto& d = j.at("images").at(name);
            const std::string file = (fs::path(base).parent_path() / d.at("file").get<std::string>()).string();
            const std::string bytes = util::readFile(file, "a cached OpenEXR image", size_t(1) << 34);
            const std::string got = util::digestHex(bytes);
            if (got != d.at("digest").get<std::string>())
                throw Error(fmt::format("{}: content digest {} differs from the recorded {}", file, got,
                                        d.at("digest").get<std::string>()));
            Image img = readExr(file);
            if (img.width != res || img.height != res || d.at("width") != res || d.at("height") != res)
                throw Error(fmt::format("{}: {} x {} pixels, expected {} x {}", file, img.width, img.height, res, res));
            return img;
        };
        r.image = readChecked("main");
        for (auto& name : j.at("extra")) r.extraImages[name] = readChecked(name.get<std::string>());
        auto& t = j.at("time_ms");
        r.timing.median_ms = t.at("median");
        r.timing.min_ms = t.at("min");
        r.timing.max_ms = t.at("max");
        r.timing.reps = t.at("reps");
        r.buildSeconds = j.at("build_s");
        r.stats = j.at("stats");
    } catch (const std::exception& e) {
        std::cerr << fmt::format("lumibench: warning: reference cache {}: ignoring entry {}: {}; rendering again\n",
                                 fs::path(base).parent_path().string(), fs::path(base).filename().string(), e.what());
        // drop what was read (swap: GCC 12 warns, wrongly, on assigning a temporary here)
        RenderResult empty;
        std::swap(r, empty);
        return false;
    }
    r.nonfinite = countNonfinite(r.image);
    r.cached = true;
    return true;
}

// Writes the entry as one group (util::writeFilesAtomic): a failure leaves
// none of its files. A cache that cannot be written is a warning naming it:
// the render itself succeeded.
void storeCached(const std::string& base, const std::string& key, const RenderResult& r)
{
    const std::string stem = fs::path(base).filename().string();
    std::vector<std::pair<std::string, std::string>> files;
    nlohmann::json images = nlohmann::json::object(), extra = nlohmann::json::array();
    auto add = [&](const std::string& name, const std::string& suffix, const Image& img) {
        std::string bytes = encodeExr(img);
        images[name] = {
            {"file", stem + suffix}, {"width", img.width}, {"height", img.height}, {"digest", util::digestHex(bytes)}};
        files.emplace_back(base + suffix, std::move(bytes));
    };
    add("main", ".exr", r.image);
    for (auto& [name, img] : r.extraImages) {
        add(name, "." + name + ".exr", img);
        extra.push_back(name);
    }
    nlohmann::json j = {{"key", key},
                        {"time_ms", timingJson(r.timing)},
                        {"build_s", r.buildSeconds},
                        {"stats", r.stats},
                        {"extra", extra},
                        {"images", images}};
    // The description last: an entry without it is not served.
    files.emplace_back(base + ".json", j.dump(1) + '\n');
    try {
        std::error_code ec;
        fs::create_directories(fs::path(base).parent_path(), ec);
        if (ec) throw Error(fmt::format("cannot create the directory: {}", ec.message()));
        util::removeStaleTemporaries(fs::path(base).parent_path().string());
        util::writeFilesAtomic(files);
    } catch (const std::exception& e) {
        std::cerr << fmt::format("lumibench: warning: reference cache {}: cannot store {}: {}\n",
                                 fs::path(base).parent_path().string(), stem, e.what());
    }
}

}  // namespace

std::string cacheDir(const RenderOptions& opt)
{
    if (!opt.cacheDir.empty()) return opt.cacheDir;
    if (const char* e = std::getenv("LUMIBENCH_CACHE"); e && *e) return e;
    const char* home = std::getenv("HOME");
    return (fs::path(home ? home : ".") / ".cache" / "lumibench").string();
}

std::string cacheKey(const photometry::Table& table, const Scene& scene, const MethodSpec& spec, Precision p)
{
    util::Digest f;
    f.str("lumibench-render-v2");
    auto P = scene.params();
    f.bytes(P.data(), P.size() * sizeof(double));
    auto lum = photometry::tiltedFor(table, scene.rotation).packed();
    f.bytes(lum.data(), lum.size() * sizeof(float));
    f.str(precisionName(p));
    f.str(resolvePreset(spec, table.source).canonical());  // a preset: the entry it resolves to
    f.str(ocl::kernelSourceDigest(spec.family().file));  // the kernel and every header it includes
    return f.hex();
}

Prepared::Prepared(ocl::Runtime& rt, const photometry::Table& table, const Scene& scene, const MethodSpec& spec,
                   Precision precision)
    : fam_(spec.family()), spec_(resolvePreset(spec, table.source)), scene_(scene),
      table_(photometry::tiltedFor(table, scene.rotation))
{
    if (spec.kind != scene.kind)
        throw InputError(fmt::format("method {} was given for the {} scene, not the {} scene it renders here",
                                     spec.name, sceneKindName(spec.kind), sceneKindName(scene.kind)));
    util::checkRange("the scene's res (pixels per side)", scene_.res, 1, kMaxRes);
    scene_.validate();
    checkShape(fam_, scene_);
    table_.validate();
    const bool dbl = precision == Precision::Double;
    if (dbl && !rt.fp64())
        throw InputError(fmt::format("device '{}' has no double precision (cl_khr_fp64)", rt.info().name));
    Plan plan = spec_.plan(scene_, table_, rt.info(), precision);
    options_ = plan.defines;
    if (dbl) options_ += " -DLB_DOUBLE";
    const int lanes = plan.lanes;
    if (lanes > 1) options_ += fmt::format(" -DLB_LANES={}", lanes);
    renderScene_ = scene_;
    if (plan.renderRes > 0) {
        util::checkRange("the plan's render resolution (pixels per side)", plan.renderRes, 1, scene_.res);
        if (!plan.postPasses) throw Error("Prepared: a plan that renders at another resolution needs post-passes");
        renderScene_.res = plan.renderRes;
    }
    double b0 = rt.buildSeconds();
    ctx_.reset(new LaunchContext{fam_,
                                 rt,
                                 spec_,
                                 renderScene_,
                                 table_,
                                 precision,
                                 rt.kernel(fam_.file, fam_.kernelName, options_),
                                 {},
                                 {},
                                 {},
                                 {}});
    ctx_->imageRes = scene_.res;
    ctx_->stats = nlohmann::json::object();  // {} above made it null
    ctx_->lanes = lanes;
    ctx_->options = options_;
    buildSeconds_ = rt.buildSeconds() - b0;

    const size_t npx = static_cast<size_t>(renderScene_.res) * renderScene_.res;
    cl::Buffer P = ctx_->realBuffer(renderScene_.params());
    P_ = P;
    std::vector<float> lum = plan.lum ? plan.lum() : table_.packed();
    cl::Buffer L(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, lum.size() * sizeof(float), lum.data());
    ctx_->buffers.push_back(L);
    ctx_->named["P"] = P;  // for the pre-passes' kernels
    ctx_->named["lum"] = L;
    cl::Buffer rendered = ctx_->outputReals(npx);
    ctx_->named["out"] = rendered;  // for the post-passes
    out_ = rendered;
    if (renderScene_.res != scene_.res) {
        out_ = ctx_->outputReals(static_cast<size_t>(scene_.res) * scene_.res);
        ctx_->named["image"] = out_;  // the post-passes' result
    }
    ctx_->kernel.setArg(0, P);
    ctx_->kernel.setArg(1, L);
    ctx_->kernel.setArg(2, rendered);
    ctx_->kernel.setArg(3, cl_int(0));
    bindPlan(*ctx_, plan);
    plan_ = std::move(plan);
    statsSwitch(false);
}

Prepared::~Prepared()
{
    try {
        if (ctx_) ctx_->rt.queue().finish();
    } catch (...) {  // a failed device: nothing left to wait for
    }
}

void Prepared::statsSwitch(bool on)
{
    if (!plan_.statsSwitch.empty()) ctx_->arg(plan_.statsSwitch, cl_int(on ? 1 : 0));
}

cl::Event Prepared::launch(int row0, int rows)
{
    if (plan_.prePasses && row0 == 0) {
        auto ev = plan_.prePasses(*ctx_);
        passEvents_.insert(passEvents_.end(), ev.begin(), ev.end());
    }
    if (renderScene_.res != scene_.res) {
        if (row0 != 0 || rows != scene_.res)
            throw Error(fmt::format("Prepared::launch: {} renders at {} pixels per side and launches whole frames, "
                                    "not rows {} .. {}",
                                    spec_.name, renderScene_.res, row0, row0 + rows));
        rows = renderScene_.res;
    }
    ctx_->kernel.setArg(3, cl_int(row0));
    const size_t cols = (renderScene_.res + ctx_->lanes - 1) / ctx_->lanes;
    cl::Event ev = ctx_->rt.launch2D(ctx_->kernel, cols, rows, lx_, ly_);
    if (plan_.postPasses && row0 + rows >= renderScene_.res) {
        auto post = plan_.postPasses(*ctx_);
        passEvents_.insert(passEvents_.end(), post.begin(), post.end());
    }
    return ev;
}

double Prepared::launchMs()
{
    const double ms = ocl::Runtime::eventMs(launch(0, scene_.res));
    return ms + takePassMs();
}

ocl::Timing Prepared::time(int reps)
{
    statsSwitch(false);
    if (!plan_.prePasses && !plan_.postPasses)
        return ctx_->rt.time([&] { return launch(0, scene_.res); }, std::max(1, reps), 1);
    // Multi-pass: every launch's time is its pre- and post-passes' events
    // plus the render kernel's; one warm-up as for the others. A family whose
    // passes this spec does not run (mc without a filter) is timed as a
    // one-kernel method.
    launch(0, scene_.res).wait();
    if (passEvents_.empty()) return ctx_->rt.time([&] { return launch(0, scene_.res); }, std::max(1, reps), 0);
    takePassMs();
    std::vector<double> total;
    std::map<std::string, std::vector<double>> stages;
    for (int i = 0; i < std::max(1, reps); ++i) {
        const double eval = ocl::Runtime::eventMs(launch(0, scene_.res));
        std::map<std::string, double> per;
        for (auto& s : passEvents_) per[s.stage] += ocl::Runtime::eventMs(s.event);
        passEvents_.clear();
        per["eval"] += eval;
        double sum = 0;
        for (auto& [name, ms] : per) {
            stages[name].push_back(ms);
            sum += ms;
        }
        total.push_back(sum);
    }
    stageMs_ = nlohmann::json::object();
    for (auto& [name, v] : stages) stageMs_[name] = ocl::summarize(v).median_ms;
    return ocl::summarize(total);
}

double Prepared::takePassMs()
{
    double ms = 0;
    for (auto& s : passEvents_) ms += ocl::Runtime::eventMs(s.event);
    passEvents_.clear();
    return ms;
}

void Prepared::setScene(const Scene& scene)
{
    if (scene.res != scene_.res) throw Error("Prepared::setScene: the resolution must stay");
    scene.validate();
    scene_ = scene;
    const int rr = renderScene_.res;
    renderScene_ = scene;
    renderScene_.res = rr;
    auto P = renderScene_.params();
    if (ctx_->dbl()) {
        ctx_->rt.queue().enqueueWriteBuffer(P_, CL_TRUE, 0, P.size() * sizeof(double), P.data());
    } else {
        std::vector<float> f(P.begin(), P.end());
        ctx_->rt.queue().enqueueWriteBuffer(P_, CL_TRUE, 0, f.size() * sizeof(float), f.data());
    }
}

void Prepared::collect()
{
    if (!plan_.statsSwitch.empty()) {
        statsSwitch(true);
        launch(0, scene_.res).wait();
        statsSwitch(false);
    }
    if (plan_.finish) plan_.finish(*ctx_);
}

Image Prepared::image()
{
    Image img(scene_.res, scene_.res);
    img.px = ctx_->readReals(out_, static_cast<size_t>(scene_.res) * scene_.res);
    return img;
}

namespace {

// An expensive method's one run (no warm-up: minutes at large sizes, and
// deterministic) in bands of `bandRows` rows (0: all), progress between them;
// returns the sum of the bands' device times (ms).
double runInBands(Prepared& prep, int bandRows, const std::string& name, int res, bool progress)
{
    int band = bandRows > 0 ? bandRows : res;
    double total = 0;
    for (int r0 = 0; r0 < res; r0 += band) {
        int rows = std::min(band, res - r0);
        total += ocl::Runtime::eventMs(prep.launch(r0, rows)) + prep.takePassMs();
        if (progress)
            std::cerr << fmt::format("\r{}: {:3d}% ({:.1f} s)", name, 100 * (r0 + rows) / res, total / 1e3)
                      << std::flush;
    }
    if (progress) std::cerr << '\n';
    return total;
}

}  // namespace

RenderResult render(ocl::Runtime& rt, const photometry::Table& table, const Scene& scene, const MethodSpec& spec,
                    Precision precision, const RenderOptions& opt)
{
    const Family& fam = spec.family();
    RenderResult result;
    std::string base, key;
    if (fam.expensive && opt.useCache) {
        scene.validate();
        key = cacheKey(table, scene, spec, precision);
        base = (fs::path(cacheDir(opt)) / (spec.name + "-" + key)).string();
        if (loadCached(base, key, scene.res, result)) {
            result.stats["cached"] = true;
            return result;
        }
    }

    Prepared prep(rt, table, scene, spec, precision);
    result.buildSeconds = prep.buildSeconds();
    const int res = scene.res;
    std::string timeDefines;  // the timed kernel's options where they differ from the image's
    nlohmann::json stageMs;  // multi-pass methods: the timed launches' stages
    if (fam.expensive) {
        result.timing = ocl::summarize({runInBands(prep, fam.bandRows, spec.name, res, opt.progress)});
        result.timeRes = res;
    } else if (opt.timeRes > 0 && opt.timeRes != res) {
        // Timed at its own resolution (docs/design.md section 6), so that a small error image
        // still gets an honest time; the image is one untimed launch.
        Scene ts = scene;
        ts.res = opt.timeRes;
        Prepared timed(rt, table, ts, spec, precision);
        result.buildSeconds += timed.buildSeconds();
        result.timing = timed.time(opt.reps);
        result.timeRes = opt.timeRes;
        if (timed.options() != prep.options()) timeDefines = timed.options();
        if (!timed.stageMs().empty()) stageMs = timed.stageMs();
        prep.launch(0, res).wait();
    } else {
        result.timing = prep.time(opt.reps);
        result.timeRes = res;
        stageMs = prep.stageMs();
    }
    if (const int n = fam.settleFrames(spec); n > 0) {
        // a stateful method's image: its steady state on this static scene
        prep.takePassMs();
        prep.reset();
        for (int i = 0; i < n; ++i) prep.launch(0, res).wait();
    }
    prep.takePassMs();
    result.image = prep.image();
    prep.collect();
    result.extraImages = prep.extraImages();
    result.stats = prep.stats();
    if (stageMs.is_object() && !stageMs.empty()) result.stats["stage_ms"] = stageMs;
    // which kernel variant ran (structural and scene defines): the records
    // say whether a straight-line form or the general kernel was timed
    result.stats["defines"] = prep.options();
    // a per-luminaire preset: the spec it resolved to for this luminaire
    if (spec.has("preset") && spec.str("preset") != "none") result.stats["preset_spec"] = prep.spec().canonical();
    // the form of the timed kernel: an equal-time verdict is fair where it is the fast one
    std::string form = kernelForm(fam, timeDefines.empty() ? prep.options() : timeDefines);
    if (!form.empty()) result.stats["form"] = form;
    if (!timeDefines.empty()) result.stats["time_defines"] = timeDefines;
    result.nonfinite = countNonfinite(result.image);
    if (fam.expensive) {
        result.stats["cached"] = false;
        if (opt.useCache) storeCached(base, key, result);
    }
    return result;
}

}  // namespace lb::methods
