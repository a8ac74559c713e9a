// lumibench render as outside tools call it (docs/design.md section 7).
#include "cli/commands.h"
#include "metrics/image.h"
#include "testutil.h"
#include "util/error.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace lb {
namespace {

struct Result {
    int code;
    std::string out, err;
};

Result run(const std::string& args)
{
    auto c = test::runCli(args);
    return {c.code, c.out, c.err};
}

TEST(RenderCli, WritesExrAndJson)
{
    LB_REQUIRE_RUNTIME(rt);
    auto out = std::filesystem::temp_directory_path() / fmt::format("lb-render-cli-{}.exr", ::getpid());
    auto r = run("render --luminaire analytic:cos1 --method mc:n=16,pattern=halton --height 1.1 --rotation 3pi/4 "
                 "--res 16 --size 1x0.5 --extent 4 --json --reps 5 --out " +
                 out.string());
    ASSERT_EQ(r.code, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("method"), "mc");
    EXPECT_EQ(j.at("params").at("n"), 16);
    EXPECT_EQ(j.at("params").at("pattern"), "halton");
    EXPECT_EQ(j.at("precision"), "float");
    EXPECT_NEAR(j.at("scene").at("rotation").get<double>(), 3 * M_PI / 4, 1e-15);
    EXPECT_EQ(j.at("scene").at("length"), 0.5);
    EXPECT_EQ(j.at("time_ms").at("reps"), 5);
    EXPECT_GT(j.at("time_ms").at("median").get<double>(), 0.0);
    EXPECT_EQ(j.at("nonfinite"), 0);
    for (auto* k : {"device", "driver", "build_s", "luminaire", "stats"}) EXPECT_TRUE(j.contains(k)) << k;
    Image img = readExr(out.string());
    EXPECT_EQ(img.width, 16);
    EXPECT_EQ(img.height, 16);
    double sum = 0;
    for (double v : img.px) sum += v;
    EXPECT_GT(sum, 0.0);
    std::filesystem::remove(out);
}

TEST(RenderCli, BadInputExitsWithTwo)
{
    // No device needed: the arguments are checked first.
    const std::string base = "render --luminaire analytic:cos1 --height 1 --out /tmp/never.exr ";
    auto r = run(base + "--rotation pi --method mc:n=0");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("an integer in [1,"), std::string::npos) << r.err;
    r = run(base + "--rotation pi --method magic");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("valid methods: reference|"), std::string::npos) << r.err;
    r = run(base + "--rotation 3pie/4 --method point");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--rotation"), std::string::npos) << r.err;
    r = run(base + "--rotation pi --method point --precision half");
    EXPECT_EQ(r.code, 2);
    r = run(base + "--rotation pi --method point --size 1by1");
    EXPECT_EQ(r.code, 2);
    r = run("render --luminaire analytic:cosx --height 1 --rotation pi --method point --out /tmp/never.exr");
    EXPECT_EQ(r.code, 2);
}

TEST(RenderCli, ShapeAndSizeFromTheFile)
{
    LB_REQUIRE_RUNTIME(rt);
    LB_REQUIRE_SHARED(shared);
    const std::string lum = shared + "/luminaires/ieslibrary/007cfb11e343e2f42e3b476be4ab684e.ies";
    const auto dir = test::freshDir("render-shape");
    const std::string out = (dir / "d.exr").string();
    Result r = run("render --luminaire '" + lum +
                   "' --method cubature --height 0.1 --rotation pi --size file --res 5 "
                   "--reps 1 --json --out '" +
                   out + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["scene"]["shape"], "disk");  // an 80 mm circle
    EXPECT_EQ(j["scene"]["width"], 0.08);
    EXPECT_EQ(j["scene"]["res"], 5);  // --size file keeps the other flags
    r = run("render --luminaire '" + lum + "' --method point --height 1 --rotation pi --shape oval --out '" + out +
            "'");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--shape: expected rect or disk, got 'oval'"), std::string::npos) << r.err;
    r = run("render --luminaire '" + lum + "' --method voronoi --height 1 --rotation pi --size file --res 4 --out '" +
            out + "'");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("not shape=disk"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace lb
