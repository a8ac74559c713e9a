// The program options every family builds (structural defines, the scene's
// specialisation defines, lanes) and the specialisation records (JSON) over a
// sweep of specs x scenes x luminaires, held to the sweep's recorded output
// (tests/methods/program_options.golden), so that a refactoring of the
// specialisation rules (the tables of methods/specialize.h) keeps every kernel
// variant a scene gets. No device needed.
//
// A deliberate change of a rule: run with LUMIBENCH_UPDATE_GOLDEN=1 to write
// the new recording, and say in the commit which lines changed and why.
#include "methods/cubature_options.h"
#include "methods/registry.h"
#include "methods/spec.h"
#include "methods/specialize.h"
#include "photometry/lut.h"
#include "test_tables.h"
#include "testutil.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include "lb_build_config.h"

namespace lb::methods {
namespace {

using test_tables::asymmetric;
using test_tables::frontLobe;

// Heights through the receiver plane to far above it, at grazing, tilted and
// facing rotations: unclipped, clipped along u, touching, below.
std::vector<Scene> sweepScenes(SceneKind kind)
{
    std::vector<Scene> out;
    for (auto [h, rot] : {std::pair{1.0, 3 * M_PI / 4},
                          {1.0, M_PI},
                          {0.1, M_PI / 2},
                          {0.0, M_PI / 2},
                          {-0.1, M_PI / 2},
                          {-0.6, 3 * M_PI / 4}})
        out.push_back(test_tables::sceneAt(kind, h, rot, 24));
    return out;
}

// Every cubature structure the SPEC allows (fan with at most one dynamic
// point and no static samples), with the options the rules read.
std::vector<std::string> cubatureSweep(const std::string& name)
{
    std::vector<std::string> out;
    for (const char* tri : {"fan", "delaunay"})
        for (const char* dyn : {"cp", "none", "np", "cp+barycentre", "cp+np+mrp+barycentre"})
            for (const char* st : {"static=0", "static=1", "static=3,s3=0.005"})
                for (const char* extra : {"", ",normalize=formfactor", ",lookup=exact", ",specialize=none",
                                          ",blend_dist=3", ",horizon_eps=0.1,lanes=1"}) {
                    std::string spec = fmt::format("{}:triangulation={},dynamic={},{}{}", name, tri, dyn, st, extra);
                    try {
                        parseSpec(spec);
                    } catch (const InputError&) {
                        continue;  // a combination validate() rejects
                    }
                    out.push_back(spec);
                }
    return out;
}

std::vector<std::string> specsOf(const Family& f)
{
    std::vector<std::string> specs = {f.name};
    for (const auto& b : f.benchSpecs) specs.push_back(b);
    for (const auto& p : f.params)
        if (p.name == "lookup" || p.name == "specialize")
            for (const auto& c : p.choices) specs.push_back(f.name + ":" + p.name + "=" + c);
    if (f.name == "cubature")
        for (const auto& s : cubatureSweep(f.name)) specs.push_back(s);
    return specs;
}

// The rules that hold, by their JSON names (every value is a boolean).
std::string trueKeys(const nlohmann::json& j)
{
    std::string out;
    for (const auto& [k, v] : j.items()) out += v.get<bool>() ? " " + k : std::string();
    return fmt::format("{} keys:{}", j.size(), out);
}

// One line of the sweep: the program options and lanes Prepared builds
// (MethodSpec::plan: the family's plan), on a CPU and a GPU in
// float and on a CPU in double, the form, and the specialisation's JSON.
std::string sweepLine(const Family& f, const std::string& text, const MethodSpec& spec, const Scene& sc,
                      const std::string& tname, const photometry::Table& t)
{
    ocl::DeviceInfo cpu, gpu;
    cpu.type = "CPU";
    gpu.type = "GPU";
    std::string opts, lanes;
    for (auto [dev, p] : {std::pair{&cpu, Precision::Float}, {&gpu, Precision::Float}, {&cpu, Precision::Double}}) {
        Plan plan = spec.plan(sc, t, *dev, p);
        opts = plan.defines;
        lanes += fmt::format(" {}", plan.lanes);
    }
    std::string json;
    if (f.file == "cubature.cl") json = trueKeys(analyseCubature(sc, t, CubatureOptions::parse(spec.values)).json());
    if (f.file == "mc.cl")
        json = trueKeys(analyse(sc, t, spec.str("lookup") == "lut", spec.str("specialize") == "auto").json());
    return fmt::format("{} [{}] h={} R={:.4f} {} |{} | lanes{} | {} | {}\n", text, sceneKindName(spec.kind), sc.height,
                       sc.rotation, tname, opts, lanes, kernelForm(f, opts), json);
}

std::string sweep()
{
    std::ostringstream out;
    const std::vector<std::pair<std::string, photometry::Table>> tables = {{"front", frontLobe()},
                                                                           {"asym", asymmetric()}};
    for (const auto& f : registry().all())
        for (SceneKind kind : f.scenes)
            for (const auto& text : specsOf(f)) {
                MethodSpec spec = parseSpec(text, kind);
                for (const auto& sc : sweepScenes(kind))
                    for (const auto& [tname, t] : tables) out << sweepLine(f, text, spec, sc, tname, t);
            }
    return out.str();
}

TEST(ProgramOptions, EveryFamilysOptionsMatchTheRecordedSweep)
{
    const std::string path = std::string(LB_SOURCE_DIR) + "/tests/methods/program_options.golden";
    const std::string got = sweep();
    if (const char* u = std::getenv("LUMIBENCH_UPDATE_GOLDEN"); u && std::string(u) == "1") {
        std::ofstream(path) << got;
        GTEST_SKIP() << "wrote " << path;
    }
    std::ifstream in(path);
    ASSERT_TRUE(in) << "missing " << path;
    std::stringstream want;
    want << in.rdbuf();
    // Line by line, so that a failure names the first spec and scene that changed.
    std::istringstream a(want.str()), b(got);
    std::string la, lb;
    int line = 0, lines = 0;
    while (true) {
        bool ea = !std::getline(a, la), eb = !std::getline(b, lb);
        ++line;
        if (ea || eb) {
            EXPECT_EQ(ea, eb) << "the sweep and the recording differ in length at line " << line;
            break;
        }
        ASSERT_EQ(la, lb) << "line " << line << " of " << path;
        ++lines;
    }
    // the sweep covers every family and the cubature's structures (over a thousand lines)
    EXPECT_GT(lines, 1000);
}

// ---- The cubature's form table (methods/specialize.h cubatureForms) ----

// Each form's structures select that form, and only it, on an unclipped
// scene: the conditions exclude each other (analyseCubature takes the first
// that holds, so an overlap would hide a form).
TEST(FormTable, EachFormsStructuresSelectItAlone)
{
    Scene s;
    s.height = 1.0;
    s.rotation = 3 * M_PI / 4;
    s.res = 24;
    for (const auto& f : cubatureForms())
        for (const auto& e : f.examples) {
            auto o = CubatureOptions::parse(parseSpec("cubature" + (e.empty() ? "" : ":" + e)).values);
            EXPECT_EQ(analyseCubature(s, asymmetric(), o).form, f.name.json) << e;
            const CubatureScene sc(s, o);
            int holds = 0;
            for (const auto& g : cubatureForms()) holds += g.applies(o, sc);
            EXPECT_EQ(holds, 1) << e;
        }
}

// Over the whole sweep at most one form's condition holds.
TEST(FormTable, ConditionsExcludeEachOtherOverTheSweep)
{
    int checked = 0;
    for (const auto& spec : cubatureSweep("cubature")) {
        auto o = CubatureOptions::parse(parseSpec(spec).values);
        for (const auto& sc : sweepScenes(SceneKind::Diffuse)) {
            const CubatureScene facts(sc, o);
            int holds = 0;
            for (const auto& g : cubatureForms()) holds += g.applies(o, facts);
            EXPECT_LE(holds, 1) << spec << " " << sc.describe();
            ++checked;
        }
    }
    EXPECT_GT(checked, 500);
}

// The family's straight-line defines and the kernel's variants come from the
// table: every form's define is a straight-line define and is built, alone,
// with the LUT and eight lanes, and (where it runs clipped) with the clip.
TEST(FormTable, DefinesAndVariantsDeriveFromIt)
{
    EXPECT_EQ(family("cubature").straightDefines, cubatureFormDefines());
    const auto variants = cubatureVariants();
    for (size_t i = 0; i < variants.size(); ++i)
        for (size_t j = 0; j < i; ++j) EXPECT_NE(variants[i], variants[j]) << "built twice";
    auto built = [&](const std::vector<std::string>& words) {
        for (const auto& v : variants) {
            bool all = true;
            for (const auto& w : words) all = all && (v + " ").find(w + " ") != std::string::npos;
            if (all) return true;
        }
        return false;
    };
    for (const auto& f : cubatureForms()) {
        const std::string d = f.name.define;
        EXPECT_EQ(kernelForm(family("cubature"), " " + d), "straight-line") << d;
        EXPECT_TRUE(built({d})) << d;
        EXPECT_TRUE(built({"-DLB_LUT", d, "-DLB_CUB_BLEND", "-DLB_LANES=8"})) << d;
        EXPECT_EQ(built({d, "-DLB_CUB_RECT_CLIP"}), f.clipOk) << d;
    }
    EXPECT_TRUE(built({"-DLB_CUB_STATIC=4"}));
    EXPECT_TRUE(built({"-DLB_CUB_AREA=2"}));
    EXPECT_TRUE(built({"-DLB_CUB_AREA=3"}));
}

// ---- The cubature's plan (Family::plan): everything render needs, decided
// without a device ----

// Every kernel argument the family declares is bound by name, once, with the
// spec's values; the statistics buffer has two ints per pixel; the lookup
// buffer is the LUT for lookup=lut and the exact table otherwise.
TEST(CubaturePlan, BindsEveryArgumentByNameWithTheSpecsValues)
{
    Scene s;
    s.height = 1.0;
    s.rotation = 3 * M_PI / 4;
    s.res = 24;
    ocl::DeviceInfo cpu;
    cpu.type = "CPU";
    const auto t = asymmetric();
    const Family& f = family("cubature");
    auto spec = parseSpec("cubature:plane_eps=0.01,corner_inset=0.25,blend_dist=7,s2=0.3");
    Plan plan = spec.plan(s, t, cpu, Precision::Float);
    std::vector<std::string> names;
    for (const auto& a : plan.args) names.push_back(a.name);
    EXPECT_EQ(names, f.args);
    auto arg = [&](const std::string& name) {
        for (const auto& a : plan.args)
            if (a.name == name) return a;
        ADD_FAILURE() << "no argument " << name;
        return PlanArg{};
    };
    for (const auto& name : cubatureTunableNames()) {
        EXPECT_EQ(arg(name).kind, PlanArg::Kind::Real) << name;
        EXPECT_EQ(arg(name).value, spec.num(name)) << name;  // the spec's own number, not a rounding of it
    }
    EXPECT_EQ(arg("stats").kind, PlanArg::Kind::OutputInts);
    EXPECT_EQ(arg("stats").count, 2u * 24 * 24);
    EXPECT_EQ(arg("want_stats").value, 0);  // timed launches run without statistics
    EXPECT_EQ(plan.statsSwitch, "want_stats");
    EXPECT_EQ(plan.lum(), photometry::buildLut(t).packed);
    EXPECT_EQ(parseSpec("cubature:lookup=exact").plan(s, t, cpu, Precision::Float).lum(), t.packed());
    EXPECT_EQ(plan.lanes, 8);  // the fan's straight-line form on a CPU in float with the LUT
    EXPECT_EQ(spec.plan(s, t, cpu, Precision::Double).lanes, 1);
    EXPECT_TRUE(plan.finish);
    EXPECT_FALSE(plan.bind);  // nothing beyond the named arguments
}

}  // namespace
}  // namespace lb::methods
