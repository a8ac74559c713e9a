// Every numeric flag is range-checked before any work, with a message that
// names the flag (exit code 2): nan, inf, negatives, zero counts, absurd
// sizes, odd angle forms. Each case was accepted or misreported before.
#include "util/check.h"
#include "util/error.h"

#include "../testutil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace lb {
namespace {

struct Case {
    std::string args;  // after build/lumibench
    std::string expect;  // a part of the error message
};

void expectRejected(const std::vector<Case>& cases)
{
    for (const auto& c : cases) {
        auto r = test::runCli(c.args);
        EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.expect), std::string::npos)
            << c.args << "\nexpected: " << c.expect << "\ngot: " << r.err;
    }
}

const std::string kRender = "render --luminaire analytic:cos1 --method point --rotation pi --out /nonexistent/x.exr ";

TEST(Flags, RenderAndBenchSceneFlags)
{
    expectRejected({
        {kRender + "--height nan", "--height: expected a number in [0, 10000] m, got nan"},
        {kRender + "--height inf", "--height: expected a number in [0, 10000] m, got inf"},
        {kRender + "--height -5", "--height: expected a number in [0, 10000] m, got -5"},
        {kRender + "--height 1e30", "--height: expected a number in [0, 10000] m, got 1e+30"},
        {kRender + "--height 1 --extent 1e9", "--extent: expected a number in [0, 10000] m, got 1000000000"},
        {kRender + "--height 1 --size 1xnan", "--size L: expected a finite number, got 'nan'"},
        {kRender + "--height 1 --res 0", "--res: expected an integer in [1, 16384], got 0"},
        {kRender + "--height 1 --precision half", "--precision: expected float or double, got 'half'"},
        {kRender + "--height 1 --reps 0", "--reps: expected an integer in [1, 1000], got 0"},
        {kRender + "--height 1 --reps 1000000000", "--reps: expected an integer in [1, 1000], got 1000000000"},
        {kRender + "--height 1 --device -1", "--device: expected an integer in [0, 4095], got -1"},
        {"render --luminaire analytic:cos1 --method point --height 1 --rotation 7 --out x.exr",
         "--rotation: expected radians in [0, 2pi], got '7'"},
        {"render --luminaire analytic:cos1 --method point --height 1 --rotation pi/-2 --out x.exr",
         "--rotation: expected radians in [0, 2pi] as a number or C*pi/D"},
        {"render --luminaire analytic:cos1 --method= --height 1 --rotation pi --out x.exr",
         "--method: expected a value after '=', got an empty value"},
        {"bench --height nan", "--height: expected a number in [0, 10000] m, got nan"},
        {"bench --height inf", "--height: expected a number in [0, 10000] m, got inf"},
        {"bench --height -5", "--height: expected a number in [0, 10000] m, got -5"},
        {"bench --height 1e30", "--height: expected a number in [0, 10000] m, got 1e+30"},
        {"bench --reps 1000000000", "--reps: expected an integer in [1, 1000]"},
        {"bench --samples 0", "--samples: expected an integer in [1, 1048576], got 0"},
    });
}

// The scene-kind flags: a value of the wrong range, or a flag of another kind.
TEST(Flags, SceneKindFlags)
{
    const std::string r = kRender + "--height 1 ";
    expectRejected({
        {r + "--scene glossy", "--scene: expected diffuse, specular or indirect, got 'glossy'"},
        {r + "--alpha 0.1", "--alpha: only the specular scene has it (--scene specular)"},
        {r + "--eye 0,4,2", "--eye: only the specular scene has it"},
        {r + "--scene specular --albedo 0.2", "--albedo: only the indirect scene has it"},
        {r + "--scene specular --alpha 0", "--alpha: expected a number in [0.01, 1], got 0"},
        {r + "--scene specular --alpha nan", "--alpha: expected a number in [0.01, 1], got nan"},
        {r + "--scene specular --eye 0,4", "--eye: expected X,Y,Z in metres, got '0,4'"},
        {r + "--scene specular --eye 0,4,-1", "--eye: the eye must be above the floor (Z > 0)"},
        {r + "--scene specular --eye 0,x,1", "--eye: expected a finite number, got 'x'"},
        {r + "--scene indirect --albedo 2", "--albedo: expected a number in [0, 1], got 2"},
    });
}

TEST(Flags, RunTuneCompareFlags)
{
    const std::string smoke = test::sourceDir() + "/experiments/smoke.json";
    const std::string tune = test::sourceDir() + "/experiments/tune-smoke.json";
    const std::string exr = test::sourceDir() + "/nonexistent.exr";
    expectRejected({
        {"run " + smoke + " --out /nonexistent/o --res 0", "--res: expected an integer in [1, 16384], got 0"},
        {"run " + smoke + " --out /nonexistent/o --reps 0", "--reps: expected an integer in [5, 1000], got 0"},
        {"run " + smoke + " --out /nonexistent/o --reps 2", "--reps: expected an integer in [5, 1000], got 2"},
        {"run " + smoke + " --out /nonexistent/o --reps 1000000000", "--reps: expected an integer in [5, 1000]"},
        {"run " + smoke + " --out /nonexistent/o --time-res -1",
         "--time-res: expected an integer in [0, 16384], got -1"},
        {"run " + smoke + " --out /nonexistent/o --seeds 0", "--seeds: expected an integer in [1, 1000], got 0"},
        {"run " + smoke + " --out /nonexistent/o --device -1", "--device: expected an integer in [0, 4095], got -1"},
        {"run " + smoke + " --out /nonexistent/o --shard 5/4", "--shard: expected 1 <= K <= N, got '5/4'"},
        {"run " + smoke + " --out /nonexistent/o --luminaires " + test::sourceDir() + "/experiments",
         "--luminaires: no .ldt or .ies file in"},
        {"tune " + tune + " --out /nonexistent/o --maxeval 0", "--maxeval: expected an integer in [1, 1000000], got 0"},
        {"tune " + tune + " --out /nonexistent/o --maxeval -1",
         "--maxeval: expected an integer in [1, 1000000], got -1"},
        {"tune " + tune + " --out /nonexistent/o --maxtime -1",
         "--maxtime: expected a number in [0, 10000000] s, got -1"},
        {"tune " + tune + " --out /nonexistent/o --maxtime nan",
         "--maxtime: expected a number in [0, 10000000] s, got nan"},
        {"compare " + exr + " " + exr + " --k nan", "--k: expected a number in [1e-300, 1e+300], got nan"},
        {"compare " + exr + " " + exr + " --bound nan", "--bound: expected a number in [1e-300, 1e+300] lux, got nan"},
        {"compare " + exr + " " + exr + " --k 0", "--k: expected a number in [1e-300, 1e+300], got 0"},
    });
}

// A directory where a file is expected says so (before: "basic_filebuf::underflow").
TEST(Flags, DirectoriesWhereFilesAreExpected)
{
    const std::string dir = test::sourceDir() + "/experiments";
    expectRejected({
        {"run " + dir + " --out /nonexistent/o", dir + ": expected an experiment file (JSON), got a directory"},
        {"merge --out /nonexistent/o " + dir + "/smoke.json/", "smoke.json/: "},
        {"luminaire info " + test::sourceDir() + "/luminaires",
         "luminaires: expected a luminaire file, got a directory"},
        {"tune " + dir + " --out /nonexistent/o", dir + ": expected a tune experiment file (JSON), got a directory"},
    });
    auto r = test::runCli("merge --out /nonexistent/o " + dir);  // a directory without results.json
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find(dir + "/results.json: cannot open a results file (JSON)"), std::string::npos) << r.err;
}

TEST(Flags, AngleForms)
{
    EXPECT_DOUBLE_EQ(util::parseAngle("r", "3.14159265358979323846"), M_PI);
    EXPECT_DOUBLE_EQ(util::parseAngle("r", "pi"), M_PI);
    EXPECT_DOUBLE_EQ(util::parseAngle("r", "3pi/4"), 3 * M_PI / 4);
    EXPECT_DOUBLE_EQ(util::parseAngle("r", "3*pi/4"), 3 * M_PI / 4);
    EXPECT_DOUBLE_EQ(util::parseAngle("r", "pi/2"), M_PI / 2);
    EXPECT_DOUBLE_EQ(util::parseAngle("r", "0.75pi"), 0.75 * M_PI);
    EXPECT_DOUBLE_EQ(util::parseAngle("r", "2pi"), 2 * M_PI);
    EXPECT_DOUBLE_EQ(util::parseAngle("r", "0"), 0);
    for (auto* bad : {"", "pie", "3pi/", "pi/0", "x", "pi2", "1/2/3", "pi/-2", "-pi", "-1", "7", "3pi", "nan", "inf",
                      "1e400", "+-1pi", "pi/2/2", "pi*2"})
        EXPECT_THROW(util::parseAngle("r", bad), InputError) << bad;
}

TEST(Flags, RangeCheckNamesTheFlag)
{
    EXPECT_EQ(util::checkRange("--x", 3, 1, 5), 3);
    EXPECT_DOUBLE_EQ(util::checkRange("--y", 2.5, 0.0, 3.0), 2.5);
    try {
        util::checkRange("--y", NAN, 0.0, 3.0, "m");
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "--y: expected a number in [0, 3] m, got nan");
        EXPECT_EQ(e.code, 2);
    }
}

}  // namespace
}  // namespace lb
