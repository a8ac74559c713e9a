// runtime.h -- the OpenCL layer: device choice, program build and cache,
// launches with an explicit small local size, profiling-event timing.
#pragma once

#define CL_HPP_TARGET_OPENCL_VERSION 120
#define CL_HPP_MINIMUM_OPENCL_VERSION 120
#define CL_HPP_ENABLE_EXCEPTIONS
#include <CL/opencl.hpp>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace lb::ocl {

// Timed launches per measurement at most (--reps, "reps"): 1000 launches of
// the slowest kernel at 512^2 (the naive MC, ~0.4 s) take 7 minutes already,
// and the median of more adds nothing.
constexpr int kMaxReps = 1000;

// A readable name for an OpenCL error code ("CL_OUT_OF_RESOURCES (-5)").
std::string errorString(cl_int code);

struct DeviceInfo {
    int index = 0;  // position in listDevices(): what --device takes
    std::string platform;  // platform name
    std::string name;  // device name
    std::string vendor;
    std::string version;  // device OpenCL version
    std::string driver;  // driver version
    std::string type;  // CPU, GPU, ACCELERATOR
    bool fp64 = false;
    bool pocl = false;
    cl_uint computeUnits = 0;
    cl_ulong globalMem = 0;
    cl::Device device;
};

// Every device of every platform, flattened in platform order.
std::vector<DeviceInfo> listDevices();

// The device index to use: `requested` if >= 0, else $LUMIBENCH_DEVICE, else
// the first PoCL device, else device 0. Throws InputError for a bad index.
int chooseDevice(int requested = -1);

// Directory of the .cl sources: $LUMIBENCH_KERNEL_DIR or the source tree's kernels/.
std::string kernelDir();

// Digest (util/digest.h, 16 hex digits) of kernels/<file> and of every file
// it includes with #include "..." (transitively; resolved against the
// including file's directory, then the kernel directory): what a kernel
// computes, for keys of results and caches. Throws lb::Error naming a
// missing source.
std::string kernelSourceDigest(const std::string& file);

// Robust statistics of repeated timings, in milliseconds.
struct Timing {
    double median_ms = 0, min_ms = 0, max_ms = 0;
    double cv = 0;  // coefficient of variation: sample standard deviation / mean (google/benchmark's "cv")
    int reps = 0;
    std::vector<double> samples_ms;
};
Timing summarize(std::vector<double> samples_ms);

class Runtime {
public:
    explicit Runtime(int device = -1);

    const DeviceInfo& info() const { return info_; }
    cl::Context& context() { return context_; }
    cl::CommandQueue& queue() { return queue_; }

    // Builds kernels/<file> with `options` (plus -I kernels/), cached in this
    // process by (source, headers, options). Throws lb::Error with the build
    // log on failure. buildSeconds() accumulates the wall time of real builds.
    cl::Program& program(const std::string& file, const std::string& options = "");
    cl::Kernel kernel(const std::string& file, const std::string& name, const std::string& options = "");
    double buildSeconds() const { return buildSeconds_; }
    bool fp64() const { return info_.fp64; }

    // Launches a 2D range over (w, h) work-items with the local size lx x ly,
    // the global size rounded up to it: kernels must check their bounds.
    cl::Event launch2D(cl::Kernel& k, size_t w, size_t h, size_t lx = 8, size_t ly = 8);
    cl::Event launch1D(cl::Kernel& k, size_t n, size_t lx = 64);

    // Device time of one event (START to END) in ms; waits for it.
    static double eventMs(const cl::Event& e);

    // One warm-up, then `reps` timed launches (median, min, max kept).
    Timing time(const std::function<cl::Event()>& launch, int reps = 5, int warmup = 1);
    // Several launches timed in alternation: `warmup` of each, then `reps`
    // rounds launching each in turn; each launch returns its own device time
    // in ms (a multi-pass method: its passes plus its render kernel, see
    // methods::Prepared::launchMs). Timing::samples_ms keeps the rounds in
    // order, so ratios can be taken round by round and a shared machine's
    // drift hits every launch alike.
    // Needs no device of its own (the launches time themselves): static.
    static std::vector<Timing> timeInterleaved(const std::vector<std::function<double()>>& launches, int reps = 5,
                                               int warmup = 1);

private:
    DeviceInfo info_;
    cl::Context context_;
    cl::CommandQueue queue_;
    std::map<std::string, cl::Program> cache_;
    std::string headerDigest_;
    double buildSeconds_ = 0;
};

// Sets a kernel argument of type `real`: float or double as the program was built.
void setReal(cl::Kernel& k, cl_uint idx, double v, bool dbl);

}  // namespace lb::ocl
