// build/lumibench as outside tools call it (docs/design.md section 7).
#include "testutil.h"

#include <array>
#include <cstdio>
#include <memory>

namespace lb {
namespace {

struct Result {
    int code;
    std::string out;
};

// Runs build/lumibench with `args`, stdout and stderr together.
Result run(const std::string& args)
{
    auto c = test::runCli(args);
    return {c.code, c.out + c.err};
}

TEST(Cli, HelpListsEverySubcommand)
{
    auto r = run("--help");
    EXPECT_EQ(r.code, 0) << r.out;
    for (const char* c : {"devices", "luminaire", "render", "compare", "run", "merge", "tune", "stability", "bench"})
        EXPECT_NE(r.out.find(c), std::string::npos) << c << "\n" << r.out;
}

TEST(Cli, EverySubcommandHasHelp)
{
    for (const char* c :
         {"devices", "luminaire", "luminaire info", "luminaire eval", "render", "compare", "run", "merge", "report"}) {
        auto r = run(std::string(c) + " --help");
        EXPECT_EQ(r.code, 0) << c << "\n" << r.out;
        EXPECT_NE(r.out.find("Usage"), std::string::npos) << c << "\n" << r.out;
    }
}

// `run --help` names every experiment key and where each is documented.
TEST(Cli, RunHelpListsTheExperimentKeys)
{
    auto r = run("run --help");
    EXPECT_EQ(r.code, 0) << r.out;
    for (const char* k : {"luminaires", "heights", "equal_time_tolerance", "time_res", "seeds", "docs/experiments.md",
                          "512 x 512", "--seeds"})
        EXPECT_NE(r.out.find(k), std::string::npos) << k << "\n" << r.out;
}

TEST(Cli, UnknownSubcommandIsAnInputError)
{
    auto r = run("frobnicate");
    EXPECT_EQ(r.code, 2) << r.out;
}

TEST(Cli, DevicesListsThePoclDevice)
{
    LB_REQUIRE_RUNTIME(rt);
    auto r = run("devices");
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find(rt->info().name), std::string::npos) << r.out;
    auto j = run("devices --json");
    EXPECT_EQ(j.code, 0) << j.out;
    EXPECT_NE(j.out.find("\"default\": true"), std::string::npos) << j.out;
}

TEST(Cli, BadDeviceIndexIsAnInputError)
{
    LB_REQUIRE_RUNTIME(rt);
    auto r = run("devices --json");
    setenv("LUMIBENCH_DEVICE", "99", 1);
    auto b = run("devices");
    unsetenv("LUMIBENCH_DEVICE");
    EXPECT_EQ(b.code, 2) << b.out;
    EXPECT_NE(b.out.find("LUMIBENCH_DEVICE"), std::string::npos) << b.out;
}

}  // namespace
}  // namespace lb
