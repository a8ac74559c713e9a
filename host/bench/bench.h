// bench.h -- `lumibench bench`: MC samples per second against a
// deliberately naive kernel (kernels/naive.cl), time per pixel of every
// method, cubature against MC with 8 samples, and cubature's equal-time MC
// sample count, all in one run on one device. Timing: OpenCL profiling events,
// one warm-up and the median of `reps` launches (ocl::Runtime::time).
#pragma once

#include "cl/runtime.h"
#include "equaltime/protocol.h"
#include "photometry/table.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace lb::bench {

// The bench's protocol for `reps`: rounds max(reps, 11), the curve at N = 1,
// 4, 8, 16, 32, 64, 128 (quick: 1, 8, 32).
equaltime::Protocol benchProtocol(bool quick, int reps);

struct Options {
    int res = 512;
    int reps = 5;
    // The equal-time protocol of the cubature's MC partner and of the paired
    // ratios (rounds); its fit the MC sample counts of the t(N) curve. Unset:
    // benchProtocol(quick, reps). Its reps and time_res are the bench's own
    // (reps, res).
    std::optional<equaltime::Protocol> protocol;
    int samples = 32;  // N of the samples/s comparison (naive vs fast MC)
    int rounds = 3;  // alternating naive / fast rounds (median of each)
    size_t lx = 8, ly = 8;  // local size
    bool quick = false;  // fewer methods and MC fit points (tests)
    bool filtersOnly = false;  // the header and the filters' rows alone
};

// Runs the benchmark; returns the JSON document `bench --json` prints:
//   device, driver, res, luminaire, scene, local,
//   mc: {n, naive_ms, fast_ms, fast_exact_ms, general_lut_ms, naive_sps, fast_sps, ratio, target 10, ok},
//   methods: [{method, time_ms, ns_per_pixel, defines}],
//   protocol: the equal-time protocol's keys (equaltime/protocol.h),
//   mc_fit: {points [[n, ms]]} (the partner's t(N) at the protocol's fit),
//   cubature: {time_ms, mc8_ms, ratio, target 1, ok, and equaltime::search's
//     equal_time_n (+ equal_time_extra), verify_ms and paired_ms (MC's and
//     cubature's medians over the same paired rounds), equal_time_ratio,
//     equal_time_ok, equal_time_bracketed, equal_time_candidates},
//   filters: {bandwidth_gbps, peak_gflops, filters: [{spec, mc_ms, passes_ms,
//     ratio, goal, ok, passes: [{stage, ns_per_pixel, limit_ns_per_pixel}]}]}
//     (the image filters after one solid + sobol MC pass at N = 1).
nlohmann::json run(ocl::Runtime& rt, const photometry::Table& table, const Scene& scene, const Options& opt);

// The cubature's equal-time section of run()'s document ("cubature"): the
// protocol's search (equaltime::pairUp) of "cubature" against its partner on
// `frames`, aimed from the measured t(N) `fit` and the cubature's time cubMs;
// mc8Ms is MC's t(8) for the cubature / MC 8 ratio.
nlohmann::json cubatureEqualTime(const equaltime::Protocol& p, const equaltime::Frames& frames,
                                 const equaltime::Curve& fit, double cubMs, double mc8Ms);

// Human-readable table of run()'s document.
std::string format(const nlohmann::json& doc);

}  // namespace lb::bench
