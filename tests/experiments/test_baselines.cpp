// Several Monte Carlo baselines per experiment: the "mc" list and its errors,
// partners keyed by baseline, verdicts only at equal time (off-time pairs and
// their reasons), merge refusing what it would replace silently, results.csv
// in at most 45 columns with a verdict per pair, results_long.csv, and the
// report's verdict table and first sentence. Device-free: hand-made records.
#include "experiments/experiment.h"
#include "experiments/report.h"
#include "experiments/report_verdicts.h"
#include "experiments/results.h"
#include "methods/mc_denoise.h"
#include "methods/spec.h"
#include "util/error.h"

#include "../testutil.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace lb {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using results::Record;

const std::string kStrong = "mc:domain=solid,sequence=sobol";

std::string slurp(const fs::path& p)
{
    std::ifstream in(p);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

json experiment(const json& mc)
{
    return {{"name", "b"},
            {"luminaire_dir", (fs::path(test::sourceDir()) / "luminaires").string()},
            {"luminaires", {"lambert.ldt"}},
            {"heights", {1.1}},
            {"rotations", {"3pi/4"}},
            {"methods", {"point", "cubature"}},
            {"equal_time", {"cubature"}},
            {"mci_curve", {1, 4}},
            {"mc", mc},
            {"res", 8}};
}

experiments::Experiment load(const fs::path& dir, const json& mc)
{
    const fs::path p = dir / "e.json";
    std::ofstream(p) << experiment(mc).dump();
    return experiments::loadExperiment(p.string());
}

TEST(Baselines, McTakesASpecOrAListOfLabelledSpecs)
{
    const fs::path d = test::freshDir("baselines-parse");
    auto one = load(d, "mc");
    ASSERT_EQ(one.baselines.size(), 1u);
    EXPECT_EQ(one.baselines[0].label, "MCI");  // mc's defaults: the thesis' MCI
    auto list = load(d, json::array({"mc", "mc:paper=1", {{"label", "strong"}, {"spec", kStrong}}}));
    ASSERT_EQ(list.baselines.size(), 3u);
    EXPECT_EQ(list.baselines[1].label, "mc:paper=1");  // a bare SPEC other than the defaults: as written
    EXPECT_EQ(list.baselines[2].label, "strong");
    EXPECT_NE(list.baselines[2].canonical.find("domain=solid"), std::string::npos) << list.baselines[2].canonical;
    EXPECT_NE(list.baselines[2].canonical.find("sequence=sobol"), std::string::npos);
    EXPECT_EQ(list.baselines[2].at(4), kStrong + ",n=4");
    const std::string spec = results::baselineSpec(list.baselines[2].canonical);  // as records carry it
    EXPECT_EQ(spec.find(",n="), std::string::npos) << spec;  // the runner chooses N: not part of the baseline
    EXPECT_EQ(spec.find(",extra="), std::string::npos) << spec;
    EXPECT_NE(spec.find(",min_solid="), std::string::npos) << spec;  // a key ending in n is kept
    EXPECT_EQ(results::baselineSpec("mc:a=1,extra=0,n=24,z=2"), "mc:a=1,z=2");

    auto refused = [&](const json& mc, const std::string& part) {
        const std::string msg = test::inputErrorOf([&] { load(d, mc); });
        EXPECT_NE(msg.find("\"mc\""), std::string::npos) << msg;  // names the key
        EXPECT_NE(msg.find(part), std::string::npos) << msg;
    };
    refused(json::array(), "non-empty list");
    refused(json::array({"mc", {{"label", "MCI"}, {"spec", "mc:paper=1"}}}), "label 'MCI' given twice");
    refused(json::array({"mc", "mc:pattern=poisson"}), "same MC as an earlier baseline");  // the default, spelt out
    refused(json::array({"mc", "cubature"}), "expected an mc SPEC");
    refused(json::array({"mc", {{"label", "x"}}}), "entry 1: expected an mc SPEC or");
    refused(json::array({"mc", 3}), "entry 1");
    refused(json::array({{{"label", "a\tb"}, {"spec", "mc"}}}), "no tab");
    refused(json::array({"mc:n=4"}), "must not set n");
}

Record methodRec(const std::string& spec, double nmse, double ms, double h = 1.1)
{
    Record r;
    r.method = spec.substr(0, spec.find(':'));
    r.params = {{"triangulation", "fan"}};
    r.luminaire = "l.ldt";
    r.height = h;
    r.rotation = 2.356;
    r.res = 8;
    r.device = "dev";
    r.driver = "drv";
    r.time_ms = {ms, ms, ms, 5, 128, 0.01};
    r.error.nmse = nmse;
    r.error.flip = nmse;
    r.extra["spec"] = spec;
    r.extra["role"] = "method";
    r.extra["scene"] = "l_h" + std::to_string(h);
    return r;
}

// The partner of `method` against baseline (label, spec) at n samples with
// the paired ratio t MC / t method.
Record partnerRec(const std::string& method, const std::string& label, const std::string& spec, double nmse, long n,
                  double ratio, double h = 1.1)
{
    Record r = methodRec("mc", nmse, 1.0 * ratio, h);
    r.params = {{"n", n}};
    if (spec.find("solid") != std::string::npos) r.params["domain"] = "solid";
    r.extra["spec"] = spec + ",n=" + std::to_string(n);
    r.extra["role"] = "equal_time";
    r.equal_time_to = method;
    r.n = n;
    r.baseline = results::BaselineRef{label, spec};
    results::EqualTime et;
    et.label = method;
    et.n = double(n);
    et.ratio = ratio;
    et.method_ms = 1;
    et.partner_ms = ratio;
    et.tolerance = 0.15;
    et.ok = std::abs(ratio - 1) <= 0.15;
    r.equalTime = et;
    r.inputs = {{"mc", spec}};
    return r;
}

TEST(Baselines, PartnersOfTwoBaselinesAreTwoCellsAndOldFilesGetTheirs)
{
    Record a = partnerRec("cubature", "MCI", "mc", 1, 4, 1.0), b = partnerRec("cubature", "strong", kStrong, 1, 4, 1.0);
    EXPECT_NE(a.key(), b.key());
    Record relabelled = b;
    relabelled.baseline->label = "other name";
    EXPECT_EQ(relabelled.key(), b.key());  // the SPEC tells baselines apart, the label only names it

    // a record of a file written before baselines: its partner's inputs.mc names it
    json old = a;
    old.erase("baseline");
    old["inputs"] = {{"mc", methods::parseSpec("mc").canonical()}};
    Record back = old.get<Record>();
    ASSERT_TRUE(back.baseline);
    EXPECT_EQ(back.baseline->label, "MCI");
    // an old MC curve point: from its parameters without n
    json curve = methodRec("mc", 1, 1);
    curve["params"] = {{"n", 4}, {"domain", "solid"}, {"sequence", "sobol"}};
    curve["role"] = "mci_curve";
    Record c = curve.get<Record>();
    ASSERT_TRUE(c.baseline);
    EXPECT_NE(c.baseline->spec.find("domain=solid"), std::string::npos) << c.baseline->spec;
    EXPECT_EQ(c.baseline->spec.find("n=4"), std::string::npos) << c.baseline->spec;
    EXPECT_EQ(c.baseline->label, c.baseline->spec);  // not the thesis' MC: named by its SPEC
}

TEST(Baselines, OffTimePairsAreNoVerdictAndSayWhy)
{
    const Record m = methodRec("cubature", 1e-3, 1);
    // errors that would be a clear win, at 6.5x the time with N = 1: the floor
    const Record floor = partnerRec("cubature", "strong", kStrong, 1, 1, 6.5);
    EXPECT_EQ(results::verdict(m, floor), results::Verdict::OffTime);
    EXPECT_EQ(results::verdict(m, floor, "flip"), results::Verdict::OffTime);
    EXPECT_STREQ(results::verdictName(results::Verdict::OffTime), "off-time");
    EXPECT_EQ(results::offTimeClass(floor), "floor");
    EXPECT_NE(results::offTimeReason(floor).find("N = 1 floor exceeds the method's time"), std::string::npos);
    EXPECT_NE(results::offTimeReason(floor).find("6.5"), std::string::npos) << results::offTimeReason(floor);
    // N_eq = 2 by a hair, N = 1 timed slower than the tolerance too: still the floor
    Record two = partnerRec("cubature", "strong", kStrong, 1, 2, 30);
    two.equalTime->candidates = {{{"n", 1}, {"ratio", 30.5}, {"ms", 30.5}}, {{"n", 2}, {"ratio", 30}, {"ms", 30}}};
    EXPECT_EQ(results::offTimeClass(two), "floor");
    two.equalTime->candidates = {{{"n", 2}, {"ratio", 30}, {"ms", 30}}};
    EXPECT_EQ(results::offTimeClass(two), "unmatched");
    Record ceiling = partnerRec("cubature", "strong", kStrong, 1, 1L << 20, 0.5);
    EXPECT_EQ(results::offTimeClass(ceiling), "ceiling");
    Record step = partnerRec("cubature", "strong", kStrong, 1, 7, 1.3);
    step.equalTime->bracketed = true;
    EXPECT_EQ(results::offTimeClass(step), "step");
    step.equalTime->bracketed = false;
    EXPECT_EQ(results::offTimeClass(step), "unmatched");
    // below N = 1 (mc's scale): the floor is the least scale, and no step
    Record scaled = partnerRec("cubature", "strong", kStrong, 1, 1, 1.3);
    scaled.equalTime->scale = 0.4;
    scaled.equalTime->bracketed = true;
    scaled.equalTime->candidates = {{{"n", 1}, {"ratio", 4}, {"ms", 4}},
                                    {{"n", 1}, {"scale", 0.5}, {"ratio", 1.5}, {"ms", 1.5}},
                                    {{"n", 1}, {"scale", 0.4}, {"ratio", 1.3}, {"ms", 1.3}}};
    EXPECT_EQ(results::offTimeClass(scaled), "unmatched");
    EXPECT_NE(results::offTimeReason(scaled).find("no scale within"), std::string::npos);
    scaled.equalTime->scale = methods::kMinScale;
    scaled.equalTime->candidates.push_back({{"n", 1}, {"scale", methods::kMinScale}, {"ratio", 1.3}, {"ms", 1.3}});
    EXPECT_EQ(results::offTimeClass(scaled), "floor");
    EXPECT_NE(results::offTimeReason(scaled).find("scale = 0.05 floor"), std::string::npos);
    // inside the tolerance (0.15): a verdict, and no reason
    const Record on = partnerRec("cubature", "strong", kStrong, 1, 4, 1.14);
    EXPECT_EQ(results::verdict(m, on), results::Verdict::Win);
    EXPECT_EQ(results::offTimeReason(on), "");
}

// Three scenes, two baselines: against MCI cubature wins 2 at equal time and
// one pair is off-time (the floor); against strong it wins 1 and loses 2.
results::Results twoBaselines()
{
    results::Results doc;
    doc.context = {{"device", "Test CPU"},
                   {"experiment", "b"},
                   {"commit", "abc"},
                   {"baselines", {{{"label", "MCI"}, {"spec", "mc"}}, {{"label", "strong"}, {"spec", kStrong}}}}};
    for (double h : {0.1, 1.1, 5.1}) {
        doc.records.push_back(methodRec("cubature", 1e-3, 1, h));
        doc.records.push_back(partnerRec("cubature", "MCI", "mc", 1e-2, h == 5.1 ? 1 : 8, h == 5.1 ? 3.0 : 1.05, h));
        doc.records.push_back(partnerRec("cubature", "strong", kStrong, h == 0.1 ? 1e-2 : 1e-4, 4, 0.95, h));
    }
    return doc;
}

TEST(Baselines, VerdictTableCountsOnlyPairsAtEqualTime)
{
    const results::Results doc = twoBaselines();
    const experiments::Tallies t = experiments::tallyPairs(doc);
    ASSERT_EQ(t.methods, std::vector<std::string>{"cubature"});
    ASSERT_EQ(t.baselines, (std::vector<std::string>{"MCI", "strong"}));
    const auto& mci = t.by.at("cubature").at("MCI");
    EXPECT_EQ(mci.nmse.win, 2);
    EXPECT_EQ(mci.nmse.onTime(), 2);  // the off-time pair is no win although its error is 10x
    EXPECT_EQ(mci.offTime, 1);
    EXPECT_EQ(mci.offTimeBy.at("floor"), 1);
    const auto& strong = t.by.at("cubature").at("strong");
    EXPECT_EQ(strong.nmse.win, 1);
    EXPECT_EQ(strong.nmse.loss, 2);
    EXPECT_EQ(strong.flip.loss, 2);
    // the methods fare worst against strong: geometric mean 10^((-1+1+1)/3) > MCI's 0.1
    EXPECT_EQ(experiments::strongestBaseline(t), "strong");
    const experiments::VerdictReport v = experiments::verdictReport(doc, {});
    EXPECT_NE(v.headline.find("`cubature` wins 1, ties 0 and loses 2 of its 3 pairs against the strongest Monte "
                              "Carlo here, strong"),
              std::string::npos)
        << v.headline;
    EXPECT_NE(v.headline.find("5 of the 6 pairs"), std::string::npos) << v.headline;
    EXPECT_NE(v.headline.find("1 off-time"), std::string::npos) << v.headline;
    EXPECT_NE(v.headline.find("Test CPU"), std::string::npos) << v.headline;
    ASSERT_EQ(v.verdicts.rows.size(), 1u);
    ASSERT_EQ(v.verdicts.head.size(), 1u + 2 * 4);  // method, then 4 columns per baseline
    EXPECT_EQ(v.verdicts.rows[0][1].text, "2 / 0 / 0");  // MCI: NMSE
    EXPECT_EQ(v.verdicts.rows[0][3].text, "1");  // MCI: off-time
    EXPECT_EQ(v.verdicts.rows[0][5].text, "1 / 0 / 2");  // strong: NMSE
    ASSERT_EQ(v.details.rows.size(), 2u);
    EXPECT_NE(v.details.rows[0][3].text.find("1 MC's floor (N = 1, or its least scale) exceeds"), std::string::npos);
}

TEST(Baselines, CsvHasAVerdictPerPairInAtMost45Columns)
{
    results::Results doc = twoBaselines();
    // the widest case: every scene kind's keys and both units, seeds with intervals
    Record spec = methodRec("cubature", 1, 1);
    spec.sceneKeys = {{"scene_kind", "specular"}, {"alpha", 0.25}, {"eye", {0, 4, 2}}};
    Record ind = methodRec("cubature", 1, 1);
    ind.sceneKeys = {{"scene_kind", "indirect"}, {"albedo", 0.5}};
    Record disk = methodRec("cubature", 1, 1);
    disk.sceneKeys = {{"shape", "disk"}, {"size", {0.08, 0.08}}};
    doc.records.insert(doc.records.end(), {spec, ind, disk});
    doc.records[1].seeds = 8;
    doc.records[1].ci95["nmse"] = {0.005, 0.015};
    const std::string csv = results::toCsv(doc);
    const std::string head = csv.substr(0, csv.find('\n'));
    const size_t columns = std::count(head.begin(), head.end(), ',') + 1;
    EXPECT_LE(columns, results::kMaxCsvColumns) << head;
    EXPECT_GE(columns, 40u) << head;  // the fixed columns are there: a test of an empty header cannot pass
    for (const char* c : {"verdict", "verdict_flip", "off_time", "baseline", "baseline_spec", "spec", "unit",
                          "scene_kind", "albedo", "shape", "size"})
        EXPECT_NE(("," + head + ",").find(std::string(",") + c + ","), std::string::npos) << c << " in " << head;
    EXPECT_EQ(head.find("param_"), std::string::npos) << head;
    EXPECT_EQ(head.find("ci95"), std::string::npos) << "intervals are in results_long.csv: " << head;
    // partner rows: their baseline and verdicts; the full SPEC with the sampler, not mc:n=4
    EXPECT_NE(csv.find(",strong,"), std::string::npos);
    EXPECT_NE(csv.find(",off-time,off-time,\"MC's N = 1 floor exceeds"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",win,win,"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",loss,loss,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("domain=solid"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",\"cubature:area=none,"), std::string::npos) << "every parameter, the defaults too: " << csv;

    const std::string lng = results::toLongCsv(doc);
    EXPECT_EQ(lng.substr(0, lng.find('\n')), "record,metric,mean,lo,hi");
    EXPECT_EQ(size_t(std::count(lng.begin(), lng.end(), '\n')), 1 + doc.records.size() * 7);  // 7 metrics
    EXPECT_NE(lng.find("\n1,nmse,0.01,0.005,0.015\n"), std::string::npos) << lng.substr(0, 400);
}

TEST(Baselines, MergeKeepsBothBaselinesAndRefusesOtherRunsByName)
{
    const fs::path d = test::freshDir("baselines-merge");
    auto save = [&](const std::string& name, const json& context, std::vector<Record> recs) {
        results::save((d / name).string(), {context, std::move(recs)});
        return (d / name).string();
    };
    const json ctx = {{"experiment", "b"}, {"commit", "abc"}};
    const std::string a = save("a.json", ctx, {partnerRec("cubature", "MCI", "mc", 1, 4, 1)});
    const std::string b = save("b.json", ctx, {partnerRec("cubature", "strong", kStrong, 1, 4, 1)});
    results::MergeStats st;
    auto m = results::mergeResults({a, b}, &st);
    EXPECT_EQ(m.records.size(), 2u);  // two baselines: two partners, none replaced
    EXPECT_EQ(st.replaced, 0u);
    EXPECT_EQ(m.context["commits"], json::array({"abc", "abc"}));

    json other = ctx;
    other["commit"] = "def";
    const std::string c = save("c.json", other, {partnerRec("cubature", "MCI", "mc", 2, 5, 1)});
    std::string msg = test::inputErrorOf([&] { results::mergeResults({a, c}); });
    for (const std::string& part : std::vector<std::string>{"commit 'abc' in " + a, "'def' in " + c, "--force"})
        EXPECT_NE(msg.find(part), std::string::npos) << part << " in " << msg;
    other = ctx;
    other["experiment"] = "main";
    const std::string e = save("e.json", other, {});
    msg = test::inputErrorOf([&] { results::mergeResults({a, e}); });
    EXPECT_NE(msg.find("experiment 'b' in " + a), std::string::npos) << msg;

    // the same cell from other inputs: refused by name, or with force replaced and said
    Record changed = partnerRec("cubature", "MCI", "mc", 2, 5, 1);
    changed.inputs["kernel"] = "0123";
    const std::string f = save("f.json", ctx, {changed});
    msg = test::inputErrorOf([&] { results::mergeResults({a, f}); });
    for (const char* part : {"the partner of cubature against MCI", "computed from other inputs (kernel)"})
        EXPECT_NE(msg.find(part), std::string::npos) << part << " in " << msg;
    m = results::mergeResults({a, c, f}, &st, {true});
    ASSERT_EQ(m.records.size(), 1u);
    EXPECT_EQ(m.records[0].error.nmse, 2);  // the last input wins
    ASSERT_EQ(st.forced.size(), 2u);  // c's commit, and f's record replacing c's from other inputs
    EXPECT_EQ(m.context["commits"], json::array({"abc", "def", "abc"}));
}

// The report of two baselines: its first sentence, the verdict table with a
// column group per baseline, the scene of a disk named without "?", and run
// times relative to the first method where there is no `point`.
TEST(Baselines, ReportOpensWithTheSentenceAndTheTable)
{
    const fs::path d = test::freshDir("baselines-report");
    results::Results doc = twoBaselines();
    for (auto& r : doc.records) r.sceneKeys = {{"shape", "disk"}, {"size", {0.08, 0.08}}};
    results::save((d / "results.json").string(), doc);
    experiments::writeReport(d.string(), "test");
    const std::string md = slurp(d / "report.md");
    const size_t sentence = md.find("**At equal time on Test CPU"), table = md.find("## Verdicts at equal time");
    ASSERT_NE(sentence, std::string::npos) << md.substr(0, 2000);
    EXPECT_LT(sentence, table);  // the answer first
    EXPECT_NE(md.find("strong: NMSE W / T / L"), std::string::npos);
    EXPECT_NE(md.find("## Off-time pairs and losses"), std::string::npos);
    EXPECT_EQ(md.find("? shape"), std::string::npos);
    EXPECT_NE(md.find("disk 0.08 x 0.08 m"), std::string::npos);
    EXPECT_NE(md.find("relative to cubature"), std::string::npos);
    EXPECT_NE(md.find("| cubature | 1.0000 | 1.00 |"), std::string::npos) << md;
    const std::string html = slurp(d / "report.html");
    EXPECT_NE(html.find("<p class=\"headline\"><b>At equal time on Test CPU"), std::string::npos);
}

// A run with two baselines on the device (8 x 8, one scene): a curve and a
// partner per baseline, each naming its baseline; merge keeps two runs of
// other baselines apart and refuses one of another experiment unless forced.
TEST(Baselines, RunGivesAPartnerAndACurvePerBaselineAndMergeKeepsBoth)
{
    if (!test::runtime()) GTEST_SKIP() << "no OpenCL device";
    const fs::path d = test::freshDir("baselines-run");
    json e = experiment(json::array({"mc", {{"label", "strong"}, {"spec", kStrong}}}));
    e["time_res"] = 16;
    e["seeds"] = 2;
    std::ofstream(d / "e.json") << e.dump();
    auto r = test::runCli("run " + (d / "e.json").string() + " --out " + (d / "a").string() + " --no-report --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    const results::Results doc = results::load((d / "a" / "results.json").string());
    std::map<std::string, int> partners, curves;
    for (const auto& rec : doc.records) {
        if (rec.equal_time_to) {
            ASSERT_TRUE(rec.baseline);
            ++partners[rec.baseline->label];
            EXPECT_EQ(rec.extra["spec"].get<std::string>().rfind(rec.baseline->label == "strong" ? kStrong : "mc", 0),
                      0u)
                << rec.extra.dump();  // the baseline's SPEC at N, sampler and all
        } else if (rec.extra.value("role", "") == "mci_curve") {
            ASSERT_TRUE(rec.baseline);
            ++curves[rec.baseline->label];
        }
    }
    EXPECT_EQ(partners, (std::map<std::string, int>{{"MCI", 1}, {"strong", 1}}));
    EXPECT_EQ(curves, (std::map<std::string, int>{{"MCI", 2}, {"strong", 2}}));  // N = 1, 4 each
    const std::string csv = slurp(d / "a" / "results.csv");
    EXPECT_NE(csv.find(",strong=cubature,"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",strong curve,"), std::string::npos) << csv;

    // the same experiment with one baseline more, into another directory: merged, nothing replaced
    e["mc"] =
        json::array({"mc", {{"label", "strong"}, {"spec", kStrong}}, {{"label", "paper"}, {"spec", "mc:paper=1"}}});
    e["equal_time"] = json::array({"cubature"});
    std::ofstream(d / "e.json") << e.dump();
    r = test::runCli("run " + (d / "e.json").string() + " --out " + (d / "b").string() + " --no-report --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    r = test::runCli("merge --no-report --out " + (d / "m").string() + " " + (d / "a").string() + " " +
                     (d / "b").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(results::load((d / "m" / "results.json").string()).records.size(),
              results::load((d / "b" / "results.json").string()).records.size());  // b holds a's cells and more
    // another experiment's results: refused, naming both, exit 2; --force merges and says what
    results::Results other = results::load((d / "b" / "results.json").string());
    other.context["experiment"] = "other";
    fs::create_directories(d / "c");
    results::save((d / "c" / "results.json").string(), other);
    r = test::runCli("merge --no-report --out " + (d / "n").string() + " " + (d / "a").string() + " " +
                     (d / "c").string());
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("experiment 'b' in"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("'other' in"), std::string::npos) << r.err;
    r = test::runCli("merge --force --no-report --out " + (d / "n").string() + " " + (d / "a").string() + " " +
                     (d / "c").string());
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("merge --force: experiment 'b'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace lb
