// The indirect scene from the command line, as CI runs it: the smoke
// experiment (every RSM method, acrsm against VPLs at equal time) and a short
// animated sequence with its flicker.
#include "testutil.h"

#include "experiments/experiment.h"
#include "experiments/results.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

namespace lb {
namespace {

namespace fs = std::filesystem;

struct TempDir {
    fs::path p = fs::temp_directory_path() / ("lb-indirect-" + std::to_string(::getpid()));
    TempDir() { fs::create_directories(p); }
    ~TempDir() { fs::remove_all(p); }
};

TEST(IndirectCli, SmokeExperimentRendersEveryMethodWithAnEqualTimePartner)
{
    LB_REQUIRE_RUNTIME(rt);
    TempDir d;
    const std::string smoke = test::sourceDir() + "/experiments/indirect-smoke.json";
    auto r = test::runCli("run '" + smoke + "' --out " + (d.p / "out").string() + " --no-report --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    auto doc = results::load((d.p / "out" / "results.json").string());
    auto e = experiments::loadExperiment(smoke);
    std::set<std::string> methods;
    size_t eq = 0;
    for (auto& rec : doc.records) {
        EXPECT_EQ(rec.error.nonfinite, 0) << rec.key();
        EXPECT_TRUE(std::isfinite(rec.error.nmse)) << rec.key();
        // the methods' own images are near the reference; an equal-time MC
        // partner's N follows the measured times, and on a loaded machine a
        // small N gives more (measured 1.43 for the acrsm partner at updown
        // h 1.1 in one clean-clone run): it is held to finite only
        if (!rec.equal_time_to.has_value()) {
            EXPECT_LT(rec.error.nmse, 1.0) << rec.key();
        }
        methods.insert(rec.method);
        eq += rec.equal_time_to.has_value();
    }
    for (const char* m : {"vpl", "kmeans", "acrsm", "mc"}) EXPECT_TRUE(methods.count(m)) << m;
    EXPECT_EQ(eq, e.equalTime.size());
}

TEST(IndirectCli, SequenceReportsFlickerPerMethod)
{
    LB_REQUIRE_RUNTIME(rt);
    TempDir d;
    const std::string out = (d.p / "seq.json").string();
    auto r = test::runCli("sequence --luminaire " + test::sourceDir() +
                          "/luminaires/updown.ldt --method vpl:rsm=64,n=64 --method kmeans:rsm=64,k=16 "
                          "--method acrsm:rsm=64,k=16 --path rotate --frames 3 --res 8 --height 1.1 "
                          "--reference reference:tol=1e-3,dir_tol=1e-4,dir_cell=0.5 --no-cache --out " +
                          out);
    ASSERT_EQ(r.code, 0) << r.err;
    nlohmann::json j;
    std::ifstream(out) >> j;
    ASSERT_EQ(j["frames"].size(), 3u);
    for (const char* m : {"vpl:rsm=64,n=64", "kmeans:rsm=64,k=16", "acrsm:rsm=64,k=16"}) {
        ASSERT_TRUE(j["flicker"].contains(m)) << m;
        EXPECT_TRUE(j["flicker"][m].is_number()) << m;
        EXPECT_GE(j["flicker"][m].get<double>(), 0.0) << m;
        EXPECT_GE(j["flicker_seq"][m].get<double>(), 0.0) << m;
    }
    // a bad path is an input error (exit 2) naming the flag
    auto bad = test::runCli("sequence --luminaire " + test::sourceDir() +
                            "/luminaires/updown.ldt --method vpl --path spin --out " + out);
    EXPECT_EQ(bad.code, 2);
    EXPECT_NE(bad.err.find("--path"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace lb
