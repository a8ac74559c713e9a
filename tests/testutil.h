// testutil.h -- shared helpers for the GoogleTest suite.
#pragma once

#include "cl/runtime.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>
#include "lb_build_config.h"

namespace lb::test {

// The OpenCL runtime shared by all tests of this process, or nullptr when the
// machine has no OpenCL device. Tests skip then, unless
// LUMIBENCH_REQUIRE_DEVICE=1 (set by .ci/run), where a missing device fails.
inline ocl::Runtime* runtime()
{
    static std::unique_ptr<ocl::Runtime> rt;
    static bool tried = false;
    if (!tried) {
        tried = true;
        try {
            rt = std::make_unique<ocl::Runtime>();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "no OpenCL runtime: %s\n", e.what());
        }
    }
    return rt.get();
}

inline bool deviceRequired()
{
    const char* e = std::getenv("LUMIBENCH_REQUIRE_DEVICE");
    return e && std::string(e) == "1";
}

#define LB_REQUIRE_RUNTIME(rt)                                                                  \
    ocl::Runtime* rt = ::lb::test::runtime();                                                   \
    if (!rt) {                                                                                  \
        if (::lb::test::deviceRequired()) FAIL() << "LUMIBENCH_REQUIRE_DEVICE=1 but no device"; \
        GTEST_SKIP() << "no OpenCL device";                                                     \
    }

// ../shared beside the checkout (luminaires, seeds), or "" when absent.
inline std::string sharedDir()
{
    std::filesystem::path p = LB_SHARED_DIR;
    return std::filesystem::is_directory(p / "luminaires") ? p.string() : std::string();
}

#define LB_REQUIRE_SHARED(dir)                 \
    std::string dir = ::lb::test::sharedDir(); \
    if (dir.empty()) GTEST_SKIP() << "../shared is not present";

inline std::string sourceDir() { return LB_SOURCE_DIR; }

struct CliResult {
    int code = -1;  // exit status, -1 if the program did not exit normally
    std::string out;  // stdout
    std::string err;  // stderr
};

// Runs a shell command line; its stdout, and in *code its exit status (-1 if it
// did not exit normally). Add 2>&1 to the line to capture stderr as well.
inline std::string shellOutput(const std::string& cmd, int* code)
{
    std::string out;
    *code = -1;
    std::array<char, 4096> buf;
    size_t n;
    if (FILE* p = popen(cmd.c_str(), "r")) {
        while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
        int st = pclose(p);
        *code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    }
    return out;
}

// Runs build/lumibench with `args` (a shell word list), stdout and stderr apart.
inline CliResult runCli(const std::string& args)
{
    static std::atomic<int> counter{0};
    auto errFile = std::filesystem::temp_directory_path() /
        ("lb-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".err");
    CliResult r;
    r.out = shellOutput(std::string(LB_BINARY) + " " + args + " 2>" + errFile.string(), &r.code);
    if (FILE* f = std::fopen(errFile.c_str(), "r")) {
        std::array<char, 4096> buf;
        size_t n;
        while ((n = fread(buf.data(), 1, buf.size(), f)) > 0) r.err.append(buf.data(), n);
        std::fclose(f);
    }
    std::filesystem::remove(errFile);
    return r;
}
inline std::string binary() { return LB_BINARY; }

// An empty directory <tmp>/lumibench-test-<name>-<pid> (removed first).
inline std::filesystem::path freshDir(const std::string& name)
{
    auto d = std::filesystem::temp_directory_path() / ("lumibench-test-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

// The message of the lb::InputError that f throws, or "(no error)".
inline std::string inputErrorOf(const std::function<void()>& f)
{
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

// Worst per-pixel relative difference |ref - test| / max(|ref|, floor peak)
// (peak: the largest |ref|); each pixel is held within `bound` (the loop
// stops at the first pixel beyond it). `what` names the comparison.
inline double worstRelDiff(const std::vector<double>& ref, const std::vector<double>& test, double floor, double bound,
                           const std::string& what)
{
    double peak = 0, worst = 0;
    for (double v : ref) peak = std::max(peak, std::fabs(v));
    EXPECT_GT(peak, 0) << what;
    for (size_t i = 0; i < ref.size(); ++i) {
        double d = std::fabs(ref[i] - test[i]) / std::max(std::fabs(ref[i]), floor * peak);
        worst = std::max(worst, d);
        EXPECT_LE(d, bound) << what << " pixel " << i << ": " << ref[i] << " vs " << test[i];
        if (d > bound) break;
    }
    return worst;
}

}  // namespace lb::test
