// Expectations over seeds and the equal-time verdict: metrics::overSeeds'
// mean and Student-t interval against closed forms and its coverage rate,
// results::verdict on hand-made intervals, and the results document's
// schema_version with the typed equal-time result round trip.
#include "experiments/results.h"
#include "metrics/metrics.h"
#include "testutil.h"
#include "util/error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

namespace lb {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

metrics::Metrics withNmse(double nmse)
{
    metrics::Metrics m;
    m.nmse = nmse;
    m.flip = NAN;  // undefined in every draw: no interval
    return m;
}

// Table values of Student's t at 97.5 % (Abramowitz and Stegun 26.10), to
// the 3 decimals the table gives; large dof tends to the normal's 1.960.
TEST(Seeds, StudentTMatchesTheTable)
{
    EXPECT_NEAR(metrics::studentT975(1), 12.706, 5e-4);
    EXPECT_NEAR(metrics::studentT975(7), 2.365, 5e-4);
    EXPECT_NEAR(metrics::studentT975(30), 2.042, 5e-4);
    EXPECT_NEAR(metrics::studentT975(60), 2.000, 5e-4);
    EXPECT_NEAR(metrics::studentT975(100000), 1.960, 5e-4);
    EXPECT_THROW(metrics::studentT975(0), InputError);
}

// Draws 1..8: mean 4.5, sample standard deviation sqrt(6), so the 95 %
// half-width is t(7) sqrt(6) / sqrt(8) = 2.365 * 0.866025 = 2.04815.
TEST(Seeds, MeanAndIntervalOfEightDrawsAreTheClosedForm)
{
    std::vector<metrics::Metrics> draws;
    for (int k = 1; k <= 8; ++k) draws.push_back(withNmse(k));
    const metrics::SeedSummary s = metrics::overSeeds(draws);
    EXPECT_EQ(s.seeds, 8);
    EXPECT_DOUBLE_EQ(s.mean.nmse, 4.5);
    ASSERT_TRUE(s.ci95.count("nmse"));
    const double half = 2.365 * std::sqrt(6.0 / 8.0);
    EXPECT_NEAR(s.ci95.at("nmse")[0], 4.5 - half, 1e-12);
    EXPECT_NEAR(s.ci95.at("nmse")[1], 4.5 + half, 1e-12);
    EXPECT_FALSE(s.ci95.count("flip")) << "an undefined metric has no interval";
    // one draw: its value, no interval
    const metrics::SeedSummary one = metrics::overSeeds({withNmse(3)});
    EXPECT_EQ(one.seeds, 1);
    EXPECT_DOUBLE_EQ(one.mean.nmse, 3);
    EXPECT_TRUE(one.ci95.empty());
    EXPECT_THROW(metrics::overSeeds({}), InputError);
}

// The interval is a 95 % interval: over 4000 sets of 8 normal draws it covers
// the true mean in 95 % of them. The binomial standard deviation of the rate
// is sqrt(0.95 * 0.05 / 4000) = 0.0034, so +-0.012 is 3.5 sigma. The normal
// quantile 1.96 in place of t(7) would cover 91.0 % (fails), a t of 8 dof
// 94.7 %; the check tells t(7) from z.
TEST(Seeds, IntervalCoversTheTrueMeanAt95Percent)
{
    std::mt19937 rng(7);
    std::normal_distribution<double> g(1.0, 0.3);
    const int sets = 4000;
    int covered = 0;
    for (int i = 0; i < sets; ++i) {
        std::vector<metrics::Metrics> draws;
        for (int k = 0; k < 8; ++k) draws.push_back(withNmse(g(rng)));
        const auto ci = metrics::overSeeds(draws).ci95.at("nmse");
        covered += ci[0] <= 1.0 && 1.0 <= ci[1];
    }
    EXPECT_NEAR(covered / double(sets), 0.95, 0.012);
}

results::Record rec(double nmse, double lo, double hi, int seeds)
{
    results::Record r;
    r.method = "mc";
    r.error.nmse = nmse;
    r.seeds = seeds;
    if (seeds > 1) r.ci95["nmse"] = {lo, hi};
    return r;
}

TEST(Verdict, WinTieLossByIntervals)
{
    using results::Verdict;
    const results::Record det = rec(1.0, 1.0, 1.0, 1);  // a deterministic method: a point
    EXPECT_EQ(results::verdict(det, rec(2.0, 1.5, 2.5, 8)), Verdict::Win);
    EXPECT_EQ(results::verdict(det, rec(0.5, 0.2, 0.8, 8)), Verdict::Loss);
    EXPECT_EQ(results::verdict(det, rec(1.2, 0.9, 1.5, 8)), Verdict::Tie);  // overlaps the point
    EXPECT_EQ(results::verdict(rec(1.0, 0.8, 1.6, 8), rec(2.0, 1.5, 2.5, 8)), Verdict::Tie);
    EXPECT_EQ(results::verdict(rec(1.0, 0.8, 1.4, 8), rec(2.0, 1.5, 2.5, 8)), Verdict::Win);
    EXPECT_EQ(results::verdict(det, rec(2.0, 2.0, 2.0, 1)), Verdict::Win);  // two single draws
    results::Record dark = det;
    dark.error.nmse = NAN;  // undefined: no verdict
    EXPECT_EQ(results::verdict(dark, rec(2.0, 1.5, 2.5, 8)), Verdict::Undefined);
    EXPECT_STREQ(results::verdictName(Verdict::Tie), "tie");
    EXPECT_STREQ(results::verdictName(Verdict::Undefined), "n/a");
}

TEST(ResultsSchema, TypedEqualTimeAndSeedsRoundTripAndNewerVersionsAreRefused)
{
    const fs::path dir = test::freshDir("results-schema");
    results::Results doc;
    results::Record r = rec(0.5, 0.25, 0.75, 8);
    r.equal_time_to = "cubature";
    r.n = 4;
    results::EqualTime et;
    et.label = "cubature";
    et.n = 4.25;
    et.method_ms = 1.0;
    et.partner_ms = 1.04;
    et.ratio = 1.04;
    et.tolerance = 0.1;
    et.ok = true;
    et.candidates = json::array({{{"n", 4}, {"ratio", 1.04}, {"ms", 1.04}}});
    r.equalTime = et;
    doc.records = {r};
    const std::string path = (dir / "results.json").string();
    results::save(path, doc);
    const json raw = json::parse(std::ifstream(path));
    EXPECT_EQ(raw["schema_version"], results::kResultsSchemaVersion);
    EXPECT_EQ(raw["records"][0]["equal_time"]["partner_ms"], 1.04);
    const results::Results back = results::load(path);
    ASSERT_EQ(back.records.size(), 1u);
    const results::Record& b = back.records[0];
    EXPECT_EQ(b.seeds, 8);
    EXPECT_EQ(b.ci95.at("nmse")[0], 0.25);
    ASSERT_TRUE(b.equalTime.has_value());
    EXPECT_EQ(b.equalTime->label, "cubature");
    EXPECT_EQ(b.equalTime->n, 4.25);
    EXPECT_EQ(b.equalTime->partner_ms, 1.04);
    EXPECT_TRUE(b.equalTime->ok);
    EXPECT_EQ(b.equalTime->candidates, et.candidates);
    // A document of a later version is refused, naming the version.
    json later = raw;
    later["schema_version"] = results::kResultsSchemaVersion + 1;
    std::ofstream(dir / "later.json") << later.dump();
    try {
        results::load((dir / "later.json").string());
        ADD_FAILURE() << "a later schema_version was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("schema_version"), std::string::npos) << e.what();
    }
    // A mistyped field of the typed result is an error, not a silent false.
    json bad = raw;
    bad["records"][0]["equal_time"]["ok"] = "yes";
    std::ofstream(dir / "bad.json") << bad.dump();
    EXPECT_THROW(results::load((dir / "bad.json").string()), InputError);
    // A version 1 record (flat equal_time_* keys) reads into the same typed result.
    json v1 = raw;
    v1.erase("schema_version");
    json& r1 = v1["records"][0];
    r1.erase("equal_time");
    r1["equal_time_label"] = "cubature";
    r1["equal_time_ratio"] = 0.97;
    r1["equal_time_ok"] = true;
    r1["equal_time_target_ms"] = 2.0;
    std::ofstream(dir / "v1.json") << v1.dump();
    const results::Results old = results::load((dir / "v1.json").string());
    ASSERT_TRUE(old.records[0].equalTime.has_value());
    EXPECT_EQ(old.records[0].equalTime->ratio, 0.97);
    EXPECT_TRUE(old.records[0].equalTime->ok);
    EXPECT_EQ(old.records[0].equalTime->method_ms, 2.0);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace lb
