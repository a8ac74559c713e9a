// Every registered method's plan (Family::plan), built with no OpenCL device:
// the defines, the lanes and the kernel arguments by name. The exact defines
// of every family over a sweep of scenes are held by program_options.golden
// (test_program_options.cpp); this test holds what a plan must be for render
// to bind it (methods/registry.h: Plan, bindPlan).
#include "methods/registry.h"
#include "methods/spec.h"
#include "test_tables.h"
#include "testutil.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace lb::methods {
namespace {

// The unclipped scene of the golden sweep, and an edge one: the light in the
// receiver plane, seen edge-on (the horizon clips it to a line).
std::vector<Scene> planScenes(SceneKind kind)
{
    return {test_tables::sceneAt(kind, 1.0, 3 * M_PI / 4, 24), test_tables::sceneAt(kind, 0.0, M_PI / 2, 24)};
}

const Param* paramOf(const Family& f, const std::string& name)
{
    for (const auto& p : f.params)
        if (p.name == name) return &p;
    return nullptr;
}

// One argument's value as bindPlan will set it: an int that fits cl_int, a
// finite real, an output of at least one element.
void expectBindable(const Family& f, const MethodSpec& spec, const PlanArg& a, const std::string& what)
{
    using K = PlanArg::Kind;
    const Param* p = paramOf(f, a.name);
    switch (a.kind) {
    case K::Int:
        EXPECT_EQ(a.value, std::floor(a.value)) << what;
        EXPECT_LE(std::fabs(a.value), double(std::numeric_limits<cl_int>::max())) << what;
        if (p && p->kind == Kind::Int && a.name != "seed") {
            EXPECT_EQ(a.value, spec.integer(a.name)) << what;
        }
        break;
    case K::Real:
    case K::Float:
        EXPECT_TRUE(std::isfinite(a.value)) << what;
        // a parameter bound under its own name carries the spec's number, not a rounding of it
        if (p && a.kind == K::Real) {
            EXPECT_EQ(a.value, spec.num(a.name)) << what;
        }
        break;
    case K::Reals:
        for (double v : a.reals) EXPECT_TRUE(std::isfinite(v)) << what;
        break;
    case K::Floats:
        EXPECT_FALSE(a.floats.empty()) << what;
        break;
    case K::OutputInts:
    case K::OutputReals:
        EXPECT_GE(a.count, 1u) << what;
        break;
    case K::Device:
        break;
    }
}

// Each -D word once; LB_DOUBLE and LB_LANES are render's, not the plan's.
void expectDefines(const std::string& defines, const std::string& what)
{
    std::istringstream in(defines);
    std::vector<std::string> seen;
    for (std::string w; in >> w;) {
        EXPECT_EQ(w.rfind("-D", 0), 0u) << what << ": " << w;
        EXPECT_EQ(w.find("LB_DOUBLE"), std::string::npos) << what;
        EXPECT_EQ(w.find("LB_LANES"), std::string::npos) << what;
        EXPECT_EQ(std::count(seen.begin(), seen.end(), w), 0) << what << ": " << w << " twice";
        seen.push_back(w);
    }
}

// The plan of every method (its default spec and its bench specs) on both
// scenes, on a CPU in float and double and on a GPU in float: every argument
// the family declares, by name, once, in the kernel's order, each bindable;
// a device argument only with a binder; lanes 1 or, for a straight-line form
// on a CPU in float, 8; the default spec on the unclipped scene runs the
// family's straight-line form where it has one.
TEST(MethodPlan, EveryRegisteredMethodPlansWithoutADevice)
{
    ocl::DeviceInfo cpu, gpu;
    cpu.type = "CPU";
    gpu.type = "GPU";
    const auto table = test_tables::asymmetric();
    int plans = 0;
    for (const Family& f : registry().all())
        for (SceneKind kind : f.scenes) {
            std::vector<std::string> specs = {f.name};
            specs.insert(specs.end(), f.benchSpecs.begin(), f.benchSpecs.end());
            for (const auto& text : specs)
                for (const Scene& sc : planScenes(kind))
                    for (auto [dev, p] :
                         {std::pair{&cpu, Precision::Float}, {&gpu, Precision::Float}, {&cpu, Precision::Double}}) {
                        const MethodSpec spec = parseSpec(text, kind);
                        const std::string what = fmt::format("{} [{}] {} on {} in {}", text, sceneKindName(kind),
                                                             sc.describe(), dev->type, precisionName(p));
                        ASSERT_TRUE(f.plan) << what;
                        const Plan plan = spec.plan(sc, table, *dev, p);
                        std::vector<std::string> names;
                        for (const auto& a : plan.args) {
                            names.push_back(a.name);
                            expectBindable(f, spec, a, what + " " + a.name);
                            if (a.kind == PlanArg::Kind::Device) {
                                EXPECT_TRUE(plan.bind) << what << " " << a.name;
                            }
                        }
                        EXPECT_EQ(names, f.args) << what;
                        expectDefines(plan.defines, what);
                        const bool straight = kernelForm(f, plan.defines) == "straight-line";
                        if (plan.lanes != 1) {
                            EXPECT_EQ(plan.lanes, 8) << what;
                            EXPECT_TRUE(straight && dev == &cpu && p == Precision::Float) << what;
                        }
                        if (text == f.name && sc.height > 0 && !f.straightDefines.empty()) {
                            EXPECT_TRUE(straight) << what;
                        }
                        ++plans;
                    }
            // the lookup buffer, made on demand (empty: the exact table)
            const Plan plan = parseSpec(f.name, kind).plan(planScenes(kind)[0], table, cpu, Precision::Float);
            EXPECT_FALSE(plan.lum ? plan.lum().empty() : table.packed().empty()) << f.name;
        }
    // every family at least once on both scenes and three devices
    EXPECT_GE(plans, static_cast<int>(registry().all().size()) * 6);
}

}  // namespace
}  // namespace lb::methods
