// plots/visual_claims.py: the tables of docs/studies/visual-claims.md from a results
// file, checked on hand-made records (no device needed).
#include "testutil.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace lb {
namespace {

namespace fs = std::filesystem;

nlohmann::json rec(const std::string& role, const std::string& method, nlohmann::json params, const char* lum, double h,
                   double nmse, double grad, double flip)
{
    return {{"role", role},      {"method", method}, {"params", params},  {"luminaire", lum}, {"height", h},
            {"rotation", 2.356}, {"nmse", nmse},     {"grad_nmse", grad}, {"flip", flip}};
}

TEST(Plots, VisualClaimsTables)
{
    fs::path dir = fs::temp_directory_path() / ("lb_visual_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const nlohmann::json sct = {{"triangulation", "fan"}, {"dynamic", "cp"}};
    nlohmann::json recs = nlohmann::json::array();
    // Two luminaires at h 0.1 and 1.1. A: MCI-24 wins in NMSE in both scenes, loses in
    // grad_nmse at h 0.1 (the bumps), FLIP equal there (a tie is not a win).
    for (double h : {0.1, 1.1}) {
        recs.push_back(rec("method", "cubature", sct, "A_1.ldt", h, 4.0, h < 1 ? 0.01 : 0.1, 0.2));
        recs.push_back(rec("method", "mc", {{"n", 24}}, "A_1.ldt", h, 1.0, h < 1 ? 0.04 : 0.01, 0.2));
        recs.push_back(rec("mci_curve", "mc", {{"n", 24}}, "A_1.ldt", h, 99.0, 99.0, 0.9));  // not MCI-24
        recs.push_back(rec("method", "cubature", sct, "B_2.ldt", h, 1.0, 1.0, 0.1));
        recs.push_back(rec("method", "mc", {{"n", 24}}, "B_2.ldt", h, 2.0, 0.5, 0.3));
    }
    std::ofstream(dir / "results.json") << nlohmann::json{{"records", recs}}.dump();
    int code = -1;
    const std::string script = "python3 " + test::sourceDir() + "/plots/visual_claims.py ";
    std::string out = test::shellOutput(script + (dir / "results.json").string() + " 2>&1", &code);
    ASSERT_EQ(code, 0) << out;
    EXPECT_NE(out.find("4 scenes: 2 luminaires, heights 0.1, 1.1"), std::string::npos) << out;
    // geometric means of one scene each: the values themselves
    EXPECT_NE(out.find("| A | h 0.1 | grad_nmse | 0.01 | 0.04 |"), std::string::npos) << out;
    // SCT's mean over MCI-24's at A, h 0.1: NMSE 4 / 1, grad_nmse 0.01 / 0.04, FLIP 0.2 / 0.2
    EXPECT_NE(out.find("| A | h 0.1 | 4 | 0.25 | 1 |"), std::string::npos) << out;
    // A: MCI-24 below SCT in NMSE 2 / 2, grad_nmse 1 / 2 (only at h 1.1), FLIP 0 / 2 (ties);
    // B: 0 / 2, 2 / 2, 0 / 2. Near the light (h 0.1) only: A 1 / 1, 0 / 1, 0 / 1.
    EXPECT_NE(out.find("| A | 2 / 2 | 1 / 2 | 0 / 2 |"), std::string::npos) << out;
    EXPECT_NE(out.find("| B | 0 / 2 | 2 / 2 | 0 / 2 |"), std::string::npos) << out;
    EXPECT_NE(out.find("| **all** | 2 / 4 | 3 / 4 | 0 / 4 |"), std::string::npos) << out;
    EXPECT_NE(out.find("| A | 1 / 1 | 0 / 1 | 0 / 1 |"), std::string::npos) << out;
    // ranks by SCT's error: B has the smaller NMSE (1 < 4), A the smaller grad_nmse and the larger FLIP
    EXPECT_NE(out.find("| A | 4 (2) | 0.0316 (1) | 0.2 (2) |"), std::string::npos) << out;
    std::ofstream(dir / "bad.json") << "{\"x\": 1}";
    out = test::shellOutput(script + (dir / "bad.json").string() + " 2>&1", &code);
    EXPECT_NE(code, 0) << out;
    fs::remove_all(dir);
}

// The counts docs/studies/visual-claims.md quotes come from the committed run.
TEST(Plots, VisualClaimsReproducesTheCommittedRun)
{
    int code = -1;
    std::string out =
        test::shellOutput("python3 " + test::sourceDir() + "/plots/visual_claims.py " + test::sourceDir() +
                              "/experiments/results/visual-claims-pocl-xeon.json.xz 2>&1",
                          &code);
    ASSERT_EQ(code, 0) << out;
    EXPECT_NE(out.find("28 scenes: 7 luminaires"), std::string::npos) << out;
    EXPECT_NE(
        out.find("| **all** | 26 / 28 | 27 / 28 | 26 / 28 | 26 / 28 | 28 / 28 | 25 / 28 | 4 / 28 | 4 / 28 | 5 / 28 |"),
        std::string::npos)
        << out;
    EXPECT_NE(out.find("| ARCOS3 | h 0.1 | 6.63 | 1.26 | 2.22 |"), std::string::npos) << out;
    EXPECT_NE(out.find("| ARCOS3 | 0.405 (7) | 0.000666 (7) | 0.224 (7) |"), std::string::npos) << out;
}

}  // namespace
}  // namespace lb
