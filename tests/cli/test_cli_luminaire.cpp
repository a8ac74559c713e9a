// `lumibench luminaire info|eval` on every file of ../shared/luminaires and on
// bad input (docs/design.md section 7).
#include "photometry/ldt.h"
#include "photometry/load.h"
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

TEST(CliLuminaire, InfoPrintsTheOpening)
{
    LB_REQUIRE_SHARED(dir);
    std::string f = "'" + dir + "/luminaires/ieslibrary/007cfb11e343e2f42e3b476be4ab684e.ies'";
    auto j = nlohmann::json::parse(run("luminaire info --json " + f, false).out);
    EXPECT_EQ(j["shape"], "circle");  // the file's width -0.080, length 0, height 0
    EXPECT_EQ(j["length_m"], 0.08);
    EXPECT_EQ(j["width_m"], 0.08);
    EXPECT_EQ(j["height_m"], 0.0);
    auto text = run("luminaire info '" + dir + "/luminaires/zumtobel/SLOTLIGHT_42184612.LDT'", false);
    ASSERT_EQ(text.code, 0) << text.out;
    EXPECT_NE(text.out.find("shape              \"rectangle\"\n"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("length_m           2.0\n"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("width_m            0.072\n"), std::string::npos) << text.out;
}

// Values: LDT stores cd/klm, read x flux / 1000 (2 roundings); the IES file
// stores the absolute cd as shortest round-trip text (exact); the second LDT
// stores cd x 1000 / flux' (2 roundings) with flux' the table's own integral
// (IES declares none), read back x flux' / 1000 (2 more). Six correctly
// rounded operations stay under 6 x 1.1e-16 relative: 1e-14 covers it.
void expectSameTable(const photometry::Table& a, const photometry::Table& b, const std::string& what)
{
    ASSERT_EQ(a.c, b.c) << what;
    ASSERT_EQ(a.gamma, b.gamma) << what;
    ASSERT_EQ(a.cd.size(), b.cd.size()) << what;
    for (size_t i = 0; i < a.cd.size(); ++i) ASSERT_NEAR(a.cd[i], b.cd[i], 1e-14 * a.cd[i]) << what << " @" << i;
    EXPECT_EQ(a.opening.shape, b.opening.shape) << what;
    // Millimetres in LDT, metres in IES: each a multiply or divide by 1000,
    // correctly rounded; 4 of them stay within 1e-15 relative.
    EXPECT_NEAR(a.opening.lengthM, b.opening.lengthM, 1e-15 * a.opening.lengthM) << what;
    EXPECT_NEAR(a.opening.widthM, b.opening.widthM, 1e-15 * a.opening.widthM) << what;
    EXPECT_NEAR(a.opening.heightM, b.opening.heightM, 1e-15 * a.opening.heightM) << what;
}

TEST(CliLuminaire, ConvertLdtToIesAndBackKeepsTableAndOpening)
{
    LB_REQUIRE_SHARED(dir);
    auto d = test::freshDir("convert");
    int n = 0;
    for (auto& e : std::filesystem::directory_iterator(dir + "/luminaires/zumtobel")) {
        std::string in = e.path().string(), ies = (d / "a.ies").string(), ldt = (d / "b.LDT").string();
        auto r = run("luminaire convert '" + in + "' " + ies);
        ASSERT_EQ(r.code, 0) << in << r.out;
        EXPECT_EQ(nlohmann::json::parse(run("luminaire info --json " + ies, false).out)["format"], "ies");
        r = run("luminaire convert " + ies + " " + ldt);
        ASSERT_EQ(r.code, 0) << in << r.out;
        expectSameTable(photometry::load(in), photometry::load(ldt), in);
        // Same format: a rewrite in place.
        ASSERT_EQ(run("luminaire convert " + ldt + " " + ldt).code, 0) << in;
        expectSameTable(photometry::load(in), photometry::load(ldt), in + " rewritten");
        ++n;
    }
    EXPECT_EQ(n, 7);
    std::filesystem::remove_all(d);
}

TEST(CliLuminaire, ConvertRefusesBadInputWithExit2)
{
    auto d = test::freshDir("convert-bad");
    std::string lambert = test::sourceDir() + "/luminaires/lambert.ldt";
    auto r = run("luminaire convert " + lambert + " " + (d / "x.txt").string());
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("expected an output file FILE.ldt or FILE.ies"), std::string::npos) << r.out;
    r = run("luminaire convert " + (d / "missing.ldt").string() + " " + (d / "y.ies").string());
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("missing.ldt"), std::string::npos) << r.out;
    r = run("luminaire convert " + lambert + " " + d.string() + "/");  // a directory, not a file path
    EXPECT_EQ(r.code, 2) << r.out;
    // An elliptical opening has no EULUMDAT field: refused, nothing written.
    std::ofstream(d / "ellipse.ies") << "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 3 1 1 2 -0.1 -0.3 0\n1 1 10\n0 45 90\n0\n"
                                        "3 2 1\n";
    r = run("luminaire convert " + (d / "ellipse.ies").string() + " " + (d / "e.ldt").string());
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("ellipse"), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(d / "e.ldt"));
    r = run("luminaire convert --help", false);
    EXPECT_EQ(r.code, 0);
    EXPECT_NE(r.out.find("luminous opening"), std::string::npos) << r.out;
    std::filesystem::remove_all(d);
}

}  // namespace
}  // namespace lb
