// lumibench compare as outside tools call it (docs/design.md section 7), on EXR files
// written here.
#include "metrics/flip.h"
#include "metrics/image.h"
#include "metrics/png.h"
#include "testutil.h"
#include "util/fileio.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include <sys/wait.h>
#include <unistd.h>

namespace lb {
namespace {

namespace fs = std::filesystem;

struct Result {
    int code;
    std::string out, err;
};

// Runs build/lumibench with `args`; stdout and stderr apart.
Result run(const std::string& args, const fs::path&)
{
    auto c = test::runCli(args);
    return {c.code, c.out, c.err};
}

// A scratch folder per test, removed afterwards.
struct CompareCli : ::testing::Test {
    fs::path dir;
    std::string ref, test, big;
    void SetUp() override
    {
        dir = fs::temp_directory_path() /
            ("lb_compare_" + std::to_string(getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir);
        // R = [1 2; 3 4], A = [2 2; 2 6]: exact in float, so the metrics are those of
        // tests/metrics/test_metrics.cpp: NMSE 0.2, UEB 2, LEB -1.
        Image r(2, 2), a(2, 2);
        r.px = {1, 2, 3, 4};
        a.px = {2, 2, 2, 6};
        ref = (dir / "ref.exr").string();
        test = (dir / "test.exr").string();
        big = (dir / "big.exr").string();
        writeExr(ref, r);
        writeExr(test, a);
        writeExr(big, Image(3, 2, 1.0));
    }
    void TearDown() override { fs::remove_all(dir); }
};

TEST_F(CompareCli, JsonHasTheMetrics)
{
    auto r = run("compare " + ref + " " + test + " --json", dir);
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    auto j = nlohmann::json::parse(r.out);  // exactly one JSON object on stdout
    // Same exact dyadic arithmetic as the library test; the JSON carries 17
    // significant digits, so 4 ulp holds through the text.
    EXPECT_DOUBLE_EQ(j["nmse"].get<double>(), 0.2);
    EXPECT_DOUBLE_EQ(j["nrmse"].get<double>(), std::sqrt(1.5) / 2.5);
    EXPECT_DOUBLE_EQ(j["relmse"].get<double>(), (16.0 / 17 + 16.0 / 145 + 64.0 / 257) / 4);
    EXPECT_EQ(j["ueb"].get<double>(), 2.0);
    EXPECT_EQ(j["leb"].get<double>(), -1.0);
    EXPECT_EQ(j["nonfinite"].get<int>(), 0);
    EXPECT_EQ(j["pixels"].get<int>(), 4);
    EXPECT_DOUBLE_EQ(j["mean_ref"].get<double>(), 2.5);
    EXPECT_DOUBLE_EQ(j["mean_test"].get<double>(), 3.0);
    // grad_nmse hand computed in tests/metrics/test_metrics.cpp (0.6, exact dyadic: 4 ulp).
    EXPECT_DOUBLE_EQ(j["grad_nmse"].get<double>(), 0.6);
    EXPECT_EQ(j["grad_pairs"].get<int>(), 4);
    // flip: a FLIP value in (0, 1) when flip-evaluator imports (measured 0.193
    // for these four pixels), null with a warning otherwise; never missing.
    ASSERT_TRUE(j.contains("flip"));
    if (metrics::flipAvailable()) {
        ASSERT_TRUE(j["flip"].is_number()) << r.err;
        EXPECT_GT(j["flip"].get<double>(), 0.0);
        EXPECT_LT(j["flip"].get<double>(), 1.0);
    } else {
        EXPECT_TRUE(j["flip"].is_null());
    }
    EXPECT_FALSE(j.contains("pictures"));  // no --png, no pictures
}

// Without flip-evaluator (here: no Python at all) flip is null, the rest is
// computed, and one warning says why and how to get it; exit 0.
TEST_F(CompareCli, FlipIsNullWithOneWarningWhenNotAvailable)
{
    // LUMIBENCH_FLIP_PYTHON pointing nowhere stands for a machine without the package.
    const char* was = std::getenv("LUMIBENCH_FLIP_PYTHON");
    std::string saved = was ? was : "";
    setenv("LUMIBENCH_FLIP_PYTHON", (dir / "no-python").c_str(), 1);
    auto r = run("compare " + ref + " " + test + " --json", dir);
    auto t = run("compare " + ref + " " + test, dir);
    if (was)
        setenv("LUMIBENCH_FLIP_PYTHON", saved.c_str(), 1);
    else
        unsetenv("LUMIBENCH_FLIP_PYTHON");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    auto j = nlohmann::json::parse(r.out);
    ASSERT_TRUE(j.contains("flip"));
    EXPECT_TRUE(j["flip"].is_null());
    EXPECT_DOUBLE_EQ(j["nmse"].get<double>(), 0.2);  // the rest as with FLIP (4 ulp: see JsonHasTheMetrics)
    EXPECT_DOUBLE_EQ(j["grad_nmse"].get<double>(), 0.6);
    // One warning, naming the missing Python and the way to install it.
    size_t at = r.err.find("warning: FLIP is not available");
    ASSERT_NE(at, std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("warning: FLIP", at + 1), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no-python"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("install-deps.sh"), std::string::npos) << r.err;
    ASSERT_EQ(t.code, 0) << t.out << t.err;
    EXPECT_NE(t.out.find("FLIP       n/a"), std::string::npos) << t.out;
}

TEST_F(CompareCli, TableNamesEveryMetric)
{
    auto r = run("compare " + ref + " " + test, dir);
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    for (const char* s : {"NMSE       2.000000e-01", "UEB        2.000000e+00", "LEB        -1.000000e+00", "NRMSE",
                          "relMSE", "0 non-finite", "grad NMSE  6.000000e-01", "FLIP "})
        EXPECT_NE(r.out.find(s), std::string::npos) << s << "\n" << r.out;
}

TEST_F(CompareCli, NonFiniteTestPixelsAreReported)
{
    Image a(2, 2);
    a.px = {2, std::nan(""), 2, INFINITY};
    auto bad = (dir / "bad.exr").string();
    writeExr(bad, a);
    auto r = run("compare " + ref + " " + bad + " --json --png " + (dir / "nf").string(), dir);
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["nonfinite"].get<int>(), 2);
    EXPECT_DOUBLE_EQ(j["nmse"].get<double>(), 0.25);  // hand computed in test_metrics.cpp
    EXPECT_NE(r.err.find("2 non-finite"), std::string::npos) << r.err;
    EXPECT_EQ(readPng((dir / "nf_err.png").string()).at(0, 1), tonemap::kNonFinite);
    EXPECT_EQ(readPng((dir / "nf_test.png").string()).at(1, 1), tonemap::kNonFinite);
}

TEST_F(CompareCli, PicturesHaveTheExpectedColours)
{
    auto prefix = (dir / "fig").string();
    auto r = run("compare " + ref + " " + test + " --json --png " + prefix, dir);
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_DOUBLE_EQ(j["k"].get<double>(), 0.4);  // default 1 / mean(R) = 1 / 2.5
    // One symmetric bound: the 99.9th percentile of |A - R| = [1 0 1 2] (at 4
    // pixels the largest), the same for both sides.
    EXPECT_EQ(j["bound"].get<double>(), 2.0);
    EXPECT_EQ(j["bound_over"].get<double>(), 2.0);
    EXPECT_EQ(j["bound_under"].get<double>(), 2.0);
    EXPECT_EQ(j["colour_bar"].size(), 33u);

    // Error A - R = [1 0; -1 2] at the bound 2: half orange, white, half blue, orange.
    auto e = readPng(prefix + "_err.png");
    ASSERT_EQ(e.width, 2);
    ASSERT_EQ(e.height, 2);
    EXPECT_EQ(e.at(0, 0), tonemap::errorColour(1.0, 2.0, 2.0));  // half way (tests/metrics/test_tonemap.cpp)
    EXPECT_EQ(e.at(0, 1), tonemap::kWhite);
    EXPECT_EQ(e.at(1, 0), tonemap::errorColour(-1.0, 2.0, 2.0));  // as pale as +1: the scale is symmetric
    EXPECT_FALSE(e.at(1, 0) == tonemap::kBlue);
    EXPECT_EQ(e.at(1, 1), tonemap::kOrange);
    // The SVG figure: the picture with its colour bar labelled in lux and in %
    // of the reference mean (2.5 lx: +-2 lx is +-80 %).
    const std::string svg = util::readFile(prefix + "_err.svg", "an SVG figure", size_t(1) << 20);
    for (const char* s : {"<svg", "data:image/png;base64,", "linearGradient", "-2 lx", "+2 lx", "+1 lx", "0 lx",
                          "-80 %", "+80 %", "reference mean 2.5 lx", "saturated beyond +-2 lx"})
        EXPECT_NE(svg.find(s), std::string::npos) << s << "\n" << svg.substr(0, 400);
    // Tone mapped with k = 0.4: E = 1 -> 0.4/1.4 -> 73; E = 2 (test, row 0 col 0) -> 0.8/1.8 -> 113.3 -> 113.
    EXPECT_EQ(readPng(prefix + "_ref.png").at(0, 0), (tonemap::Rgb8{73, 73, 73}));
    EXPECT_EQ(readPng(prefix + "_test.png").at(0, 0), (tonemap::Rgb8{113, 113, 113}));

    // --k and --bound override: E = 1 with k = 1 -> 128; d = +1 with bound 1 -> orange.
    auto r2 = run("compare " + ref + " " + test + " --png " + prefix + " --k 1 --bound 1", dir);
    ASSERT_EQ(r2.code, 0) << r2.out << r2.err;
    EXPECT_EQ(readPng(prefix + "_ref.png").at(0, 0), (tonemap::Rgb8{128, 128, 128}));
    EXPECT_EQ(readPng(prefix + "_err.png").at(0, 0), tonemap::kOrange);
}

TEST_F(CompareCli, BadInputExitsWithCode2AndAClearMessage)
{
    auto missing = (dir / "missing.exr").string();
    auto r = run("compare " + ref + " " + missing, dir);
    EXPECT_EQ(r.code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;

    auto s = run("compare " + ref + " " + big, dir);
    EXPECT_EQ(s.code, 2) << s.out << s.err;
    EXPECT_NE(s.err.find("sizes differ: reference is 2x2, test is 3x2"), std::string::npos) << s.err;
    EXPECT_NE(s.err.find(big), std::string::npos) << s.err;

    auto k = run("compare " + ref + " " + test + " --k -1", dir);
    EXPECT_EQ(k.code, 2) << k.out << k.err;

    // A black reference has no default k: ask for --k rather than divide by zero.
    auto black = (dir / "black.exr").string();
    writeExr(black, Image(2, 2, 0.0));
    auto b = run("compare " + black + " " + test + " --png " + (dir / "b").string(), dir);
    EXPECT_EQ(b.code, 2) << b.out << b.err;
    EXPECT_NE(b.err.find("--k"), std::string::npos) << b.err;
}

}  // namespace
}  // namespace lb
