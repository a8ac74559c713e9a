// lumibench tune: what the objectives aggregate (closed forms on synthetic
// scores), the parameters' spread over cross-validation folds, and the
// balanced objectives end to end.
#include "methods/render.h"
#include "photometry/load.h"
#include "testutil.h"
#include "tune/tune.h"
#include "util/error.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace lb {
namespace {

namespace fs = std::filesystem;

TEST(TuneObjective, AggregatesInClosedForm)
{
    const std::vector<double> s = {1, 4, 16};
    // The arithmetic mean 21 / 3, the geometric mean (1 * 4 * 16)^(1/3) = 4,
    // the worst 16; exp(mean log) rounds within a few ulp: 1e-14 relative.
    EXPECT_DOUBLE_EQ(tune::aggregateScores("mean", s), 7.0);
    EXPECT_NEAR(tune::aggregateScores("geomean", s), 4.0, 4e-14);
    EXPECT_DOUBLE_EQ(tune::aggregateScores("worst", s), 16.0);
    // relative and equal_time average the scores they are given.
    EXPECT_DOUBLE_EQ(tune::aggregateScores("relative", s), 7.0);
    EXPECT_DOUBLE_EQ(tune::aggregateScores("equal_time", {-1.0, 0.5}), -0.25);
    // A zero score is clamped to 1e-300 before the log: finite, tiny.
    const double z = tune::aggregateScores("geomean", {0.0, 1.0});
    EXPECT_TRUE(std::isfinite(z));
    EXPECT_NEAR(z, 1e-150, 1e-162);
    EXPECT_THROW(tune::aggregateScores("mean", {}), Error);
}

TEST(TuneObjective, GeomeanWeighsEveryScene)
{
    // A: one scene 1000x worse than the others, those 10x better than B's.
    // The arithmetic mean follows the worst scene and prefers B (1.733 < 3.34);
    // the geometric mean prefers A: (10 * 0.01 * 0.01)^(1/3) = 0.1 against
    // (5 * 0.1 * 0.1)^(1/3) = 0.368.
    const std::vector<double> a = {10, 0.01, 0.01}, b = {5, 0.1, 0.1};
    EXPECT_GT(tune::aggregateScores("mean", a), tune::aggregateScores("mean", b));
    EXPECT_LT(tune::aggregateScores("geomean", a), tune::aggregateScores("geomean", b));
    EXPECT_NEAR(tune::aggregateScores("geomean", a), 0.1, 1e-15);
    EXPECT_NEAR(tune::aggregateScores("geomean", b), std::cbrt(0.05), 1e-15);
    // Scaling one scene by c scales the geometric mean by c^(1/n) for every
    // candidate alike: the ranking does not depend on a scene's scale.
    std::vector<double> a2 = a, b2 = b;
    a2[0] *= 1000;
    b2[0] *= 1000;
    EXPECT_NEAR(tune::aggregateScores("geomean", a2) / tune::aggregateScores("geomean", a), 10.0, 1e-12);
    EXPECT_NEAR(tune::aggregateScores("geomean", b2) / tune::aggregateScores("geomean", b), 10.0, 1e-12);
}

TEST(TuneObjective, RelativeDividesByTheScale)
{
    EXPECT_DOUBLE_EQ(tune::relativeScore(8, 4), 2.0);
    EXPECT_DOUBLE_EQ(tune::relativeScore(0.5, 0.25), 2.0);
    // An undefined scale (0, NaN, inf): 1e-30, so the score is large, finite.
    EXPECT_DOUBLE_EQ(tune::relativeScore(1, 0), 1e30);
    EXPECT_DOUBLE_EQ(tune::relativeScore(1, std::nan("")), 1e30);
    EXPECT_DOUBLE_EQ(tune::relativeScore(1, INFINITY), 1e30);
}

TEST(TuneObjective, ParameterSpreadInTheSearchScale)
{
    std::vector<tune::Dim> dims = {{methods::Param::real("lin", 1, 0, 4, methods::Scale::Linear, "")},
                                   {methods::Param::real("log", 1e-3, 1e-6, 1, methods::Scale::Log, "")}};
    // lin 1 and 3 of [0, 4]: half the range, mean 2, std 1; log 1e-6 and 1e-3
    // of [1e-6, 1]: half the log range; 0 where the folds agree.
    auto s = tune::parameterSpread(dims, {{1, 1e-6}, {3, 1e-3}});
    EXPECT_DOUBLE_EQ(s["lin"]["unit_range"].get<double>(), 0.5);
    EXPECT_DOUBLE_EQ(s["lin"]["mean"].get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(s["lin"]["std"].get<double>(), 1.0);
    EXPECT_EQ(s["lin"]["default"], "1");
    EXPECT_NEAR(s["log"]["unit_range"].get<double>(), 0.5, 1e-12);
    EXPECT_DOUBLE_EQ(s["log"]["min"].get<double>(), 1e-6);
    EXPECT_DOUBLE_EQ(s["log"]["max"].get<double>(), 1e-3);
    auto same = tune::parameterSpread(dims, {{2, 1e-4}, {2, 1e-4}, {2, 1e-4}});
    EXPECT_DOUBLE_EQ(same["lin"]["unit_range"].get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(same["lin"]["std"].get<double>(), 0.0);
}

// A minimal valid tune file on the suite's luminaires.
nlohmann::json smallExperiment()
{
    return {
        {"method", "robust"},
        {"params", {"area_q"}},
        {"reference", "reference:tol=1e-4"},
        {"luminaire_dir", test::sourceDir() + "/luminaires"},
        {"res", 8},
        {"train", {{"luminaires", {"lambert.ldt", "grazing.ldt"}}, {"heights", {0.1, 1.1}}, {"rotations", {"pi/2"}}}},
        {"validation", {{"luminaires", {"batwing.ldt"}}, {"heights", {1.1}}, {"rotations", {"pi/2"}}}},
        {"maxeval", 3}};
}

// Writes e to a fresh directory and runs `lumibench tune` on it.
test::CliResult tuneCli(const nlohmann::json& e, const fs::path& dir)
{
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "e.json") << e.dump();
    return test::runCli("tune " + (dir / "e.json").string() + " --out " + (dir / "out").string() +
                        " --quiet --no-plot");
}

TEST(TuneObjective, BadObjectiveAndScaleAreRefused)
{
    const fs::path dir = fs::temp_directory_path() / ("lb_tune_obj_bad_" + std::to_string(::getpid()));
    auto e = smallExperiment();
    e["objective"] = "median";
    auto r = tuneCli(e, dir);
    EXPECT_EQ(r.code, 2) << r.err;
    for (const char* s : {"objective", "geomean", "relative", "'median'"})
        EXPECT_NE(r.err.find(s), std::string::npos) << s << " in: " << r.err;
    e["objective"] = "geomean";
    e["scale"] = "point";
    r = tuneCli(e, dir);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("scale"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("relative uses it"), std::string::npos) << r.err;
    e["objective"] = "relative";
    e["scale"] = "nosuchmethod";
    r = tuneCli(e, dir);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("scale"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

// relative end to end: each scene's score is the method's NMSE over the
// point light's, the objective their mean; the cross-validation reports
// both means per fold, the parameters' spread, and prints its table
// before the tuned SPEC on stdout.
TEST(TuneObjective, RelativeObjectiveAndCrossValidationTable)
{
    LB_REQUIRE_RUNTIME(rt);
    const fs::path dir = fs::temp_directory_path() / ("lb_tune_obj_rel_" + std::to_string(::getpid()));
    auto e = smallExperiment();
    e["objective"] = "relative";
    e["cross_validation"] = "leave-one-luminaire-out";
    auto r = tuneCli(e, dir);
    ASSERT_EQ(r.code, 0) << r.err;
    nlohmann::json doc;
    std::ifstream(dir / "out" / "tune.json") >> doc;
    EXPECT_EQ(doc["scale"], "point");
    for (const char* which : {"default", "tuned"}) {
        const auto& s = doc[which];
        const auto& m = s["train_nmse_per_scene"];
        const auto& sc = s["train_scale_nmse_per_scene"];
        ASSERT_EQ(m.size(), 4u);
        double sum = 0;
        for (size_t i = 0; i < m.size(); ++i) {
            const double rel = m[i].get<double>() / sc[i].get<double>();
            EXPECT_NEAR(s["train_relative_per_scene"][i].get<double>(), rel, 1e-12 * rel);
            sum += rel;
        }
        // The objective is their arithmetic mean (summed in the same order).
        EXPECT_NEAR(s["train_objective"].get<double>(), sum / 4, 1e-12 * sum);
        // The geometric mean of the NMSE is reported whatever the objective.
        double lg = 0;
        for (const auto& v : m) lg += std::log(v.get<double>());
        EXPECT_NEAR(s["train_nmse_geomean"].get<double>(), std::exp(lg / 4), 1e-12 * std::exp(lg / 4));
    }
    const auto& cv = doc["cross_validation"];
    ASSERT_EQ(cv["folds"].size(), 2u);
    EXPECT_EQ(cv["folds_count"], 2);
    for (const auto& f : cv["folds"]) {
        EXPECT_EQ(f["improved"].get<bool>(), f["tuned"].get<double>() < f["default"].get<double>());
        EXPECT_EQ(f["default_nmse"]["per_scene"].size(), 2u);
        EXPECT_TRUE(std::isfinite(f["tuned_nmse"]["geomean"].get<double>()));
    }
    const auto& q = cv["param_spread"]["area_q"];
    EXPECT_EQ(q["values"].size(), 2u);
    EXPECT_GE(q["unit_range"].get<double>(), 0.0);
    EXPECT_LE(q["unit_range"].get<double>(), 1.0);
    // stdout: the table (a row per held-out luminaire and per parameter), the SPEC last.
    for (const char* s : {"| held out |", "| lambert.ldt |", "| grazing.ldt |", "| area_q | 0.5 |"})
        EXPECT_NE(r.out.find(s), std::string::npos) << s << " in: " << r.out;
    const std::string spec = doc["tuned"]["spec"].get<std::string>() + "\n";
    ASSERT_GE(r.out.size(), spec.size());
    EXPECT_EQ(r.out.substr(r.out.size() - spec.size()), spec);
    fs::remove_all(dir);
}

// The registered `tuned` is robust with the tuned values as its defaults:
// the same image as robust given them, pixel for pixel. Its parameters are
// the cubature's, so they act only where robust blends the cubature in: at
// h 0.1, R pi/2 (the light's plane crosses the receiver) the image differs
// from robust's; at h 1.1 (more than area_q = 0.5 light sizes away) both are
// the area rule alone, the same image.
TEST(TuneObjective, TunedIsRobustWithTheTunedDefaults)
{
    LB_REQUIRE_RUNTIME(rt);
    photometry::Table t = photometry::load(test::sourceDir() + "/luminaires/quadrant.ldt");
    Scene sc;
    sc.height = 0.1;
    sc.rotation = 1.5707963267948966;  // pi/2
    sc.res = 16;
    auto img = [&](const std::string& spec) {
        return methods::render(*rt, t, sc, methods::parseSpec(spec), methods::Precision::Float).image.px;
    };
    const auto tuned = img("tuned");
    EXPECT_EQ(tuned, img("robust:corner_inset=0.58125,dyn_weight=0"));
    EXPECT_NE(tuned, img("robust"));
    sc.height = 1.1;
    EXPECT_EQ(img("tuned"), img("robust"));
    EXPECT_EQ(methods::parseSpec("tuned").str("area"), "gauss3");
}

// `tuned`'s defaults are the full-set optimum of the committed 32 x 32
// cross-validation (experiments/tune-all-cv-geomean-res32.json), every
// searched parameter. The tuner prints the shortest double of its point
// (corner_inset 0.5812499999999999, area_q 0.49999999999999994: the search's
// [0, 1] map back to the range), the registry holds the decimal
// (0.58125, 0.5); the kernels read float, whose spacing here is 6e-8, so
// 1e-12 tells a re-registered value from printing and nothing else.
TEST(TuneObjective, TunedDefaultsAreTheRes32CrossValidationOptimum)
{
    std::ifstream in(test::sourceDir() + "/experiments/tune/tune-all-cv-geomean-res32.json");
    ASSERT_TRUE(in) << "experiments/tune/tune-all-cv-geomean-res32.json";
    const auto doc = nlohmann::json::parse(in);
    ASSERT_EQ(doc["method"], "robust");
    const auto spec = methods::parseSpec("tuned");
    ASSERT_EQ(doc["tuned"]["params"].size(), 4u);
    for (const auto& [name, value] : doc["tuned"]["params"].items())
        EXPECT_NEAR(spec.num(name), value.get<double>(), 1e-12) << name;
    EXPECT_EQ(spec.num("dyn_weight"), 0.0);
}

}  // namespace
}  // namespace lb
