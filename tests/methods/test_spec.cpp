// SPEC parsing and the tunables table (host/methods/spec.h, param.h, registry.h).
#include "methods/registry.h"
#include "methods/samples.h"
#include "methods/spec.h"
#include "testutil.h"
#include "util/error.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

namespace lb::methods {
namespace {

std::string errorOf(const std::string& spec)
{
    try {
        parseSpec(spec);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(Spec, DefaultsAndValues)
{
    auto s = parseSpec("mc:n=40,pattern=halton");
    EXPECT_EQ(s.name, "mc");
    EXPECT_EQ(s.integer("n"), 40);
    EXPECT_EQ(s.str("pattern"), "halton");
    EXPECT_EQ(s.integer("seed"), 0);  // default filled in
    EXPECT_EQ(s.given.size(), 2u);
    EXPECT_EQ(
        s.canonical(),
        "mc:atrous_sigma=4,cosine_warp=0,denoise=none,domain=area,extra=0,gauss_radius=0,gauss_sigma=0,lookup=lut,"
        "min_solid=0.001,mis_split=0.5,n=40,"
        "paper=0,pattern=halton,scale=1,seed=0,sequence=shared,shift=0,specialize=auto");
    EXPECT_EQ(s.paramsJson()["n"], 40);
    EXPECT_EQ(parseSpec("reference").num("tol"), 1e-5);
    EXPECT_EQ(parseSpec("point:").name, "point");
}

// parseSpec resolves a method once: the family of the scene kind it was
// parsed for, which with() keeps and everything after the parser reads.
TEST(Spec, ResolvesTheFamilyOfItsSceneKind)
{
    const MethodSpec d = parseSpec("mc"), sp = parseSpec("mc", SceneKind::Specular);
    EXPECT_EQ(&d.family(), &family("mc"));
    EXPECT_EQ(&sp.family(), &family("mc", SceneKind::Specular));
    EXPECT_NE(&sp.family(), &d.family());  // one name, two families (their own kernels)
    EXPECT_NE(sp.family().file, d.family().file);
    const MethodSpec w = d.with("n", "12");
    EXPECT_EQ(&w.family(), &d.family());
    EXPECT_EQ(w.canonical(), parseSpec("mc:n=12").canonical());
    EXPECT_EQ(w.given, parseSpec("mc:n=12").given);
    EXPECT_THROW(d.with("nope", "1"), InputError);  // a key the family lacks
    EXPECT_THROW(d.with("n", "0"), InputError);  // out of range
    EXPECT_THROW(parseSpec("mc:domain=solid").with("paper", "1"), InputError);  // the family's whole-spec check
    EXPECT_THROW(MethodSpec{}.family(), Error);  // a spec no parser made
}

// What a family leaves unset has its default: nothing to check, every
// parameter used, no frames to settle, no variants; a plan is its own.
TEST(Spec, FamilyDefaults)
{
    Family f;
    f.name = "bare";
    const MethodSpec s = parseSpec("mc");
    EXPECT_NO_THROW(f.validate(s));
    EXPECT_FALSE(f.unused(s, "n"));
    EXPECT_EQ(f.settleFrames(s), 0);
    EXPECT_TRUE(f.variants().empty());
    MethodSpec bare;
    bare.name = f.name;
    bare.fam = &f;
    EXPECT_THROW(bare.plan(Scene{}, photometry::Table{}, ocl::DeviceInfo{}, Precision::Float), Error);  // no plan
}

TEST(Spec, ErrorsNameWhatIsValid)
{
    // Unknown method: every valid name is listed.
    std::string e = errorOf("montecarlo:n=3");
    EXPECT_NE(e.find("unknown method 'montecarlo'"), std::string::npos) << e;
    for (auto* n : {"reference", "point", "structured", "cp", "np", "mrp", "mc"})
        EXPECT_NE(e.find(n), std::string::npos) << n;
    // Unknown key: the valid keys are listed.
    e = errorOf("mc:samples=3");
    EXPECT_NE(e.find("unknown parameter 'samples'"), std::string::npos) << e;
    EXPECT_NE(e.find("n, extra, scale, pattern, seed"), std::string::npos) << e;
    // cp has no skew (np and mrp do); its keys are listed
    e = errorOf("cp:skew=0.1");
    EXPECT_NE(e.find("unknown parameter 'skew'"), std::string::npos) << e;
    EXPECT_NE(e.find("lookup, specialize, lanes"), std::string::npos) << e;
    // Bad values: out of range, not a number, not an integer, not a choice.
    EXPECT_NE(errorOf("mc:n=0").find("an integer in [1,"), std::string::npos);
    EXPECT_NE(errorOf("mc:n=abc").find("bad value 'abc' for n"), std::string::npos);
    EXPECT_NE(errorOf("mc:n=2.5").find("bad value"), std::string::npos);
    EXPECT_NE(errorOf("mc:pattern=sobol").find("one of poisson|halton|stratified|random"), std::string::npos);
    EXPECT_NE(errorOf("reference:tol=nan").find("bad value"), std::string::npos);
    // Malformed pairs and repeats.
    EXPECT_NE(errorOf("mc:n").find("expected key=value"), std::string::npos);
    EXPECT_NE(errorOf("mc:n=4,n=5").find("given twice"), std::string::npos);
    EXPECT_NE(errorOf("mc:n=4,").find("expected key=value"), std::string::npos);
}

TEST(Tunables, TableIsComplete)
{
    // Every parameter has a meaning and a default its own check accepts.
    auto rows = tunables();
    ASSERT_FALSE(rows.empty());
    for (auto& r : rows) {
        EXPECT_FALSE(r.param.meaning.empty()) << r.method << "." << r.param.name;
        EXPECT_EQ(r.param.canonical(r.method, r.param.def), r.param.def) << r.method << "." << r.param.name;
        if (r.param.kind == Kind::Real || r.param.kind == Kind::Int) {
            EXPECT_LT(r.param.lo, r.param.hi);
        }
    }
}

TEST(Samples, SetsAreDeterministicInRangeAndDistinctBySeed)
{
    for (auto* pat : {"poisson", "halton", "stratified", "random"}) {
        auto a = samplePoints(pat, 100, 7), b = samplePoints(pat, 100, 7), c = samplePoints(pat, 100, 8);
        ASSERT_EQ(a.size(), 200u);
        EXPECT_EQ(a, b) << pat;
        EXPECT_NE(a, c) << pat;
        for (double v : a) {
            EXPECT_GE(v, 0.0);
            EXPECT_LT(v, 1.0);
        }
    }
    // Halton without a shift: the first points of bases 2 and 3.
    auto h = samplePoints("halton", 3, 0);
    EXPECT_DOUBLE_EQ(h[0], 0.5);
    EXPECT_DOUBLE_EQ(h[1], 1.0 / 3);
    EXPECT_DOUBLE_EQ(h[2], 0.25);
    EXPECT_DOUBLE_EQ(h[3], 2.0 / 3);
    // Stratified: exactly one point in each of the 4 x 4 cells for n = 16.
    auto s = samplePoints("stratified", 16, 1);
    std::vector<int> cell(16, 0);
    for (int i = 0; i < 16; ++i) ++cell[static_cast<int>(s[2 * i] * 4) + 4 * static_cast<int>(s[2 * i + 1] * 4)];
    for (int c : cell) EXPECT_EQ(c, 1);
    // Poisson-disk: far better spread than random (min distance, n = 64):
    // best-candidate reaches ~0.7 / sqrt(n); random sets typically ~0.1 / sqrt(n).
    auto mind = [](const std::vector<double>& p) {
        double m = 1e9;
        for (size_t i = 0; i < p.size() / 2; ++i)
            for (size_t j = 0; j < i; ++j)
                m = std::min(m, std::hypot(p[2 * i] - p[2 * j], p[2 * i + 1] - p[2 * j + 1]));
        return m;
    };
    EXPECT_GT(mind(samplePoints("poisson", 64, 3)), 0.4 / 8);
    EXPECT_THROW(samplePoints("sobol", 4, 0), InputError);
}

// Values of a parameter that its table allows: each choice (alone, for a
// list), or the bounds and the default of a number.
std::vector<std::string> validValues(const Param& p)
{
    if (p.kind == Kind::Choice || p.kind == Kind::List) return p.choices;
    if (p.kind == Kind::Text) return {p.def};  // a file path: any other value names a file that must exist
    if (p.kind == Kind::Int) return {fmt::format("{}", long(p.lo)), fmt::format("{}", long(p.hi)), p.def};
    return {fmt::format("{}", p.lo), fmt::format("{}", p.hi), p.def};
}

// Every parameter of every family's table, each value it allows, through a
// SPEC string and back: the parsed value is the table's canonical text, and
// the canonical SPEC parses to the same values. A value the family's own
// check refuses in combination with the defaults (e.g. a warp_stop past the
// default RSM's levels) may throw, but never as a bad value, and every
// parameter takes at least one of its values.
TEST(Spec, EveryParameterRoundTripsThroughASpec)
{
    size_t checked = 0;
    for (const auto& f : registry().all())
        for (const auto& p : f.params) {
            size_t accepted = 0;
            for (const auto& v : validValues(p)) {
                const std::string text = f.name + ":" + p.name + "=" + v;
                MethodSpec s;
                try {
                    s = parseSpec(text, f.scenes.front());
                } catch (const InputError& e) {
                    EXPECT_EQ(std::string(e.what()).find("bad value"), std::string::npos) << text << ": " << e.what();
                    continue;
                }
                ++accepted;
                EXPECT_EQ(s.values.at(p.name), p.canonical(f.name, v)) << text;
                EXPECT_EQ(parseSpec(s.canonical(), f.scenes.front()).values, s.values) << text;
            }
            EXPECT_GE(accepted, 1u) << f.name << " " << p.name;
            ++checked;
        }
    EXPECT_GE(checked, 100u);  // every family's parameters (111 when written)
}

// A value outside each parameter's table: the error names the method, the
// parameter, the value and what is allowed (Param::allowed).
TEST(Spec, EveryParameterNamesItselfAndItsAllowedValuesOnABadValue)
{
    for (const auto& f : registry().all())
        for (const auto& p : f.params) {
            std::vector<std::string> bad = {"nonesuch"};
            if (p.kind == Kind::Real || p.kind == Kind::Int)
                bad.push_back(fmt::format("{}", p.hi + 1 + std::abs(p.hi)));
            for (const auto& v : bad) {
                const std::string text = f.name + ":" + p.name + "=" + v;
                std::string e;
                try {
                    parseSpec(text, f.scenes.front());
                } catch (const InputError& err) {
                    e = err.what();
                }
                EXPECT_NE(e.find("method " + f.name), std::string::npos) << text << ": " << e;
                EXPECT_NE(e.find("for " + p.name + ":"), std::string::npos) << text << ": " << e;
                EXPECT_NE(e.find("'" + v + "'"), std::string::npos) << text << ": " << e;
                EXPECT_NE(e.find(p.allowed()), std::string::npos) << text << ": " << e;
            }
        }
}

// At the command line: exit code 2 and the same message, for the first
// parameter of each family (before any device is opened).
TEST(Spec, BadParameterValueExitsWithCode2AtTheCli)
{
    for (const auto& f : registry().all()) {
        if (f.params.empty()) continue;
        const Param& p = f.params.front();
        const std::string spec = f.name + ":" + p.name + "=nonesuch";
        auto r = test::runCli(
            "render --luminaire lambert --height 1 --rotation pi --res 4 --out /tmp/lb-never.exr --scene " +
            sceneKindName(f.scenes.front()) + " --method " + spec);
        EXPECT_EQ(r.code, 2) << spec << ": " << r.err;
        EXPECT_NE(r.err.find("for " + p.name + ": expected " + p.allowed()), std::string::npos)
            << spec << ": " << r.err;
    }
}

}  // namespace
}  // namespace lb::methods
