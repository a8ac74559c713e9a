// `lumibench luminaire info|eval` on every file of ../shared/luminaires and on
// bad input (docs/design.md section 7).
#include "testutil.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

namespace lb {
namespace {

struct Result {
    int code;
    std::string out;
};

Result run(const std::string& args, bool withStderr = true)
{
    auto c = test::runCli(args);
    return {c.code, withStderr ? c.out + c.err : c.out};
}

TEST(CliLuminaire, InfoAndEvalAnswerForEverySharedFile)
{
    LB_REQUIRE_SHARED(dir);
    size_t n = 0;
    for (auto& e : std::filesystem::recursive_directory_iterator(dir + "/luminaires")) {
        std::string ext = e.path().extension().string();
        if (ext != ".ies" && ext != ".LDT" && ext != ".ldt") continue;
        ++n;
        std::string f = "'" + e.path().string() + "'";
        auto info = run("luminaire info --json " + f, false);
        ASSERT_EQ(info.code, 0) << f << info.out;
        auto j = nlohmann::json::parse(info.out);
        for (const char* k :
             {"format", "flux_lm", "declared_flux_lm", "max_cd", "isym", "symmetry", "c_planes", "gammas"})
            EXPECT_TRUE(j.contains(k)) << k << " in " << f;
        auto ev = run("luminaire eval " + f + " 0 0 45 90 90 270", false);
        ASSERT_EQ(ev.code, 0) << f << ev.out;
        // Three lines, each a finite number >= 0.
        std::istringstream in(ev.out);
        double v;
        int lines = 0;
        while (in >> v) {
            EXPECT_GE(v, 0) << f;
            ++lines;
        }
        EXPECT_EQ(lines, 3) << f << ev.out;
    }
    EXPECT_EQ(n, 16u);
}

TEST(CliLuminaire, EvalReturnsTheTableValue)
{
    // luminaires/lambert.ldt: I0 cos(gamma), I0 = 1000 / pi = 318.309886 cd;
    // gamma 60 is a node, so the value is float(I0 / 2) printed to 9 digits.
    auto r = run("luminaire eval " + test::sourceDir() + "/luminaires/lambert.ldt 0 0 60 10 120 0", false);
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(r.out, "318.309875\n159.154938\n0\n");
}

TEST(CliLuminaire, MalformedFileIsExit2WithFileAndLine)
{
    auto p = std::filesystem::temp_directory_path() / "lumibench_bad.ldt";
    std::ofstream(p) << "company\n1\n7\n";
    auto r = run("luminaire info " + p.string());
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find(p.string() + ":3: expected the symmetry indicator Isym (an integer in [0, 4]), got \"7\""),
              std::string::npos)
        << r.out;
    r = run("luminaire eval " + p.string() + " 0 0");
    EXPECT_EQ(r.code, 2) << r.out;
    std::filesystem::remove(p);
    r = run("luminaire eval " + test::sourceDir() + "/luminaires/lambert.ldt 0");
    EXPECT_EQ(r.code, 2) << r.out;
}

}  // namespace
}  // namespace lb
