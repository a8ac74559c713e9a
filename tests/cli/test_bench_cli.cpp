// lumibench bench: a small smoke run (the goals themselves are measured by
// hand at 512^2 and recorded in docs/performance.md, not asserted here).
#include "testutil.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <memory>

namespace lb {
namespace {

std::pair<int, std::string> runBench(const std::string& args)
{
    auto c = test::runCli("bench " + args);
    return {c.code, c.out};
}

TEST(BenchCli, QuickJsonRun)
{
    LB_REQUIRE_RUNTIME(rt);
    auto [code, out] = runBench("--res 24 --quick --json --rounds 1 --reps 1 --samples 4 --luminaire downlight");
    ASSERT_EQ(code, 0) << out;
    auto j = nlohmann::json::parse(out);
    for (const char* k : {"context", "device", "driver", "res", "mc", "methods", "mc_fit", "cubature", "specialization",
                          "cubature_specialization", "cubature_lanes", "lut"})
        EXPECT_TRUE(j.contains(k)) << k;
    EXPECT_EQ(j["res"], 24);
    // downlight.ldt is rotational and emits nothing backwards: all rules fire.
    EXPECT_EQ(j["specialization"]["lut1d"], true);
    EXPECT_EQ(j["specialization"]["no_back"], true);
    EXPECT_GT(j["mc"]["naive_sps"].get<double>(), 0);
    EXPECT_GT(j["mc"]["fast_sps"].get<double>(), 0);
    EXPECT_NEAR(j["mc"]["ratio"].get<double>(), j["mc"]["naive_ms"].get<double>() / j["mc"]["fast_ms"].get<double>(),
                1e-9);
    EXPECT_GE(j["cubature"]["equal_time_n"].get<int>(), 1);
    // The t(N) curve at the protocol's fit (--quick: 1, 8, 32), its rounds max(reps, 11).
    EXPECT_EQ(j["protocol"]["fit"], nlohmann::json({1, 8, 32}));
    EXPECT_EQ(j["protocol"]["rounds"], 11);
    ASSERT_EQ(j["mc_fit"]["points"].size(), 3u);
    for (size_t i = 0; i < 3; ++i) EXPECT_EQ(j["mc_fit"]["points"][i][0], j["protocol"]["fit"][i]);
    EXPECT_TRUE(j["context"].contains("commit"));
    // h = 1: the cubature takes the straight-line rectangle fan, 8 lanes on a
    // CPU device (PoCL), one pixel per work-item elsewhere
    EXPECT_EQ(j["cubature_specialization"]["rect_fan"], true);
    EXPECT_EQ(j["cubature_lanes"].get<int>(), rt->info().type == "CPU" ? 8 : 1);
    EXPECT_GE(j["methods"].size(), 6u);
}

// plots/bench_table.py turns the committed runs into the tables of
// docs/performance.md: the median run by the cubature ratio, and a clear
// error for a missing file.
TEST(BenchCli, TableScriptReadsCommittedRuns)
{
    std::string dir = test::sourceDir();
    std::string cmd = "python3 " + dir + "/plots/bench_table.py " + dir + "/experiments/bench/pocl-epyc-run1.json " +
        dir + "/experiments/bench/pocl-epyc-run2.json " + dir + "/experiments/bench/pocl-epyc-run3.json 2>&1";
    std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), pclose);
    ASSERT_TRUE(p);
    std::string out;
    std::array<char, 4096> buf{};
    while (fgets(buf.data(), buf.size(), p.get())) out += buf.data();
    EXPECT_NE(out.find("Median run: "), std::string::npos) << out;
    EXPECT_NE(out.find("| cubature / MC 8 time (target <= 1) |"), std::string::npos) << out;
    EXPECT_NE(out.find("| mc:n=8 |"), std::string::npos) << out;
    // Groups separated by `--` come side by side: one column per group, and
    // "-" where a group's run lacks a method row.
    std::string b = dir + "/experiments/bench/";
    cmd = "python3 " + dir + "/plots/bench_table.py " + b + "pocl-epyc-run1.json -- " + b + "nvidia-h100-run1.json " +
        b + "nvidia-h100-run2.json 2>&1";
    p.reset(popen(cmd.c_str(), "r"));
    ASSERT_TRUE(p);
    out.clear();
    while (fgets(buf.data(), buf.size(), p.get())) out += buf.data();
    EXPECT_NE(out.find("| quantity | pthread-haswell-AMD EPYC (512^2) | NVIDIA H100 80GB HBM3 (512^2) |"),
              std::string::npos)
        << out;
    auto row = out.find("| cubature:lanes=1 | ");  // 8 lanes on the CPU only: no GPU row
    ASSERT_NE(row, std::string::npos) << out;
    std::string line = out.substr(row, out.find('\n', row) - row);
    EXPECT_EQ(line.substr(line.size() - 10), " | - | - |") << line;
    std::string bad = "python3 " + dir + "/plots/bench_table.py " + dir + "/nothing.json > /dev/null 2>&1";
    EXPECT_NE(std::system(bad.c_str()), 0);
}

TEST(BenchCli, BadOptionsExitTwo)
{
    EXPECT_EQ(runBench("--local 8 --res 8").first, 2);
    EXPECT_EQ(runBench("--res 0").first, 2);
    EXPECT_EQ(runBench("--rounds 0").first, 2);
    // --equal-time: a JSON object of the protocol's keys; reps and time_res are --reps and --res
    for (const char* bad :
         {"'[1]'", "'{\"reps\": 3}'", "'{\"fit\": [8]}'", "'{\"mode\": \"fast\"}'", "'{\"rounds\": 11'"}) {
        auto c = test::runCli(std::string("bench --res 8 --equal-time ") + bad);
        EXPECT_EQ(c.code, 2) << bad << ": " << c.err;
        EXPECT_NE(c.err.find("--equal-time"), std::string::npos) << c.err;
    }
}

}  // namespace
}  // namespace lb
