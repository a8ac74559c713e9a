// The equal-time protocol (equaltime/protocol.h) read from files and run by
// all three front-ends -- run's findPartner, bench's cubatureEqualTime and
// tune's pairedMs -- on a fake device: each SPEC's launch a fixed time, MC at
// N samples 0.1 N ms and the method 1.25 ms, so every answer has a closed
// form. The fit t(N) = 0.1 N aims at N = 12.5, rounded to 13; its neighbour
// towards the target is 12; the paired ratios t(MC) / t(method) are then
// 1.3 / 1.25 = 1.04 and 1.2 / 1.25 = 0.96, and 13 is closer to 1 in log
// (|log 1.04| = 0.0392 < |log 0.96| = 0.0408).
#include "bench/bench.h"
#include "equaltime/protocol.h"
#include "experiments/runner.h"
#include "methods/spec.h"
#include "tune/tune.h"
#include "util/error.h"
#include "util/json_file.h"

#include "testutil.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>

namespace lb {
namespace {

constexpr double kMethodMs = 1.25;

// The fake device: launches of a fixed time per SPEC, counted.
struct FakeDevice {
    std::map<std::string, int> builds;  // canonical SPEC -> Prepared built
    int methodLaunches = 0;

    static double mcMs(const methods::MethodSpec& s)
    {
        return 0.1 * (double(s.integer("n")) + (s.has("extra") ? s.num("extra") : 0));
    }
    equaltime::Frames frames()
    {
        return [this](const methods::MethodSpec& s) -> equaltime::Launch {
            ++builds[s.canonical()];
            if (s.name == "mc") return [ms = mcMs(s)] { return ms; };
            return [this] {
                ++methodLaunches;
                return kMethodMs;
            };
        };
    }
};

equaltime::Curve linearCurve(const std::vector<long>& ns)
{
    equaltime::Curve c;
    for (long n : ns) c.emplace_back(n, 0.1 * double(n));
    return c;
}

std::string canonical(const std::string& spec) { return methods::parseSpec(spec).canonical(); }

// Exact in binary up to rounding of 0.1 n: 1e-12 relative.
constexpr double kTol = 1e-12;

TEST(EqualTimeProtocol, RunFindsThePartnerThroughTheProtocol)
{
    experiments::Experiment e;  // the default protocol: search, 11 rounds, tolerance 0.10, fit 8, 32, 128
    experiments::Baseline b{"MCI", "mc", methods::parseSpec("mc").canonical()};
    FakeDevice dev;
    int cellTimes = 0;
    auto timeOf = [&](const methods::MethodSpec& s) {
        ++cellTimes;
        return FakeDevice::mcMs(s);
    };
    equaltime::Curve fit;  // none from the scene: the protocol's fit is timed
    const equaltime::Result q =
        experiments::findPartner(e, b, dev.frames(), timeOf, methods::parseSpec("cubature"), fit, kMethodMs);
    EXPECT_EQ(cellTimes, 3);
    EXPECT_EQ(fit, linearCurve({8, 32, 128}));
    EXPECT_EQ(q.n, 13);
    EXPECT_NEAR(q.ratio, 1.04, kTol);
    EXPECT_TRUE(q.ok);
    EXPECT_TRUE(q.bracketed);  // 12 was timed below 1
    EXPECT_EQ(dev.builds[canonical("mc:n=12")], 1);  // each candidate built once
    EXPECT_EQ(dev.builds[canonical("mc:n=13")], 1);
    EXPECT_EQ(dev.methodLaunches, e.protocol.rounds + 1);  // one set of rounds and its warm-up
}

// With "subpixel", MC slower at N = 1 than the method is rendered at a
// share of the image's side: MC at N = 1 takes 2.5 scale^2 ms here, the
// method 1.25 ms, so the first aim, scale^2 = 1 / 2 (time as the pixels),
// scale 0.707, is within the tolerance: 2.5 x 0.499849 / 1.25 = 0.9997
// (its companion, scale 0.5, timed in the same rounds: 0.5).
// Without it the search stops at N = 1, off time.
TEST(EqualTimeProtocol, SubpixelGoesBelowOneSample)
{
    experiments::Baseline b{"MC", "mc", methods::parseSpec("mc").canonical()};
    for (bool subpixel : {true, false}) {
        experiments::Experiment e;
        e.protocol.subpixel = subpixel;
        std::map<std::string, int> builds;
        equaltime::Frames frames = [&](const methods::MethodSpec& s) -> equaltime::Launch {
            ++builds[s.canonical()];
            const double ms =
                s.name == "mc" ? 2.5 * double(s.integer("n")) * s.num("scale") * s.num("scale") : kMethodMs;
            return [ms] { return ms; };
        };
        auto timeOf = [](const methods::MethodSpec& s) { return 2.5 * double(s.integer("n")); };
        equaltime::Curve fit;
        const equaltime::Result q =
            experiments::findPartner(e, b, frames, timeOf, methods::parseSpec("cubature"), fit, kMethodMs);
        EXPECT_EQ(q.n, 1);
        if (subpixel) {
            EXPECT_NEAR(q.scale, 0.707, kTol);
            EXPECT_NEAR(q.ratio, 2.5 * 0.707 * 0.707 / kMethodMs, kTol);
            EXPECT_TRUE(q.ok);
            EXPECT_EQ(builds[canonical("mc:n=1,scale=0.707")], 1);
        } else {
            EXPECT_EQ(q.scale, 1);
            EXPECT_NEAR(q.ratio, 2.0, kTol);
            EXPECT_FALSE(q.ok);
        }
    }
}

TEST(EqualTimeProtocol, BenchPairsTheCubatureThroughTheProtocol)
{
    const equaltime::Protocol p = bench::benchProtocol(true, 5);
    EXPECT_EQ(p.rounds, 11);  // max(reps, 11)
    EXPECT_EQ(p.fit, (std::vector<long>{1, 8, 32}));
    FakeDevice dev;
    const nlohmann::json c = bench::cubatureEqualTime(p, dev.frames(), linearCurve(p.fit), kMethodMs, 0.8);
    EXPECT_EQ(c["equal_time_n"], 13);
    EXPECT_NEAR(c["equal_time_ratio"].get<double>(), 1.04, kTol);
    EXPECT_NEAR(c["verify_ms"].get<double>(), 1.3, kTol);
    EXPECT_NEAR(c["ratio"].get<double>(), kMethodMs / 0.8, kTol);
    EXPECT_TRUE(c["equal_time_ok"].get<bool>());
    EXPECT_EQ(dev.methodLaunches, p.rounds + 1);
}

// Tune's mode aim pairs once, at the aimed N alone; mode search also times
// the neighbour. Both read the method's time back on the curve's clock:
// t(13) / 1.04 = 1.25 exactly.
TEST(EqualTimeProtocol, TunePairsInModeAimOrSearch)
{
    const methods::MethodSpec cub = methods::parseSpec("cubature");
    auto mcAt = [](long n, double extra) { return methods::parseSpec(equaltime::specAt("mc", n, extra)); };
    equaltime::Protocol p = tune::tuneProtocol();
    ASSERT_EQ(p.mode, equaltime::Mode::Aim);
    FakeDevice aim;
    EXPECT_NEAR(tune::pairedMs(p, aim.frames(), cub, mcAt, linearCurve(p.fit), kMethodMs), kMethodMs, kTol);
    EXPECT_EQ(aim.builds.size(), 2u);  // the method and MC at 13
    EXPECT_EQ(aim.builds[canonical("mc:n=13")], 1);
    EXPECT_EQ(aim.methodLaunches, p.rounds + 1);

    p.mode = equaltime::Mode::Search;
    FakeDevice search;
    EXPECT_NEAR(tune::pairedMs(p, search.frames(), cub, mcAt, linearCurve(p.fit), kMethodMs), kMethodMs, kTol);
    EXPECT_EQ(search.builds[canonical("mc:n=12")], 1);
}

std::string writeExperiment(const std::string& name, const nlohmann::json& extra)
{
    nlohmann::json j = {{"luminaire_dir", test::sourceDir() + "/luminaires"},
                        {"luminaires", {"lambert.ldt"}},
                        {"heights", {1.1}},
                        {"rotations", {"pi"}},
                        {"methods", {"cubature"}}};
    j.update(extra);
    const std::string path = (test::freshDir("protocol-" + name) / "e.json").string();
    std::ofstream(path) << j.dump();
    return path;
}

// The "equal_time" object and the top-level equal_time_<key> form read alike,
// through the one reader; a key set twice, or one the top level owns, is refused.
TEST(EqualTimeProtocol, ExperimentFilesReadTheProtocolInBothForms)
{
    const auto object = experiments::loadExperiment(writeExperiment(
        "object",
        {{"reps", 7},
         {"time_res", 64},
         {"equal_time",
          {{"methods", {"cubature"}}, {"tolerance", 0.05}, {"rounds", 9}, {"fit", {2, 4}}, {"mode", "aim"}}}}));
    const auto flat = experiments::loadExperiment(writeExperiment("flat",
                                                                  {{"reps", 7},
                                                                   {"time_res", 64},
                                                                   {"equal_time", {"cubature"}},
                                                                   {"equal_time_tolerance", 0.05},
                                                                   {"equal_time_rounds", 9},
                                                                   {"equal_time_fit", {2, 4}}}));
    for (const auto* e : {&object, &flat}) {
        EXPECT_EQ(e->equalTime, std::vector<std::string>{"cubature"});
        EXPECT_EQ(e->protocol.reps, 7);
        EXPECT_EQ(e->protocol.timeRes, 64);
        EXPECT_EQ(e->protocol.tolerance, 0.05);
        EXPECT_EQ(e->protocol.rounds, 9);
        EXPECT_EQ(e->protocol.fit, (std::vector<long>{2, 4}));
    }
    EXPECT_EQ(object.protocol.mode, equaltime::Mode::Aim);
    EXPECT_EQ(flat.protocol.mode, equaltime::Mode::Search);

    for (const auto& [extra, what] : std::vector<std::pair<nlohmann::json, std::string>>{
             {{{"equal_time", {{"methods", {"cubature"}}, {"reps", 5}}}}, "top-level \"reps\""},
             {{{"equal_time", {{"methods", {"cubature"}}, {"mc", "mc"}}}}, "top-level \"mc\""},
             {{{"equal_time", {{"methods", {"cubature"}}, {"rounds", 9}}}, {"equal_time_rounds", 9}},
              "\"equal_time_rounds\""},
             {{{"equal_time", {{"methods", {"cubature"}}, {"fit", {8}}}}}, "at least two"},
             {{{"equal_time_rounds", 3}}, "equal_time_rounds"}}) {
        const std::string msg = test::inputErrorOf([&] { experiments::loadExperiment(writeExperiment("bad", extra)); });
        EXPECT_NE(msg.find(what), std::string::npos) << what << " in: " << msg;
    }
}

TEST(EqualTimeProtocol, ReaderChecksEachKey)
{
    auto read = [](const nlohmann::json& j) {
        equaltime::Protocol p;
        equaltime::readProtocol(util::JsonKeys{"f.json", j}, p);
        return p;
    };
    const equaltime::Protocol p = read({{"mc", "mc:domain=solid"}, {"mode", "aim"}, {"tolerance", 0.2}});
    EXPECT_EQ(p.mc, "mc:domain=solid");
    EXPECT_EQ(p.options().mode, equaltime::Mode::Aim);
    EXPECT_EQ(p.options().tolerance, 0.2);
    EXPECT_EQ(read(p.json()).json(), p.json());  // json() reads back as itself
    EXPECT_FALSE(p.subpixel);
    EXPECT_TRUE(read({{"subpixel", true}}).subpixel);
    for (const auto& [j, what] :
         std::vector<std::pair<nlohmann::json, std::string>>{{{{"mc", "mc:n=4"}}, "without n"},
                                                             {{{"mc", "cubature"}}, "without n"},
                                                             {{{"mode", "fast"}}, "search or aim"},
                                                             {{{"tolerance", 0}}, "tolerance"},
                                                             {{{"rounds", 0}}, "rounds"},
                                                             {{{"subpixel", "yes"}}, "subpixel"}}) {
        const std::string msg = test::inputErrorOf([&] { read(j); });
        EXPECT_NE(msg.find(what), std::string::npos) << what << " in: " << msg;
        EXPECT_NE(msg.find("f.json"), std::string::npos) << msg;
    }
}

}  // namespace
}  // namespace lb
