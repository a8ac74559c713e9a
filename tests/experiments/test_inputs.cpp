// Results are keyed by what determines them: resume recomputes cells whose
// inputs changed (luminaire file content, scene, reference, kernel sources)
// and says so; a scene keeps one equal-time partner per method; merge
// refuses to overwrite results; the reference cache checks what it serves;
// experiment keys are range-checked.
#include "experiments/experiment.h"
#include "experiments/results.h"
#include "experiments/runner.h"
#include "methods/analytic.h"
#include "methods/render.h"
#include "metrics/image.h"
#include "util/error.h"

#include "../testutil.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace lb {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path tmpDir(const std::string& name) { return test::freshDir("inputs-" + name); }

std::string writeJson(const fs::path& p, const json& j)
{
    std::ofstream(p) << j.dump(1);
    return p.string();
}

using test::inputErrorOf;

// Sets an environment variable for one scope.
struct ScopedEnv {
    std::string name, old;
    bool had;
    ScopedEnv(const std::string& n, const std::string& v) : name(n)
    {
        const char* o = std::getenv(n.c_str());
        had = o != nullptr;
        if (had) old = o;
        ::setenv(n.c_str(), v.c_str(), 1);
    }
    ~ScopedEnv()
    {
        if (had)
            ::setenv(name.c_str(), old.c_str(), 1);
        else
            ::unsetenv(name.c_str());
    }
};

json tiny(const fs::path& lumDir)
{
    return {{"name", "tiny"},
            {"luminaire_dir", lumDir.string()},
            {"luminaires", {"lum.ldt"}},
            {"heights", {1.0}},
            {"rotations", {"pi"}},
            {"methods", {"point", "mc:n=4"}},
            {"equal_time", {"point"}},
            {"mci_curve", {1, 2}},
            {"reference", "reference:tol=1e-3"},
            {"res", 8},
            {"time_res", 8},
            {"reps", 5}};
}

TEST(ExperimentKeys, AreRangeChecked)
{
    fs::path d = tmpDir("keys");
    fs::copy_file(fs::path(test::sourceDir()) / "luminaires" / "lambert.ldt", d / "lum.ldt");
    auto err = [&](const std::string& key, const json& v) {
        json j = tiny(d);
        j[key] = v;
        return inputErrorOf([&] { experiments::loadExperiment(writeJson(d / "e.json", j)); });
    };
    const std::string f = (d / "e.json").string();
    EXPECT_EQ(err("reps", 2), f + ": key \"reps\": expected an integer in [5, 1000], got 2");
    EXPECT_EQ(err("reps", 1000000000), f + ": key \"reps\": expected an integer in [5, 1000], got 1000000000");
    EXPECT_EQ(err("methods", "point"),
              f + ": key \"methods\": expected a list of strings like [\"a\", \"b\"], found \"point\"");
    EXPECT_EQ(err("equal_time", "point"),
              f + ": key \"equal_time\": expected a list of strings like [\"a\", \"b\"], found \"point\"");
    EXPECT_EQ(err("precision", "float"),
              f + ": key \"precision\": expected a list of strings like [\"a\", \"b\"], found \"float\"");
    EXPECT_EQ(err("heights", json::array({1e30})),
              f + ": key \"heights\": expected a number in [0, 10000] m, got 1e+30");
    EXPECT_EQ(err("extent", 1e9), f + ": key \"extent\": expected a number in [1e-06, 10000], got 1000000000");
    const std::string rot = f + ": key \"rotations\": expected radians in [0, 2pi] as a number or C*pi/D";
    EXPECT_EQ(err("rotations", json::array({"pi/-2"})).substr(0, rot.size()), rot);
    EXPECT_EQ(err("luminaires", "*"), "(no error)");  // the one bare string documented
    // An override is named by the key it replaces, or as its caller names it
    // (the CLI: by its flag, tests/cli/test_flags.cpp).
    experiments::Overrides ov;
    ov.reps = 0;
    EXPECT_EQ(inputErrorOf([&] { experiments::loadExperiment(writeJson(d / "e.json", tiny(d)), ov); }),
              "override of key \"reps\": expected an integer in [5, 1000], got 0");
    ov = {};
    ov.timeRes = -1;
    EXPECT_EQ(inputErrorOf([&] { experiments::loadExperiment(writeJson(d / "e.json", tiny(d)), ov); }),
              "override of key \"time_res\": expected an integer in [0, 16384], got -1");
    ov = {};
    ov.luminaireDir = d.string() + "/none";
    EXPECT_EQ(inputErrorOf([&] {
                  experiments::loadExperiment(writeJson(d / "e.json", tiny(d)), ov);
              }).rfind("override of key \"luminaires\": ", 0),
              0u);
    ov = {};
    ov.res = 0;
    ov.name = [](const std::string& key) { return "setting " + key; };
    EXPECT_EQ(inputErrorOf([&] { experiments::loadExperiment(writeJson(d / "e.json", tiny(d)), ov); }),
              "setting res: expected an integer in [1, 16384], got 0");
}

// Before: a rerun after changing the luminaire's content (same name), the
// extent or the reference tolerance kept the old records ("0 computed").
// The scene-kind keys: a key of another kind is refused, alpha lists multiply
// the scenes, and records of a specular scene carry its values in their key.
TEST(ExperimentKeys, SceneKinds)
{
    fs::path d = tmpDir("kinds");
    fs::copy_file(fs::path(test::sourceDir()) / "luminaires" / "lambert.ldt", d / "lum.ldt");
    const std::string f = (d / "e.json").string();
    auto err = [&](const json& patch) {
        json j = tiny(d);
        j.update(patch);
        return inputErrorOf([&] { experiments::loadExperiment(writeJson(d / "e.json", j)); });
    };
    EXPECT_EQ(err({{"alpha", 0.1}}), f + ": key \"alpha\": only the specular scene has it (\"scene\": \"specular\")");
    EXPECT_EQ(err({{"albedo", 0.1}}), f + ": key \"albedo\": only the indirect scene has it (\"scene\": \"indirect\")");
    EXPECT_EQ(err({{"scene", "glossy"}}),
              f + ": key \"scene\": scene: expected diffuse, specular or indirect, got 'glossy'");
    EXPECT_EQ(err({{"scene", "specular"}, {"alpha", {0.1, 0.001}}}),
              f + ": key \"alpha\": expected a number in [0.01, 1], got 0.001");
    EXPECT_EQ(err({{"scene", "specular"}, {"eye", {0, 4}}}),
              f + ": key \"eye\": expected [x, y, z] in metres, found [0,4]");
    EXPECT_EQ(err({{"scene", "indirect"}, {"albedo", -0.5}}),
              f + ": key \"albedo\": expected a number in [0, 1], got -0.5");

    // The diffuse methods do not render the specular scene: named as such.
    const std::string spec = err({{"scene", "specular"}});
    EXPECT_NE(spec.find("does not render the specular scene"), std::string::npos) << spec;

    // Alphas enumerate like heights; labels and scenes carry them.
    json j = tiny(d);
    j["heights"] = {1.0, 2.0};
    auto e = experiments::loadExperiment(writeJson(d / "e.json", j));
    auto ss = experiments::scenes(e);
    ASSERT_EQ(ss.size(), 2u);
    EXPECT_EQ(ss[0].scene().kind, SceneKind::Diffuse);
    EXPECT_EQ(ss[0].label().find("_a"), std::string::npos);
    e.sceneKeys.kind = SceneKind::Specular;
    e.sceneKeys.alphas = {0.1, 0.5};
    ss = experiments::scenes(e);
    ASSERT_EQ(ss.size(), 4u);
    EXPECT_EQ(ss[1].scene().alpha, 0.5);
    EXPECT_EQ(ss[1].scene().kind, SceneKind::Specular);
    EXPECT_EQ(ss[2].height, 2.0);
    EXPECT_NE(ss[1].label().find("_a0.5_"), std::string::npos) << ss[1].label();

    // Record keys: the diffuse key is unchanged; specular values are part of it
    // and survive a save / load.
    results::Record a;
    a.method = "point";
    const std::string diffuseKey = a.key();
    EXPECT_EQ(a.key().find("scene_kind"), std::string::npos);
    a.sceneKeys = SceneKindKeys::recordKeys(ss[0].scene());
    results::Record b = a;
    b.sceneKeys = SceneKindKeys::recordKeys(ss[1].scene());
    EXPECT_NE(a.key(), diffuseKey);
    EXPECT_NE(a.key(), b.key());
    json ja = a;
    EXPECT_EQ(ja["scene_kind"], "specular");
    EXPECT_EQ(ja["alpha"], 0.1);
    results::Record back = ja.get<results::Record>();
    EXPECT_EQ(back.key(), a.key());
    EXPECT_FALSE(back.extra.contains("alpha"));
}

TEST(Resume, RecomputesWhatChangedAndSaysSo)
{
    LB_REQUIRE_RUNTIME(rt);
    fs::path d = tmpDir("resume");
    ScopedEnv cache("LUMIBENCH_CACHE", (d / "cache").string());
    const fs::path lum = d / "lum.ldt";
    fs::copy_file(fs::path(test::sourceDir()) / "luminaires" / "lambert.ldt", lum);
    experiments::RunOptions ro;
    ro.outDir = (d / "out").string();
    ro.progress = false;
    auto runWith = [&](const json& j) {
        return experiments::run(experiments::loadExperiment(writeJson(d / "e.json", j)), ro);
    };
    const size_t cells = 5;  // point, mc:n=4, the curve's N = 1 and 2, point's equal-time partner

    auto s = runWith(tiny(d));
    EXPECT_EQ(s.computed, cells);
    const auto first = results::load(ro.outDir + "/results.json").records;
    ASSERT_EQ(first.size(), cells);
    for (const auto& r : first) {
        EXPECT_TRUE(r.inputs.contains("luminaire_digest")) << r.method;
        EXPECT_TRUE(r.inputs.contains("kernel")) << r.method;
        EXPECT_TRUE(r.inputs.contains("reference_kernel")) << r.method;
    }

    s = runWith(tiny(d));  // nothing changed
    EXPECT_EQ(s.computed, 0u);
    EXPECT_EQ(s.skipped, cells);

    // A killed run's temporary is cleaned by the next run.
    pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ::waitpid(child, nullptr, 0);
    std::ofstream(d / "out" / ("results.json.tmp." + std::to_string(child))) << "{";

    fs::copy_file(fs::path(test::sourceDir()) / "luminaires" / "spot.ldt", lum, fs::copy_options::overwrite_existing);
    s = runWith(tiny(d));
    EXPECT_EQ(s.computed, cells);
    EXPECT_EQ(s.stale, cells);
    EXPECT_FALSE(fs::exists(d / "out" / ("results.json.tmp." + std::to_string(child))));
    auto now = results::load(ro.outDir + "/results.json").records;
    ASSERT_EQ(now.size(), cells);  // replaced, not added
    EXPECT_NE(now[0].inputs["luminaire_digest"], first[0].inputs["luminaire_digest"]);
    EXPECT_NE(now[0].error.nmse, first[0].error.nmse);

    json j = tiny(d);
    j["extent"] = 4;
    EXPECT_EQ(runWith(j).stale, cells);
    j["reference"] = "reference:tol=2e-3";
    EXPECT_EQ(runWith(j).stale, cells);
    // A light of another size is another cell, not a stale one: records of any
    // light but the 1 x 1 rectangle carry shape and size in their key
    // (SceneKindKeys::recordKeys), so one file can hold both.
    j["size"] = {1, 0.5};
    s = runWith(j);
    EXPECT_EQ(s.computed, cells);
    EXPECT_EQ(s.stale, 0u);
    EXPECT_EQ(runWith(j).computed, 0u);

    // Records of an older file (no inputs) are recomputed, with the reason in the progress line.
    auto doc = results::load(ro.outDir + "/results.json");
    for (auto& r : doc.records) r.inputs = json::object();
    results::save(ro.outDir + "/results.json", doc);
    ro.progress = true;
    testing::internal::CaptureStderr();
    s = runWith(j);
    std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(s.stale, cells);
    EXPECT_NE(err.find("recomputed 5 cells whose inputs changed (no input digests (an older file))"), std::string::npos)
        << err;
    testing::internal::CaptureStderr();
    j["extent"] = 5;
    runWith(j);
    err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("recomputed 5 cells whose inputs changed (extent)"), std::string::npos) << err;
}

// A presets file is an input of the cells that use it: an edited entry for
// the cell's luminaire recomputes them (and only them); an entry for another
// luminaire does not.
TEST(Resume, RecomputesTheCellsWhosePresetChanged)
{
    LB_REQUIRE_RUNTIME(rt);
    fs::path d = tmpDir("resume_preset");
    ScopedEnv cache("LUMIBENCH_CACHE", (d / "cache").string());
    fs::copy_file(fs::path(test::sourceDir()) / "luminaires" / "lambert.ldt", d / "lum.ldt");
    const fs::path presets = d / "presets.json";
    auto writePresets = [&](const json& p) { std::ofstream(presets) << p.dump(); };
    writePresets({{"lum.ldt", "cubature:plane_eps=0.01"}});
    experiments::RunOptions ro;
    ro.outDir = (d / "out").string();
    ro.progress = false;
    json j = tiny(d);
    const std::string spec = "cubature:preset=" + presets.string();
    j["methods"] = {"point", spec};
    j["equal_time"] = {spec};
    auto runWith = [&] { return experiments::run(experiments::loadExperiment(writeJson(d / "e.json", j)), ro); };
    // point, the cubature, the curve's N = 1 and 2, the cubature's equal-time partner
    const size_t cells = 5, presetCells = 2;

    auto s = runWith();
    EXPECT_EQ(s.computed, cells);
    auto first = results::load(ro.outDir + "/results.json").records;
    size_t withPreset = 0;
    for (const auto& r : first)
        if (r.inputs.contains("preset_spec")) {
            ++withPreset;
            EXPECT_NE(r.inputs["preset_spec"].get<std::string>().find("plane_eps=0.01"), std::string::npos)
                << r.inputs.dump();
        }
    EXPECT_EQ(withPreset, presetCells);

    EXPECT_EQ(runWith().computed, 0u);  // nothing changed
    writePresets({{"lum.ldt", "cubature:plane_eps=0.01"}, {"other.ldt", "cubature:plane_eps=0.2"}});
    EXPECT_EQ(runWith().computed, 0u);  // another luminaire's entry is not this cell's input
    writePresets({{"lum.ldt", "cubature:plane_eps=0.02"}});
    s = runWith();
    EXPECT_EQ(s.stale, presetCells);
    EXPECT_EQ(s.computed, presetCells);
    EXPECT_EQ(s.skipped, cells - presetCells);
    EXPECT_EQ(runWith().computed, 0u);
}

// Before: two runs into one directory, or merged overlapping inputs, left two
// equal-time partners for one method and scene (with different N).
TEST(ResultsPartners, OneEqualTimePartnerPerSceneAndMethod)
{
    fs::path d = tmpDir("partners");
    auto partner = [](long n) {
        results::Record r;
        r.method = "mc";
        r.params = {{"n", n}};
        r.luminaire = "lambert.ldt";
        r.height = 1;
        r.rotation = 3;
        r.res = 8;
        r.device = "dev";
        r.equal_time_to = "point";
        r.n = n;
        return r;
    };
    results::Record other = partner(3);
    other.equal_time_to = "cp";
    std::vector<results::Record> v = {partner(3), other, partner(5)};
    EXPECT_EQ(results::dedupe(v), 1u);
    ASSERT_EQ(v.size(), 2u);
    EXPECT_EQ(*v[0].n, 5);  // the later record, at the first one's place

    results::save((d / "a.json").string(), {json::object(), {partner(3)}});
    results::save((d / "b.json").string(), {json::object(), {partner(4)}});
    results::MergeStats st;
    auto m = results::mergeResults({(d / "a.json").string(), (d / "b.json").string()}, &st);
    ASSERT_EQ(m.records.size(), 1u);
    EXPECT_EQ(*m.records[0].n, 4);
    EXPECT_EQ(st.replaced, 1u);

    // appendRecord (a second run into the same directory) replaces the partner.
    results::appendRecord((d / "a.json").string(), json::object(), partner(6));
    auto a = results::load((d / "a.json").string()).records;
    ASSERT_EQ(a.size(), 1u);
    EXPECT_EQ(*a[0].n, 6);
}

// Before: merge --out DIR silently replaced the results already in DIR.
TEST(MergeCli, RefusesANonEmptyOutputUnlessForced)
{
    fs::path d = tmpDir("merge");
    fs::create_directories(d / "out" / "shard-1");
    results::Record r;
    r.method = "point";
    r.luminaire = "l.ldt";
    r.device = "dev";
    results::save((d / "out" / "shard-1" / "results.json").string(), {json::object(), {r}});
    // The inputs themselves inside --out are fine (experiments/run-parallel.sh).
    auto c = test::runCli("merge --no-report --out " + (d / "out").string() + " " + (d / "out" / "shard-1").string());
    EXPECT_EQ(c.code, 0) << c.err;
    // Now --out holds results.json and results.csv: refused (naming one of
    // them), and the file is untouched.
    const auto before = fs::last_write_time(d / "out" / "results.json");
    c = test::runCli("merge --no-report --out " + (d / "out").string() + " " + (d / "out" / "shard-1").string());
    EXPECT_EQ(c.code, 2);
    EXPECT_NE(
        c.err.find("--out " + (d / "out").string() + ": expected an empty or new directory, got one holding results."),
        std::string::npos)
        << c.err;
    EXPECT_EQ(fs::last_write_time(d / "out" / "results.json"), before);
    c = test::runCli("merge --force --no-report --out " + (d / "out").string() + " " +
                     (d / "out" / "shard-1").string());
    EXPECT_EQ(c.code, 0) << c.err;
    c = test::runCli("merge --help");
    EXPECT_NE(c.out.find("keeps one partner per scene"), std::string::npos) << c.out;
}

// Before: a valid EXR of another image or size put in the cache was served
// as the reference (NMSE 48.7 where the truth is 0.0086), or failed without
// naming the cache.
TEST(ReferenceCache, ChecksDigestAndSizeOfWhatItServes)
{
    LB_REQUIRE_RUNTIME(rt);
    fs::path d = tmpDir("cache");
    photometry::Table table = methods::loadLuminaire("lambert");
    Scene scene;
    scene.height = 1;
    scene.res = 8;
    auto spec = methods::parseSpec("reference:tol=1e-3");
    methods::RenderOptions opt;
    opt.cacheDir = (d / "cache").string();
    opt.reps = 1;
    auto truth = methods::render(*rt, table, scene, spec, methods::Precision::Float, opt);
    ASSERT_FALSE(truth.cached);
    const std::string base =
        (d / "cache" / ("reference-" + methods::cacheKey(table, scene, spec, methods::Precision::Float))).string();
    json meta = json::parse(std::ifstream(base + ".json"));
    EXPECT_EQ(meta["images"]["main"]["width"], 8);
    EXPECT_EQ(meta["images"]["main"]["digest"].get<std::string>().size(), 16u);
    EXPECT_TRUE(methods::render(*rt, table, scene, spec, methods::Precision::Float, opt).cached);

    for (const Image& foreign : {Image(8, 8, 123.0), Image(4, 4, 1.0)}) {
        writeExr(base + ".exr", foreign);
        testing::internal::CaptureStderr();
        auto again = methods::render(*rt, table, scene, spec, methods::Precision::Float, opt);
        std::string err = testing::internal::GetCapturedStderr();
        EXPECT_FALSE(again.cached);
        EXPECT_EQ(again.image.px, truth.image.px);
        EXPECT_NE(err.find("warning: reference cache " + (d / "cache").string() + ": ignoring entry"),
                  std::string::npos)
            << err;
    }
}

// The cache key and the records' "kernel" input change with the kernel
// source and every header it includes, and only with those.
TEST(ReferenceCache, KeyFollowsTheKernelSources)
{
    fs::path d = tmpDir("kernels");
    fs::copy(ocl::kernelDir(), d / "kernels", fs::copy_options::recursive);
    ScopedEnv env("LUMIBENCH_KERNEL_DIR", (d / "kernels").string());
    const std::string ref = ocl::kernelSourceDigest("reference.cl"), mc = ocl::kernelSourceDigest("mc.cl");
    std::ofstream(d / "kernels" / "common" / "vec.h", std::ios::app) << "\n// changed\n";  // included via lbmath.h
    EXPECT_NE(ocl::kernelSourceDigest("reference.cl"), ref);
    const std::string ref2 = ocl::kernelSourceDigest("reference.cl");
    std::ofstream(d / "kernels" / "mc.cl", std::ios::app) << "\n// changed\n";
    EXPECT_NE(ocl::kernelSourceDigest("mc.cl"), mc);
    EXPECT_EQ(ocl::kernelSourceDigest("reference.cl"), ref2);  // mc.cl is not one of its sources
}

}  // namespace
}  // namespace lb

namespace lb {
namespace {

TEST(ExperimentKeys, ShapeAndSizeFromTheFile)
{
    LB_REQUIRE_SHARED(shared);
    fs::path d = tmpDir("shape");
    fs::copy_file(shared + "/luminaires/ieslibrary/007cfb11e343e2f42e3b476be4ab684e.ies", d / "round.ies");
    fs::copy_file(shared + "/luminaires/ieslibrary/02a7562c650498ebb301153dbbf59207.ies", d / "rect.ies");
    fs::copy_file(shared + "/luminaires/zumtobel/INTRO_60714483.LDT", d / "intro.ldt");
    json j = tiny(d);
    j["luminaires"] = {"round.ies", "rect.ies"};
    j["size"] = "file";
    auto sc = experiments::scenes(experiments::loadExperiment(writeJson(d / "e.json", j)));
    ASSERT_EQ(sc.size(), 2u);
    EXPECT_EQ(sc[0].scene().shape, LightShape::Disk);  // a circle of 80 mm
    EXPECT_DOUBLE_EQ(sc[0].scene().width, 0.08);
    EXPECT_EQ(sc[1].scene().shape, LightShape::Rect);  // 0.27 along C0 (W) x 0.24
    EXPECT_DOUBLE_EQ(sc[1].scene().width, 0.27);
    EXPECT_DOUBLE_EQ(sc[1].scene().length, 0.24);
    j["shape"] = "disk";  // wins over the file's
    sc = experiments::scenes(experiments::loadExperiment(writeJson(d / "e.json", j)));
    EXPECT_EQ(sc[1].scene().shape, LightShape::Disk);
    EXPECT_DOUBLE_EQ(sc[1].scene().width, 0.27);
    const std::string f = (d / "e.json").string();
    j["shape"] = "oval";
    EXPECT_EQ(inputErrorOf([&] { experiments::loadExperiment(writeJson(d / "e.json", j)); }),
              f + ": key \"shape\": shape: expected rect or disk, got 'oval'");
    j.erase("shape");
    j["luminaires"] = {"intro.ldt"};  // luminous sides as tall as it is wide: no flat face
    std::string m = inputErrorOf([&] { experiments::scenes(experiments::loadExperiment(writeJson(d / "e.json", j))); });
    EXPECT_NE(m.find(f + ": key \"size\""), std::string::npos) << m;
    EXPECT_NE(m.find("no flat luminous opening"), std::string::npos) << m;
}

}  // namespace
}  // namespace lb
