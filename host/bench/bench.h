// bench.h -- `lumibench bench`: MC samples per second against a
// deliberately naive kernel (kernels/naive.cl), time per pixel of every
// method, cubature against MC with 8 samples, and cubature's equal-time MC
// sample count, all in one run on one device. Timing: OpenCL profiling events,
// one warm-up and the median of `reps` launches (ocl::Runtime::time).
#pragma once

#include "cl/runtime.h"
#include "photometry/table.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <string>

namespace lb::bench {

struct Options {
    int res = 512;
    int reps = 5;
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
//   mc_fit: {points [[n, ms]], t0_ms, ms_per_sample},
//   cubature: {time_ms, mc8_ms, ratio, target 1, ok, and equaltime::search's
//     equal_time_n (+ equal_time_extra), verify_ms and paired_ms (MC's and
//     cubature's medians over the same paired rounds), equal_time_ratio,
//     equal_time_ok, equal_time_bracketed, equal_time_candidates},
//   filters: {bandwidth_gbps, peak_gflops, filters: [{spec, mc_ms, passes_ms,
//     ratio, goal, ok, passes: [{stage, ns_per_pixel, limit_ns_per_pixel}]}]}
//     (the image filters after one solid + sobol MC pass at N = 1).
nlohmann::json run(ocl::Runtime& rt, const photometry::Table& table, const Scene& scene, const Options& opt);

// Human-readable table of run()'s document.
std::string format(const nlohmann::json& doc);

}  // namespace lb::bench
