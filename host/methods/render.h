// render.h -- one method on the normalized scene: the library entry point the
// CLI (`lumibench render`), the experiment runner and the tests share.
#pragma once

#include "cl/runtime.h"
#include "methods/registry.h"

#include <nlohmann/json.hpp>

#include <map>
#include <string>

namespace lb::methods {

struct RenderOptions {
    int reps = 5;           // timed runs after one warm-up (expensive methods: one run)
    bool useCache = true;   // expensive methods: reuse / store results on disk
    bool progress = false;  // expensive methods: progress on stderr
    std::string cacheDir;   // "" = $LUMIBENCH_CACHE, else ~/.cache/lumibench
};

struct RenderResult {
    Image image;                               // E in lux, row 0 at the top
    std::map<std::string, Image> extraImages;  // reference: "err", the per-pixel error estimate
    ocl::Timing timing;                        // device time of the kernel (profiling events)
    double buildSeconds = 0;                   // program build, excluded from timing
    long nonfinite = 0;                        // pixels that are NaN or infinite
    nlohmann::json stats = nlohmann::json::object();  // per-method counters
    bool cached = false;                       // taken from the cache (timing is the stored one)
};

RenderResult render(ocl::Runtime& rt, const photometry::Table& table, const Scene& scene, const MethodSpec& spec,
                    Precision precision, const RenderOptions& opt = {});

// The cache directory in use and the key of one render (hex of a 64-bit FNV-1a
// over scene parameters, packed table, precision and canonical SPEC).
std::string cacheDir(const RenderOptions& opt);
std::string cacheKey(const photometry::Table& table, const Scene& scene, const MethodSpec& spec, Precision p);

} // namespace lb::methods
