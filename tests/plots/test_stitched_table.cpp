// plots/stitched_table.py: the thesis' stitched NMSE from a results file,
// checked on two hand-made rotations (no device needed).
#include "experiments/results.h"
#include "testutil.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <unistd.h>

namespace lb {
namespace {

namespace fs = std::filesystem;

nlohmann::json rec(const std::string& role, const std::string& spec, double R, double nmse, double mref, double mtest)
{
    nlohmann::json r = {{"role", role},  {"spec", spec},     {"luminaire", "L_1.ldt"},
                        {"height", 1.1}, {"rotation", R},    {"scene", "s" + std::to_string(R)},
                        {"nmse", nmse},  {"mean_ref", mref}, {"mean_test", mtest}};
    return r;
}

TEST(Plots, StitchedTable)
{
    fs::path dir = fs::temp_directory_path() / ("lb_stitch_" + std::to_string(getpid()));
    fs::create_directories(dir);
    // cubature: MSE = NMSE mean_ref mean_test = 1*2*1 = 2 and 0.5*2*3 = 3;
    // stitched: mean MSE 2.5 / (mean ref 2 * mean test 2) = 0.625.
    // MCI at its time: MSE 8 and 8 -> 8 / (2 * 2) = 2, mean N (2 + 4) / 2 = 3.
    nlohmann::json recs = nlohmann::json::array();
    recs.push_back(rec("method", "cubature", 1.0, 1.0, 2.0, 1.0));
    recs.push_back(rec("method", "cubature", 2.0, 0.5, 2.0, 3.0));
    for (auto [R, n] : {std::pair{1.0, 2}, std::pair{2.0, 4}}) {
        auto r = rec("equal_time", "mc:n=" + std::to_string(n), R, 2.0, 2.0, 2.0);
        r["equal_time_label"] = "cubature";
        r["n"] = n;
        r["equal_time_ok"] = n == 2;
        recs.push_back(r);
    }
    std::ofstream(dir / "results.json") << nlohmann::json{{"records", recs}}.dump();
    int code = -1;
    std::string script = test::sourceDir() + "/plots/stitched_table.py";
    std::string out = test::shellOutput("python3 " + script + " " + (dir / "results.json").string() + " 2>&1", &code);
    EXPECT_EQ(code, 0) << out;
    EXPECT_NE(out.find("| L | 1.1 | 0.625 | 2 (3) |"), std::string::npos) << out;
    // cubature beats MCI (NMSE 1 < 2, 0.5 < 2) in both scenes; one pair missed
    EXPECT_NE(out.find("beats its equal-time MCI in 2 of 2 scenes"), std::string::npos) << out;
    EXPECT_NE(out.find("pairs outside the tolerance: 1 (50 % within, 50 % within or bracketed)"), std::string::npos)
        << out;
    // stitched: cubature 0.625 against MCI 2 in the one (luminaire, height) row
    EXPECT_NE(out.find("in 2 of 2 scenes and 1 of 1 stitched rows"), std::string::npos) << out;
    // A later file's record replaces the earlier one of the same scene, role
    // and spec: cubature re-run on scene 1 with NMSE 4 now loses there.
    nlohmann::json later = nlohmann::json::array({rec("method", "cubature", 1.0, 4.0, 2.0, 1.0)});
    std::ofstream(dir / "later.json") << nlohmann::json{{"records", later}}.dump();
    out = test::shellOutput("python3 " + script + " " + (dir / "results.json").string() + " " +
                                (dir / "later.json").string() + " 2>&1",
                            &code);
    EXPECT_EQ(code, 0) << out;
    EXPECT_NE(out.find("beats its equal-time MCI in 1 of 2 scenes"), std::string::npos) << out;
    std::ofstream(dir / "bad.json") << "{\"x\": 1}";
    test::shellOutput("python3 " + script + " " + (dir / "bad.json").string() + " 2>&1", &code);
    EXPECT_NE(code, 0);
    fs::remove_all(dir);
}

// The counts docs/studies/thesis-sct-vs-mci.md quotes come from the committed results.
TEST(Plots, StitchedTableReproducesTheCommittedRuns)
{
    std::string script = test::sourceDir() + "/plots/stitched_table.py";
    std::string res = test::sourceDir() + "/experiments/results/";
    struct Run {
        std::string file;  // files after the first are named with their directory
        const char *sct, *voronoi;
    };
    for (const Run& r : {// 8 seeds of MCI, verdicts with intervals
                         Run{"thesis-sct-seeds8-pocl-epyc.json.xz", "verdicts 92 wins, 45 ties, 3 losses",
                             "voronoi: beats its equal-time MCI in 116 of 140 scenes and 28 of 28 stitched rows; MCI "
                             "N 4..8 (median 4); pairs outside the tolerance: 0 (100 % within, 100 % within or "
                             "bracketed); verdicts 116 wins, 24 ties, 0 losses"},
                         Run{"thesis-sct-pocl-epyc.json.xz", "cubature: beats its equal-time MCI in 107 of 140",
                             "voronoi: beats its equal-time MCI in 131 of 140"},
                         Run{"thesis-sct-h100-512.json.xz", "cubature: beats its equal-time MCI in 54 of 140",
                             "voronoi: beats its equal-time MCI in 114 of 140"},
                         Run{"thesis-sct-all-pocl-xeon.json.xz",
                             "cubature:triangulation=delaunay,dynamic=cp+barycentre: beats its equal-time MCI in 80 "
                             "of 140 scenes and 13 of 28 stitched rows",
                             "voronoi: beats its equal-time MCI in 138 of 140 scenes and 28 of 28 stitched rows; MCI "
                             "N 2..7 (median 4); pairs outside the tolerance: 20 (86 % within, 100 % within or "
                             "bracketed)"},
                         // the fractional-N run of five variants, Delaunay over every dynamic point re-run on its own
                         Run{"thesis-sct-frac-pocl-xeon.json.xz " + res + "thesis-sct-delall-pocl-xeon.json.xz",
                             "cubature:triangulation=delaunay,dynamic=cp+np+mrp+barycentre: beats its equal-time MCI "
                             "in 84 of 140 scenes and 16 of 28 stitched rows; MCI N 10..27 (median 13)",
                             "voronoi: beats its equal-time MCI in 134 of 140 scenes and 28 of 28 stitched rows"}}) {
        int code = -1;
        std::string out = test::shellOutput("python3 " + script + " " + res + r.file + " 2>&1", &code);
        EXPECT_EQ(code, 0) << r.file << "\n" << out;
        EXPECT_NE(out.find(r.sct), std::string::npos) << r.file << "\n" << out;
        EXPECT_NE(out.find(r.voronoi), std::string::npos) << r.file << "\n" << out;
    }
}

// results.csv gives the same table as results.json (plots/results_io.py reads both).
TEST(Plots, StitchedTableReadsTheCsvAsTheJson)
{
    fs::path dir = fs::temp_directory_path() / ("lb_stitch_csv_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string xz = test::sourceDir() + "/experiments/results/thesis-sct-pocl-epyc.json.xz";
    const std::string jsonPath = (dir / "results.json").string();
    int code = -1;
    test::shellOutput("xz -dc '" + xz + "' > '" + jsonPath + "'", &code);
    if (code != 0) GTEST_SKIP() << "no xz to unpack " << xz;
    results::saveCsv(jsonPath, results::load(jsonPath));
    std::string script = test::sourceDir() + "/plots/stitched_table.py";
    std::string fromJson = test::shellOutput("python3 " + script + " " + jsonPath + " 2>&1", &code);
    EXPECT_EQ(code, 0) << fromJson;
    std::string fromCsv =
        test::shellOutput("python3 " + script + " " + (dir / "results.csv").string() + " 2>&1", &code);
    EXPECT_EQ(code, 0) << fromCsv;
    EXPECT_NE(fromJson.find("cubature: beats its equal-time MCI in 107 of 140"), std::string::npos) << fromJson;
    EXPECT_EQ(fromCsv, fromJson);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace lb
