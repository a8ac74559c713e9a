// plots/robust_table.py: docs/studies/robust.md's tables from results files, checked on
// hand-made records and on the committed run (no device needed).
#include "testutil.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace lb {
namespace {

namespace fs = std::filesystem;

nlohmann::json rec(const char* method, const char* lum, double nmse)
{
    return {{"role", "method"}, {"method", method}, {"params", nlohmann::json::object()},
            {"luminaire", lum}, {"height", 1.1},    {"rotation", 3.14159},
            {"nmse", nmse}};
}

// MC at the time of `robust`: the mean over 8 seeds and its 95 % interval.
nlohmann::json partner(const char* lum, double nmse, double lo, double hi)
{
    nlohmann::json r = rec("mc", lum, nmse);
    r["role"] = "equal_time";
    r["equal_time_to"] = "robust";
    r["seeds"] = 8;
    r["ci95"] = {{"nmse", {lo, hi}}};
    return r;
}

// A later file replaces the earlier files' records of the luminaires it holds.
TEST(Plots, RobustTableLaterFilesReplaceTheirLuminaires)
{
    fs::path dir = test::freshDir("robust-table");
    nlohmann::json first = {{"records",
                             {rec("point", "A", 1.0), rec("robust", "A", 0.5),  //
                              rec("point", "B", 1.0), rec("robust", "B", 2.0),
                              // A: robust's 0.5 inside MCI's interval, a tie; B: 2 below [2.5, 3.5], a win
                              partner("A", 0.6, 0.4, 0.8), partner("B", 3.0, 2.5, 3.5)}}};
    nlohmann::json later = {{"records", {rec("point", "B", 4.0), rec("robust", "B", 1.0)}}};
    std::ofstream(dir / "first.json") << first.dump();
    std::ofstream(dir / "later.json") << later.dump();
    const std::string script = "python3 " + test::sourceDir() + "/plots/robust_table.py ";
    int code = -1;
    // B loses in the first file alone: robust 1 of 2; geometric mean of 0.5 and 2 is 1
    std::string out = test::shellOutput(script + (dir / "first.json").string() + " 2>&1", &code);
    ASSERT_EQ(code, 0) << out;
    EXPECT_NE(out.find("| `robust` | 1 / 2 | 1 | 1 / 1 / 0 |"), std::string::npos) << out;
    EXPECT_NE(out.find("| A | 1 / 1; 0 / 1 / 0 |"), std::string::npos) << out;
    // with B rerun: 2 of 2; geometric mean of 0.5 and 0.25 is 0.354
    out = test::shellOutput(script + (dir / "first.json").string() + " " + (dir / "later.json").string() + " 2>&1",
                            &code);
    ASSERT_EQ(code, 0) << out;
    EXPECT_NE(out.find("| `robust` | 2 / 2 | 0.354 |"), std::string::npos) << out;
    out = test::shellOutput(script + (dir / "first.json").string() + " --base nosuch 2>&1", &code);
    EXPECT_NE(code, 0) << out;
    EXPECT_NE(out.find("no records of the base method 'nosuch'"), std::string::npos) << out;
    fs::remove_all(dir);
}

// The counts docs/studies/robust.md quotes come from the committed runs (the pencil's
// 256 x 256 rerun replacing its 32 x 32 rows): single draws of MC, so no tie.
TEST(Plots, RobustTableReproducesTheCommittedRuns)
{
    const std::string res = test::sourceDir() + "/experiments/results/";
    const std::string script = "python3 " + test::sourceDir() + "/plots/robust_table.py ";
    int code = -1;
    std::string out = test::shellOutput(
        script + res + "robust-pocl-xeon.json.xz " + res + "robust-pencil-pocl-xeon.json.xz 2>&1", &code);
    ASSERT_EQ(code, 0) << out;
    EXPECT_NE(out.find("| `robust` | 211 / 211 | 0.00104 | 0.0148 | 0.0527 | 210 / 0 / 1 |"), std::string::npos) << out;
    EXPECT_NE(out.find("| `cubature` | 119 / 211 |"), std::string::npos) << out;
    EXPECT_NE(out.find("| pencil.ldt | 7 / 11; 1 / 0 / 10 | 11 / 11; 10 / 0 / 1 |"), std::string::npos) << out;
    out = test::shellOutput(script + res + "robust-pocl-xeon.json.xz 2>&1", &code);
    ASSERT_EQ(code, 0) << out;
    EXPECT_NE(out.find("| `robust` | 208 / 209 |"), std::string::npos) << out;
    // the rerun with MC over 8 seeds: verdicts with ties
    out = test::shellOutput(
        script + res + "robust-seeds8-pocl-xeon.json.xz " + res + "robust-pencil-seeds8-pocl-xeon.json.xz 2>&1", &code);
    ASSERT_EQ(code, 0) << out;
    EXPECT_NE(out.find("| `robust` | 211 / 211 | 0.00104 | 0.0148 | 0.0527 | 192 / 19 / 0 |"), std::string::npos)
        << out;
    EXPECT_NE(out.find("| `cubature` | 119 / 211 | 1.09 | 0.439 | 0.913 | 131 / 65 / 15 |"), std::string::npos) << out;
    EXPECT_NE(out.find("| pencil.ldt | 7 / 11; 0 / 2 / 9 | 11 / 11; 10 / 1 / 0 |"), std::string::npos) << out;
}

}  // namespace
}  // namespace lb
