#include "cl/runtime.h"

#include "util/digest.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include "lb_build_config.h"

namespace lb::ocl {
namespace fs = std::filesystem;

std::string errorString(cl_int code)
{
    const char* s = "unknown OpenCL error";
    // clang-format off
    switch (code) {
#define E(x) case x: s = #x; break;
        E(CL_SUCCESS) E(CL_DEVICE_NOT_FOUND) E(CL_DEVICE_NOT_AVAILABLE) E(CL_COMPILER_NOT_AVAILABLE)
        E(CL_MEM_OBJECT_ALLOCATION_FAILURE) E(CL_OUT_OF_RESOURCES) E(CL_OUT_OF_HOST_MEMORY)
        E(CL_PROFILING_INFO_NOT_AVAILABLE) E(CL_MEM_COPY_OVERLAP) E(CL_IMAGE_FORMAT_MISMATCH)
        E(CL_IMAGE_FORMAT_NOT_SUPPORTED) E(CL_BUILD_PROGRAM_FAILURE) E(CL_MAP_FAILURE)
        E(CL_MISALIGNED_SUB_BUFFER_OFFSET) E(CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST)
        E(CL_COMPILE_PROGRAM_FAILURE) E(CL_LINKER_NOT_AVAILABLE) E(CL_LINK_PROGRAM_FAILURE)
        E(CL_DEVICE_PARTITION_FAILED) E(CL_KERNEL_ARG_INFO_NOT_AVAILABLE) E(CL_INVALID_VALUE)
        E(CL_INVALID_DEVICE_TYPE) E(CL_INVALID_PLATFORM) E(CL_INVALID_DEVICE) E(CL_INVALID_CONTEXT)
        E(CL_INVALID_QUEUE_PROPERTIES) E(CL_INVALID_COMMAND_QUEUE) E(CL_INVALID_HOST_PTR)
        E(CL_INVALID_MEM_OBJECT) E(CL_INVALID_IMAGE_FORMAT_DESCRIPTOR) E(CL_INVALID_IMAGE_SIZE)
        E(CL_INVALID_SAMPLER) E(CL_INVALID_BINARY) E(CL_INVALID_BUILD_OPTIONS) E(CL_INVALID_PROGRAM)
        E(CL_INVALID_PROGRAM_EXECUTABLE) E(CL_INVALID_KERNEL_NAME) E(CL_INVALID_KERNEL_DEFINITION)
        E(CL_INVALID_KERNEL) E(CL_INVALID_ARG_INDEX) E(CL_INVALID_ARG_VALUE) E(CL_INVALID_ARG_SIZE)
        E(CL_INVALID_KERNEL_ARGS) E(CL_INVALID_WORK_DIMENSION) E(CL_INVALID_WORK_GROUP_SIZE)
        E(CL_INVALID_WORK_ITEM_SIZE) E(CL_INVALID_GLOBAL_OFFSET) E(CL_INVALID_EVENT_WAIT_LIST)
        E(CL_INVALID_EVENT) E(CL_INVALID_OPERATION) E(CL_INVALID_GL_OBJECT) E(CL_INVALID_BUFFER_SIZE)
        E(CL_INVALID_MIP_LEVEL) E(CL_INVALID_GLOBAL_WORK_SIZE) E(CL_INVALID_PROPERTY)
        E(CL_INVALID_IMAGE_DESCRIPTOR) E(CL_INVALID_COMPILER_OPTIONS) E(CL_INVALID_LINKER_OPTIONS)
        E(CL_INVALID_DEVICE_PARTITION_COUNT)
#undef E
    case -1001: s = "CL_PLATFORM_NOT_FOUND_KHR (no OpenCL platform: is pocl-opencl-icd installed?)"; break;
    default: break;
    }
    // clang-format on
    return fmt::format("{} ({})", s, code);
}

static std::string typeName(cl_device_type t)
{
    if (t & CL_DEVICE_TYPE_GPU) return "GPU";
    if (t & CL_DEVICE_TYPE_CPU) return "CPU";
    if (t & CL_DEVICE_TYPE_ACCELERATOR) return "ACCELERATOR";
    return "OTHER";
}

std::vector<DeviceInfo> listDevices()
{
    std::vector<DeviceInfo> out;
    std::vector<cl::Platform> platforms;
    try {
        cl::Platform::get(&platforms);
    } catch (const cl::Error& e) {
        if (e.err() == -1001) return out;  // no ICD: an empty list, not a crash
        throw;
    }
    for (auto& p : platforms) {
        std::vector<cl::Device> devs;
        try {
            p.getDevices(CL_DEVICE_TYPE_ALL, &devs);
        } catch (const cl::Error&) {
            continue;  // a platform without devices
        }
        for (auto& d : devs) {
            DeviceInfo i;
            i.index = static_cast<int>(out.size());
            i.platform = p.getInfo<CL_PLATFORM_NAME>();
            i.name = d.getInfo<CL_DEVICE_NAME>();
            i.vendor = d.getInfo<CL_DEVICE_VENDOR>();
            i.version = d.getInfo<CL_DEVICE_VERSION>();
            i.driver = d.getInfo<CL_DRIVER_VERSION>();
            i.type = typeName(d.getInfo<CL_DEVICE_TYPE>());
            i.fp64 = d.getInfo<CL_DEVICE_EXTENSIONS>().find("cl_khr_fp64") != std::string::npos;
            i.pocl = i.platform.find("Portable Computing Language") != std::string::npos ||
                i.version.find("PoCL") != std::string::npos;
            i.computeUnits = d.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
            i.globalMem = d.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
            i.device = d;
            out.push_back(std::move(i));
        }
    }
    return out;
}

int chooseDevice(int requested)
{
    auto devs = listDevices();
    if (devs.empty()) throw Error("no OpenCL device found (install pocl-opencl-icd: scripts/install-deps.sh)");
    int idx = requested;
    std::string from = "device index";
    if (idx < 0) {
        if (const char* env = std::getenv("LUMIBENCH_DEVICE"); env && *env) {
            char* end = nullptr;
            long v = std::strtol(env, &end, 10);
            if (*end != '\0' || v < 0)
                throw InputError(
                    fmt::format("LUMIBENCH_DEVICE={}: expected a device index (see `lumibench devices`)", env));
            idx = static_cast<int>(v);
            from = "LUMIBENCH_DEVICE";
        }
    }
    if (idx < 0) {
        for (auto& d : devs)
            if (d.pocl) return d.index;
        return 0;
    }
    if (idx >= static_cast<int>(devs.size()))
        throw InputError(
            fmt::format("{} {}: only {} device(s) available (see `lumibench devices`)", from, idx, devs.size()));
    return idx;
}

std::string kernelDir()
{
    if (const char* env = std::getenv("LUMIBENCH_KERNEL_DIR"); env && *env) return env;
    return LB_SOURCE_KERNEL_DIR;
}

static std::string readFile(const fs::path& p)
{
    std::ifstream f(p, std::ios::binary);
    if (!f) throw Error(fmt::format("{}: cannot read kernel source", p.string()));
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

std::string kernelSourceDigest(const std::string& file)
{
    util::Digest d;
    std::set<fs::path> seen;
    const fs::path root = fs::path(kernelDir());
    std::function<void(const fs::path&)> visit = [&](const fs::path& p) {
        fs::path c = p.lexically_normal();
        if (!seen.insert(c).second) return;
        const std::string src = readFile(c);
        d.str(c.lexically_relative(root).generic_string());
        d.str(src);
        std::istringstream in(src);
        std::string line;
        while (std::getline(in, line)) {
            auto h = line.find_first_not_of(" \t");
            if (h == std::string::npos || line[h] != '#') continue;
            auto inc = line.find("include", h);
            auto q0 = line.find('"', h), q1 = q0 == std::string::npos ? q0 : line.find('"', q0 + 1);
            if (inc == std::string::npos || q1 == std::string::npos || inc > q0) continue;
            const std::string name = line.substr(q0 + 1, q1 - q0 - 1);
            fs::path local = c.parent_path() / name;
            visit(fs::exists(local) ? local : root / name);
        }
    };
    visit(root / file);
    return d.hex();
}

Timing summarize(std::vector<double> s)
{
    Timing t;
    t.samples_ms = s;
    t.reps = static_cast<int>(s.size());
    if (s.empty()) return t;
    std::sort(s.begin(), s.end());
    size_t n = s.size();
    t.median_ms = n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
    t.min_ms = s.front();
    t.max_ms = s.back();
    if (n > 1) {
        double mean = 0, ss = 0;
        for (double v : s) mean += v / static_cast<double>(n);
        for (double v : s) ss += (v - mean) * (v - mean);
        t.cv = mean > 0 ? std::sqrt(ss / static_cast<double>(n - 1)) / mean : 0;
    }
    return t;
}

Runtime::Runtime(int device)
{
    auto devs = listDevices();
    int idx = chooseDevice(device);
    info_ = devs.at(static_cast<size_t>(idx));
    try {
        context_ = cl::Context(info_.device);
        queue_ = cl::CommandQueue(context_, info_.device, CL_QUEUE_PROFILING_ENABLE);
    } catch (const cl::Error& e) {
        throw Error(fmt::format("cannot open OpenCL device {} ({}): {} failed: {}", idx, info_.name, e.what(),
                                errorString(e.err())));
    }
    // Digest of every shared header: a change there invalidates cached programs.
    std::string all;
    fs::path common = fs::path(kernelDir()) / "common";
    if (fs::is_directory(common)) {
        std::vector<fs::path> files;
        for (auto& e : fs::directory_iterator(common)) files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (auto& f : files) all += readFile(f);
    }
    headerDigest_ = std::to_string(std::hash<std::string>{}(all));
}

cl::Program& Runtime::program(const std::string& file, const std::string& options)
{
    fs::path path = fs::path(kernelDir()) / file;
    std::string src = readFile(path);
    std::string key =
        file + '\n' + options + '\n' + headerDigest_ + '\n' + std::to_string(std::hash<std::string>{}(src));
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;

    // PoCL splits options at spaces and keeps quotes: the kernel path must not contain spaces.
    std::string dir = fs::absolute(kernelDir()).string();
    if (dir.find(' ') != std::string::npos)
        throw Error(fmt::format("kernel directory '{}' contains a space, which OpenCL -I cannot take", dir));
    std::string opts = fmt::format("-I {} -cl-std=CL1.2 {}", dir, options);
    auto t0 = std::chrono::steady_clock::now();
    cl::Program prog(context_, src);
    try {
        prog.build(std::vector<cl::Device>{info_.device}, opts.c_str());
    } catch (const cl::Error& e) {
        std::string log;
        try {
            log = prog.getBuildInfo<CL_PROGRAM_BUILD_LOG>(info_.device);
        } catch (...) {
        }
        throw Error(fmt::format("building {} with options '{}' failed: {}\n{}", path.string(), options,
                                errorString(e.err()), log));
    }
    buildSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return cache_.emplace(key, std::move(prog)).first->second;
}

cl::Kernel Runtime::kernel(const std::string& file, const std::string& name, const std::string& options)
{
    cl::Program& p = program(file, options);
    try {
        return cl::Kernel(p, name.c_str());
    } catch (const cl::Error& e) {
        throw Error(fmt::format("kernel '{}' in {}: {}", name, file, errorString(e.err())));
    }
}

static size_t roundUp(size_t n, size_t m) { return (n + m - 1) / m * m; }

cl::Event Runtime::launch2D(cl::Kernel& k, size_t w, size_t h, size_t lx, size_t ly)
{
    cl::Event ev;
    queue_.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(roundUp(w, lx), roundUp(h, ly)), cl::NDRange(lx, ly),
                                nullptr, &ev);
    return ev;
}

cl::Event Runtime::launch1D(cl::Kernel& k, size_t n, size_t lx)
{
    cl::Event ev;
    queue_.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(roundUp(n, lx)), cl::NDRange(lx), nullptr, &ev);
    return ev;
}

double Runtime::eventMs(const cl::Event& e)
{
    e.wait();
    cl_ulong a = e.getProfilingInfo<CL_PROFILING_COMMAND_START>();
    cl_ulong b = e.getProfilingInfo<CL_PROFILING_COMMAND_END>();
    return static_cast<double>(b - a) * 1e-6;
}

Timing Runtime::time(const std::function<cl::Event()>& launch, int reps, int warmup)
{
    for (int i = 0; i < warmup; ++i) launch().wait();
    std::vector<double> s;
    for (int i = 0; i < reps; ++i) s.push_back(eventMs(launch()));
    return summarize(s);
}

std::vector<Timing> Runtime::timeInterleaved(const std::vector<std::function<double()>>& launches, int reps, int warmup)
{
    for (int i = 0; i < warmup; ++i)
        for (const auto& l : launches) l();
    std::vector<std::vector<double>> s(launches.size());
    for (int i = 0; i < reps; ++i)
        for (size_t k = 0; k < launches.size(); ++k) s[k].push_back(launches[k]());
    std::vector<Timing> t;
    for (auto& v : s) t.push_back(summarize(v));
    return t;
}

void setReal(cl::Kernel& k, cl_uint idx, double v, bool dbl)
{
    if (dbl)
        k.setArg(idx, v);
    else
        k.setArg(idx, static_cast<float>(v));
}

}  // namespace lb::ocl
