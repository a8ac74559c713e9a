// render.h -- one method on the normalized scene: the library entry point the
// CLI (`lumibench render`), the experiment runner and the tests share.
#pragma once

#include "cl/runtime.h"
#include "methods/registry.h"
#include "methods/spec.h"

#include <nlohmann/json.hpp>

#include <map>
#include <memory>
#include <string>

namespace lb::methods {

// One method built and bound for one scene: the program with its structural,
// scene and lane defines, the buffers and every argument set by name. The one
// path from a SPEC to launches: render(), the experiment runner, tune,
// stability and bench all go through it, so what is timed is what renders.
class Prepared {
public:
    // spec: a method resolved by parseSpec (its family is spec.family()).
    Prepared(ocl::Runtime& rt, const photometry::Table& table, const Scene& scene, const MethodSpec& spec,
             Precision precision);
    // Waits for what it enqueued (post-passes a caller did not wait for).
    ~Prepared();
    Prepared(const Prepared&) = delete;
    Prepared& operator=(const Prepared&) = delete;

    const Family& family() const { return fam_; }
    const std::string& options() const { return options_; }  // the program's -D options
    const MethodSpec& spec() const { return spec_; }  // as rendered: a preset resolved for the luminaire
    int lanes() const { return ctx_->lanes; }
    double buildSeconds() const { return buildSeconds_; }
    const Scene& scene() const { return scene_; }

    // Rows row0 .. row0 + rows of the image (statistics as last switched),
    // work-groups of lx x ly (setLocal; default 8 x 8). A plan that renders
    // at another resolution (Plan::renderRes) launches whole frames only
    // (row0 0, rows the scene's res).
    cl::Event launch(int row0, int rows);
    // One launch of the whole image and its device time in ms: the render
    // kernel plus, for multi-pass methods, the pre-passes it ran (RSM,
    // clustering). What a frame costs; the paired equal-time rounds use it.
    double launchMs();
    void setLocal(size_t lx, size_t ly) { lx_ = lx, ly_ = ly; }
    // One warm-up, then `reps` launches of the whole image with statistics
    // off: exactly the kernel a renderer runs (profiling-event times).
    ocl::Timing time(int reps);
    // One untimed launch with the family's statistics switched on (when it
    // has any), then the plan's finish: the stats and extra images.
    void collect();
    Image image();  // the output buffer as it stands

    // Multi-pass methods: the summed device time (ms) of the pre-passes of
    // the last launch with any (0 when none ran since the last call), and the
    // per-stage medians of the last time() ({"rsm": ms, ..., "eval": ms}).
    double takePassMs();
    nlohmann::json stageMs() const { return stageMs_; }
    // Stateful methods: back to the first frame (LaunchContext::frame = 0).
    void reset() { ctx_->frame = 0; }
    // Animated sequences: the next frame's scene (same kind and resolution);
    // the method's buffers and state stay.
    void setScene(const Scene& scene);

    nlohmann::json stats() { return std::move(ctx_->stats); }
    std::map<std::string, Image> extraImages() { return std::move(ctx_->extraImages); }

private:
    void statsSwitch(bool on);
    const Family& fam_;
    MethodSpec spec_;
    Scene scene_;
    Scene renderScene_;  // scene_ at the plan's renderRes (the kernels' P)
    photometry::Table table_;  // the scene's: a TILT=INCLUDE factor applied (photometry::tiltedFor)
    std::string options_;
    double buildSeconds_ = 0;
    size_t lx_ = 8, ly_ = 8;
    cl::Buffer out_, P_;  // out_: the image at the scene's res (named["image"] where rendered at another)
    std::vector<StageEvent> passEvents_;
    Plan plan_;  // its passes, statistics switch and finish
    nlohmann::json stageMs_ = nlohmann::json::object();
    std::unique_ptr<LaunchContext> ctx_;
};

struct RenderOptions {
    int reps = 5;  // timed runs after one warm-up (expensive methods: one run)
    int timeRes = 0;  // time at res x res pixels (docs/design.md section 6); 0 = the image's own res
    bool useCache = true;  // expensive methods: reuse / store results on disk
    bool progress = false;  // expensive methods: progress on stderr
    std::string cacheDir;  // "" = $LUMIBENCH_CACHE, else ~/.cache/lumibench
};

struct RenderResult {
    Image image;  // E in lux, row 0 at the top
    std::map<std::string, Image> extraImages;  // reference: "err", the per-pixel error estimate
    ocl::Timing timing;  // device time of the kernel(s) (profiling events)
    int timeRes = 0;  // the pixels per side the timing was taken at
    double buildSeconds = 0;  // program build, excluded from timing
    long nonfinite = 0;  // pixels that are NaN or infinite
    nlohmann::json stats = nlohmann::json::object();  // per-method counters
    bool cached = false;  // taken from the cache (timing is the stored one)
};

RenderResult render(ocl::Runtime& rt, const photometry::Table& table, const Scene& scene, const MethodSpec& spec,
                    Precision precision, const RenderOptions& opt = {});

// The cache directory in use and the key of one render (util::Digest over
// scene parameters, packed table, precision, canonical SPEC and the digest of
// the family's kernel source with every header it includes).
std::string cacheDir(const RenderOptions& opt);
std::string cacheKey(const photometry::Table& table, const Scene& scene, const MethodSpec& spec, Precision p);

}  // namespace lb::methods
