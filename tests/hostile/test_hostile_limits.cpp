// test_hostile_limits.cpp -- limits checked up front, each an exit 2 (or an
// lb::InputError) naming the key or file: presets that name presets, LTC
// tables that cannot be LTCs, file names that are not UTF-8 or too long for
// the names made from them, results files holding values no run writes,
// synthetic luminaires the readers would refuse, and parameters that have no
// effect where they are given.
#include "hostile.h"

#include "methods/spec.h"
#include "testutil.h"
#include "util/digest.h"
#include "util/json_file.h"

#include <gtest/gtest.h>

namespace lb {
namespace {

using namespace hostile;

const std::vector<std::string> kRender = {"render", "--height", "1", "--rotation", "pi", "--res", "4"};

std::vector<std::string> renderArgs(const std::string& lum, const std::string& method, const std::string& out)
{
    std::vector<std::string> a = kRender;
    a.insert(a.end(), {"--luminaire", lum, "--method", method, "--out", out});
    return a;
}

// ---- presets naming presets ----

TEST(HostileLimits, PresetsThatNamePresetsAreRefusedNamingTheChain)
{
    const fs::path d = tmpDir("presets");
    fs::copy_file(luminaire("batwing.ies"), d / "batwing.ies");
    writeText(d / "rec.json", R"({"batwing.ies": "cubature:preset=rec.json"})");
    writeText(d / "a.json", R"({"batwing.ies": "cubature:preset=b.json"})");
    writeText(d / "b.json", R"({"batwing.ies": "cubature:preset=a.json"})");
    writeText(d / "ok.json", R"({"batwing.ies": "cubature:triangulation=delaunay"})");
    for (const auto& [file, chain] : std::vector<std::pair<std::string, std::string>>{
             {"rec.json", "rec.json -> rec.json, a cycle"}, {"a.json", "a.json -> b.json"}}) {
        CliRun r = lumibench(d, renderArgs("batwing.ies", "cubature:preset=" + file, "o.exr"), 60);
        EXPECT_EQ(r.code, 2) << file << ": " << r.err;  // 139 before: the stack ran out
        EXPECT_NE(r.err.find(chain), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("a preset may not name another preset"), std::string::npos) << r.err;
    }
    json e = tinyExperiment(d, {"batwing.ies"});
    e["methods"] = {"cubature:preset=a.json"};
    writeText(d / "e.json", e.dump());
    CliRun r = lumibench(d, {"run", "e.json", "--out", "o", "--no-report"}, 60);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("a.json -> b.json"), std::string::npos) << r.err;
    // one level is what presets are for
    EXPECT_EQ(methods::parseSpec("cubature:preset=" + (d / "ok.json").string()).str("preset"),
              (d / "ok.json").string());
}

// ---- LTC tables ----

TEST(HostileLimits, LtcTablesWithoutInvertibleMatricesOrPositiveNormsAreRefused)
{
    const fs::path d = tmpDir("ltc");
    const json good =
        util::readJsonObject((fs::path(test::sourceDir()) / "data" / "ltc" / "ggx-8.json").string(), "t", 1 << 24);
    ASSERT_EQ(good["cells"].size(), 64u);
    // cell fields: m00 m02 m20 m22 norm ...
    const std::vector<std::pair<std::string, std::function<void(json&)>>> damage = {
        {"M^-1 [[0, 0], [0, 0]]", [](json& c) { c[0] = c[1] = c[2] = c[3] = 0.0; }},
        {"is not an invertible matrix",
         [](json& c) {
             for (int k = 0; k < 4; ++k) c[k] = -c[k].get<double>();
         }},
        {"norm 0 outside (0, 1]", [](json& c) { c[4] = 0.0; }},
        {"norm -0.5 outside (0, 1]", [](json& c) { c[4] = -0.5; }},
    };
    EXPECT_EQ(
        lumibench(d, {"ltc", "info", (fs::path(test::sourceDir()) / "data" / "ltc" / "ggx-8.json").string()}, 60).code,
        0);
    for (const auto& [msg, f] : damage) {
        json t = good;
        for (auto& c : t["cells"]) f(c);
        fs::create_directories(d / "data" / "ltc");
        writeText(d / "data" / "ltc" / "ggx.json", t.dump());
        CliRun r = lumibench(d, {"ltc", "info", "data/ltc/ggx.json"}, 60);
        EXPECT_EQ(r.code, 2) << msg << ": " << r.err;
        EXPECT_NE(r.err.find("data/ltc/ggx.json: cell 0: "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(msg), std::string::npos) << r.err;
        std::vector<std::string> args = renderArgs(lambert().string(), "ltc", "s.exr");
        args.insert(args.end(), {"--scene", "specular"});
        r = lumibench(d, args, 60, {"LUMIBENCH_DATA_DIR=" + (d / "data").string()});
        EXPECT_EQ(r.code, 2) << msg << ": " << r.err;  // rendered black, exit 0, before
        EXPECT_NE(r.err.find(msg), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(d / "s.exr"));
    }
}

// ---- names: not UTF-8, too long ----

TEST(HostileLimits, FileNamesThatAreNotUtf8AreRefusedNamingTheFile)
{
    const fs::path d = tmpDir("utf8");
    const std::string bad = "bad\xff\xfe.ldt";
    fs::create_directories(d / "lums");
    fs::copy_file(lambert(), d / "lums" / bad);
    fs::copy_file(lambert(), d / bad);
    writeText(d / "e.json", tinyExperiment(d / "lums", {"lambert.ldt"}).dump());
    const std::vector<std::vector<std::string>> cmds = {
        {"luminaire", "info", bad},
        {"render", "--luminaire", bad, "--method", "point", "--height", "1", "--rotation", "pi", "--res", "4", "--out",
         "o.exr", "--json"},
        {"run", "e.json", "--luminaires", "lums", "--out", "o", "--no-report"},
    };
    for (const auto& args : cmds) {
        CliRun r = lumibench(d, args, 60);
        EXPECT_EQ(r.code, 2) << what(args) << ": " << r.err;  // 1, "invalid UTF-8 byte", no name, before
        EXPECT_NE(r.err.find("bad\\xff\\xfe.ldt: "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("not valid UTF-8 (byte 0xff at offset"), std::string::npos) << r.err;
    }
    EXPECT_FALSE(fs::exists(d / "o.exr"));
}

TEST(HostileLimits, LongGeneratedNamesAreShortenedWithADigest)
{
    EXPECT_EQ(util::shortName("abc", 10), "abc");
    const std::string a(300, 'x'), b = std::string(299, 'x') + "y";
    EXPECT_EQ(util::shortName(a).size(), util::kMaxNameBytes);
    EXPECT_NE(util::shortName(a), util::shortName(b));  // they differ only at the end
    EXPECT_EQ(util::shortName(a).rfind(std::string(100, 'x'), 0), 0u);  // still readable
    // cut inside a two-byte character: the cut moves before it (185 - 17 = 168 lands on its second byte)
    const std::string u = std::string(167, 'x') + "\xc3\xa9" + std::string(30, 'x');
    EXPECT_EQ(util::shortName(u, 185).substr(166, 2), "x-");
    EXPECT_EQ(util::shortName(u, 185).size(), 184u);

    LB_REQUIRE_RUNTIME(rt);
    const fs::path d = tmpDir("long-names");
    const std::string stem(240, 'l');
    fs::copy_file(lambert(), d / (stem + ".ldt"));
    // a presets file at the end of a 400-byte path
    fs::path deep = d;
    for (int k = 0; k < 3; ++k) deep /= std::string(130, char('a' + k));
    fs::create_directories(deep);
    writeText(deep / "p.json", json{{stem + ".ldt", "cubature"}}.dump());
    const std::string preset = "cubature:preset=" + (deep / "p.json").string();
    ASSERT_GT(preset.size(), 400u);
    json e = tinyExperiment(d, {stem + ".ldt"});
    e["methods"] = {"point", preset};
    writeText(d / "e.json", e.dump());
    for (int pass = 0; pass < 2; ++pass) {
        CliRun r = lumibench(d, {"run", "e.json", "--out", "o", "--no-report"});
        ASSERT_EQ(r.code, 0) << r.err;  // 1, "File name too long", after computing, before
    }
    size_t files = 0;
    for (const auto& p : fs::recursive_directory_iterator(d / "o")) {
        EXPECT_LE(p.path().filename().string().size(), util::kMaxNameBytes + 16) << p.path();
        ++files;
    }
    EXPECT_GT(files, 10u);
}

// ---- results files ----

TEST(HostileLimits, ResultsValuesOutsideTheirRangesAreRefusedNamingTheKey)
{
    LB_REQUIRE_RUNTIME(rt);
    const fs::path d = tmpDir("results-ranges");
    fs::copy_file(lambert(), d / "lum.ldt");
    writeText(d / "e.json", tinyExperiment(d, {"lum.ldt"}).dump());
    ASSERT_EQ(lumibench(d, {"run", "e.json", "--out", "o", "--no-report"}).code, 0);
    const json good = util::readJsonObject((d / "o" / "results.json").string(), "t", 1 << 24);
    // (shape and size: written for a scene of another shape or size than the default 1 x 1 rectangle)
    const std::vector<std::pair<std::string, std::function<void(json&)>>> damage = {
        {"\"schema_version\" 4294967297", [](json& j) { j["schema_version"] = 4294967297LL; }},
        {"key \"seeds\": expected an integer in [1, 1000], found -3", [](json& j) { j["records"][0]["seeds"] = -3; }},
        {"key \"ci95\".nmse: expected [lo, hi] with lo <= hi, found [5, -5]",
         [](json& j) {
             j["records"][0]["seeds"] = 2;
             j["records"][0]["ci95"] = {{"nmse", {5, -5}}};
         }},
        {"key \"shape\"", [](json& j) { j["records"][0]["shape"] = "hexagon"; }},
        {"key \"size\": expected [W, L] in (0, 10000] m, found [-1,1]",
         [](json& j) {
             j["records"][0]["size"] = {-1, 1};
         }},
    };
    for (const auto& [msg, f] : damage) {
        json bad = good;
        bad["records"][0]["shape"] = "disk";
        bad["records"][0]["size"] = {0.5, 0.5};
        f(bad);
        fs::create_directories(d / "bad");
        writeText(d / "bad" / "results.json", bad.dump());
        CliRun r = lumibench(d, {"report", "bad", "--no-plots"}, 60);
        EXPECT_EQ(r.code, 2) << msg << ": " << r.err;
        EXPECT_NE(r.err.find("bad/results.json"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(msg), std::string::npos) << r.err;
    }
    json ok = good;  // the same with every value in range
    ok["records"][0]["shape"] = "disk";
    ok["records"][0]["size"] = {0.5, 0.5};
    writeText(d / "bad" / "results.json", ok.dump());
    CliRun r = lumibench(d, {"report", "bad", "--no-plots"}, 60);
    EXPECT_EQ(r.code, 0) << r.err;
}

// ---- luminaire synth ----

TEST(HostileLimits, GammaStepsTheReadersWouldRefuseAreRefusedBeforeWriting)
{
    const fs::path d = tmpDir("gamma-step");
    for (const char* step : {"0.001", "0.00001", "0.018"}) {
        CliRun r = lumibench(d, {"luminaire", "synth", "lambert", "--gamma-step", step, "--out", "s.ldt"}, 60);
        EXPECT_EQ(r.code, 2) << step << ": " << r.err;
        EXPECT_NE(r.err.find("expected a gamma step of at least 0.018"), std::string::npos) << r.err;
        EXPECT_TRUE(tree(d).empty()) << step << ": a file was left behind";
    }
    // the finest step the readers take: written, and read back
    ASSERT_EQ(lumibench(d, {"luminaire", "synth", "lambert", "--gamma-step", "0.02", "--out", "s.ldt"}, 60).code, 0);
    EXPECT_EQ(lumibench(d, {"luminaire", "info", "s.ldt"}, 60).code, 0);
}

// ---- parameters without effect ----

TEST(HostileLimits, McParametersWithoutEffectAreRefusedNamingWhatWouldMakeThemAct)
{
    const std::vector<std::pair<std::string, std::string>> inert = {
        {"mc:domain=area,cosine_warp=1",
         "cosine_warp=1 has no effect with domain=area; it acts only with domain=solid"},
        {"mc:domain=projected,cosine_warp=1", "it acts only with domain=solid"},
        {"mc:mis_split=0.3", "mis_split=0.3 has no effect with domain=area; it acts only with domain=mis"},
        {"mc:domain=solid,mis_split=0.3", "it acts only with domain=mis, mis_table or mis_table_solid"},
        {"mc:min_solid=0.01", "min_solid=0.01 has no effect with domain=area; it acts only with domain=solid or "},
        {"mc:domain=mis,min_solid=0", "it acts only with domain=solid or mis_table_solid"},
        {"mc:sequence=sobol,shift=1", "shift=1 has no effect with sequence=sobol; it acts only with sequence=shared"},
        {"mc:sequence=random,pattern=halton", "pattern=halton has no effect with sequence=random"},
        {"mc:domain=solid,sequence=zsobol,pattern=stratified", "it acts only with sequence=shared"},
        {"mc:atrous_sigma=2", "atrous_sigma=2 has no effect with denoise=none; it acts only with denoise=atrous"},
        {"mc:denoise=gauss16,atrous_sigma=2", "has no effect with denoise=gauss16"},
        {"mc:paper=1,mis_split=0.3", "mis_split=0.3 has no effect with domain=solid"},
    };
    for (const auto& [spec, msg] : inert) {
        const std::string err = test::inputErrorOf([&] { methods::parseSpec(spec); });
        EXPECT_NE(err.find(msg), std::string::npos) << spec << ": " << err;
    }
    // where they act, and at their defaults (a canonical SPEC writes every key), they stay
    for (const char* ok : {"mc:domain=solid,cosine_warp=1", "mc:domain=mis,mis_split=0.3",
                           "mc:domain=mis_table_solid,mis_split=0.3,min_solid=0.01", "mc:shift=1,pattern=halton",
                           "mc:denoise=atrous,atrous_sigma=2", "mc:paper=1", "mc:sequence=sobol,shift=0"}) {
        EXPECT_NO_THROW(methods::parseSpec(methods::parseSpec(ok).canonical())) << ok;
    }
    const fs::path d = tmpDir("inert");
    CliRun r = lumibench(d, renderArgs(lambert().string(), "mc:domain=area,cosine_warp=1", "o.exr"), 60);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("cosine_warp=1 has no effect"), std::string::npos) << r.err;
}

TEST(HostileLimits, ATuneFileNamingAParameterTwiceIsRefused)
{
    const fs::path d = tmpDir("tune-twice");
    fs::copy_file(lambert(), d / "lum.ldt");
    json t = {{"name", "twice"},
              {"method", "cubature"},
              {"params", {"plane_eps", "dyn_weight", "plane_eps"}},
              {"reference", "reference:tol=1e-3"},
              {"luminaire_dir", d.string()},
              {"res", 4},
              {"train", {{"luminaires", {"lum.ldt"}}, {"heights", {0.5}}, {"rotations", {"pi"}}}},
              {"maxeval", 2}};
    writeText(d / "t.json", t.dump());
    CliRun r = lumibench(d, {"tune", "t.json", "--out", "o"}, 60);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("'plane_eps' named twice"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(d / "o" / "tune.json"));
}

}  // namespace
}  // namespace lb
