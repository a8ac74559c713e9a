// The report of a results directory: results.csv (and pandas reading it), the
// stitched-rotation tables, and report.html opened in a real browser
// (headless Chromium) with two views told apart by their screenshots.
#include "experiments/report.h"
#include "experiments/results.h"
#include "metrics/image.h"
#include "metrics/png.h"
#include "metrics/tonemap.h"
#include "testutil.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

namespace lb {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using results::Record;

std::string slurp(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int sh(const std::string& cmd)
{
    int st = std::system(cmd.c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

// The Python the README sets up (scripts/install-deps.sh: .venv of the
// source tree), else /usr/bin/python3.
std::string venvPython()
{
    const std::string venv = test::sourceDir() + "/.venv/bin/python";
    return access(venv.c_str(), X_OK) == 0 ? venv : "/usr/bin/python3";
}

struct Report : ::testing::Test {
    fs::path dir;
    void SetUp() override
    {
        dir = fs::temp_directory_path() /
            ("lb_report_" + std::to_string(getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
};

// A record of scene `scene` with the errors of `test` against `ref`.
Record rec(const std::string& spec, const std::string& role, double rotation, const Image& ref, const Image& test)
{
    Record r;
    r.method = spec.substr(0, spec.find(':'));
    r.params = r.method == "mc" ? json{{"n", 4}, {"pattern", "poisson"}} : json{{"triangulation", "fan"}};
    r.luminaire = "A, \"quoted\".ldt";  // a comma and quotes: the CSV must quote it
    r.height = 1.1;
    r.rotation = rotation;
    r.res = ref.width;
    r.precision = "float";
    r.device = "dev";
    r.driver = "drv";
    r.time_ms = {2.5, 2.25, 3.0, 5, 128};
    r.error = metrics::compare(ref, test);
    r.extra["spec"] = spec;
    r.extra["role"] = role;
    r.extra["scene"] = "S" + std::to_string(int(rotation * 100));
    if (role == "equal_time") {
        r.equal_time_to = "cubature";
        r.n = 4;
        results::EqualTime et;
        et.label = "cubature";
        et.ratio = 1.02;
        et.ok = true;
        r.equalTime = et;
    }
    return r;
}

Image ramp(int n, double scale)
{
    Image im(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) im.at(y, x) = scale * (1 + x + 3 * y + (x == n / 2 && y == n / 2 ? 40 : 0));
    return im;
}

// results.csv: one tidy row per record: unit-suffixed columns, a series to
// group by, one n, the partner's matched method as its short label and its
// verdict, the parameters in one canonical `spec` column (no param_*),
// booleans that pandas reads as bool; odd strings quoted; pandas reads it back.
TEST_F(Report, CsvHasOneFlatRowPerRecordAndLoadsWithPandas)
{
    Image ref = ramp(8, 1), a = ramp(8, 1.25);
    results::Results doc;
    doc.records = {rec("cubature", "method", 1.5, ref, a), rec("mc:n=4", "equal_time", 1.5, ref, ramp(8, 0.5)),
                   rec("mc:n=4", "mci_curve", 1.5, ref, ramp(8, 0.75))};
    doc.records[0].extra["stats"] = {{"form", "straight-line"}};  // objects stay out of the table
    doc.records[1].seeds = 8;  // a mean over seeds: its interval goes to results_long.csv
    doc.records[1].ci95["nmse"] = {0.25, 0.75};
    doc.records[1].error.flip = NAN;  // undefined: an empty field
    // the canonical SPEC stays in the JSON; the CSV names the method by its label
    doc.records[1].equal_time_to = "cubature:radiance=cubature,triangulation=fan,order=3";
    doc.records[1].equalTime->n = 4.25;  // N + extra: the CSV's n
    doc.records[0].sceneKeys = {{"scene_kind", "specular"}, {"alpha", 0.25}, {"eye", {0, 4, 2}}};  // columns too
    const std::string csv = results::toCsv(doc);
    const std::string head = csv.substr(0, csv.find('\n'));
    EXPECT_EQ(head.rfind("role,series,method,spec,baseline,baseline_spec,equal_time_label,verdict,verdict_flip,"
                         "off_time,scene,luminaire,luminaire_name,height_m,rotation_rad,res,precision,device,driver,"
                         "time_ms_median,time_ms_min,time_ms_max,time_ms_reps,time_ms_res,time_ms_cv,",
                         0),
              0u)
        << head;
    for (const char* c : {",nmse,", ",flip,", ",grad_nmse,", ",ueb,", ",leb,", ",mean_ref,", ",mean_test,", ",unit,",
                          ",n,", ",equal_time_ratio,", ",scene_kind,", ",alpha,", ",eye", ",seeds,", ",time_ms_cv,"})
        EXPECT_NE((head + ",").find(c), std::string::npos) << c << " in " << head;
    for (const char* c : {"stats", "param", ",height,", ",equal_time_to,", "ci95", "series,series"})
        EXPECT_EQ(head.find(c), std::string::npos) << c << " in " << head;
    EXPECT_EQ(csv.find("radiance=cubature"), std::string::npos) << "the partner's method by its label: " << csv;
    EXPECT_NE(csv.find("\"A, \"\"quoted\"\".ldt\""), std::string::npos) << csv;
    EXPECT_NE(csv.find(",\"[0,4,2]\""), std::string::npos) << csv;  // a short list: its JSON text
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);

    // written beside results.json by saveCsv with results_long.csv; pandas reads them
    const std::string jsonPath = (dir / "results.json").string();
    results::save(jsonPath, doc);
    results::saveCsv(jsonPath, doc);
    ASSERT_TRUE(fs::exists(dir / "results.csv"));
    EXPECT_EQ(slurp(dir / "results.csv"), csv);
    EXPECT_EQ(slurp(dir / "results_long.csv"), results::toLongCsv(doc));
    const std::string py = venvPython();
    if (sh(py + " -c 'import pandas' 2>/dev/null") != 0)
        GTEST_SKIP() << py << " has no pandas (scripts/install-deps.sh installs python3-pandas)";
    std::ofstream(dir / "check.py") << R"PY(
import json, math, sys
import pandas as pd
df = pd.read_csv(sys.argv[1])
assert len(df) == 3, len(df)
assert list(df["role"]) == ["method", "equal_time", "mci_curve"], list(df["role"])
assert list(df["series"]) == ["cubature", "MCI=cubature", "MCI curve"], list(df["series"])
assert list(df["method"]) == ["cubature", "mc", "mc"], list(df["method"])
assert df["spec"][0] == "cubature:triangulation=fan", df["spec"][0]  # no cubature on the specular scene: as recorded
assert df["luminaire"][0] == 'A, "quoted".ldt', df["luminaire"][0]
assert df["nmse"].dtype.kind == "f" and (df["nmse"] > 0).all()
assert df["unit"].tolist() == ["cd_m2", "lux", "lux"], df["unit"].tolist()
assert df["ueb"].dtype.kind == "f" and df["height_m"][0] == 1.1 and df["rotation_rad"][0] == 1.5
assert df["time_ms_median"][1] == 2.5 and df["time_ms_res"][0] == 128
assert math.isnan(df["flip"][1])
assert math.isnan(df["n"][0]) and df["n"][1] == 4.25 and df["n"][2] == 4, list(df["n"])
assert df["equal_time_label"][1] == "cubature"
assert pd.isna(df["verdict"][1])  # "n/a" (pandas reads NaN): the method's record is at another scene, unpaired
assert df["equal_time_ratio"][1] == 1.02
assert df["seeds"].tolist() == [1, 8, 1]
assert df["scene_kind"][0] == "specular" and df["alpha"][0] == 0.25 and df["eye"][0] == "[0,4,2]"
lng = pd.read_csv(sys.argv[2])
row = lng[(lng.record == 1) & (lng.metric == "nmse")]
assert row["lo"].tolist() == [0.25] and row["hi"].tolist() == [0.75], row
assert len(lng) == 3 * 7, len(lng)
print("pandas ok", df.shape)
)PY";
    EXPECT_EQ(sh(py + " " + (dir / "check.py").string() + " " + (dir / "results.csv").string() + " " +
                 (dir / "results_long.csv").string()),
              0);
}

// The python blocks of docs/experiments.md's "Results as a table" (a pivot
// of the verdicts by method and baseline, a seaborn relplot) run with the
// interpreter the README sets up (.venv/bin/python) on a CSV of hand-made
// records, as out/main/results.csv, so the documented examples keep working.
TEST_F(Report, DocExamplesRunOnTheCsv)
{
    const std::string md = slurp(fs::path(test::sourceDir()) / "docs" / "experiments.md");
    const size_t from = md.find("**Results as a table.**"), to = md.find("**Equal time**", from);
    ASSERT_NE(from, std::string::npos);
    ASSERT_NE(to, std::string::npos);
    std::vector<std::string> blocks;
    for (size_t p = md.find("```python\n", from); p < to; p = md.find("```python\n", p)) {
        const size_t b = p + 10, e = md.find("```", b);
        ASSERT_NE(e, std::string::npos);
        blocks.push_back(md.substr(b, e - b));
        p = e + 3;
    }
    ASSERT_EQ(blocks.size(), 2u) << "a pivot and a seaborn example";
    EXPECT_LE(std::count(blocks[0].begin(), blocks[0].end(), '\n'), 5) << "five lines: " << blocks[0];
    const std::string py = venvPython();
    if (sh(py + " -c 'import pandas' 2>/dev/null") != 0)
        GTEST_SKIP() << py << " has no pandas (scripts/install-deps.sh installs python3-pandas)";
    Image ref = ramp(8, 1);
    results::Results doc;
    doc.records = {rec("cubature", "method", 1.5, ref, ramp(8, 1.25)),
                   rec("mc:n=4", "equal_time", 1.5, ref, ramp(8, 0.5)),
                   rec("mc:n=4", "mci_curve", 1.5, ref, ramp(8, 0.75))};
    doc.records[1].extra["scene"] = doc.records[0].extra["scene"];  // the method's partner
    doc.records[1].baseline = results::BaselineRef{"strong MC", "mc:domain=solid"};
    doc.records[2].baseline = doc.records[1].baseline;
    fs::create_directories(dir / "out" / "main");
    std::ofstream(dir / "out" / "main" / "results.csv") << results::toCsv(doc);
    // MC at 0.5 x the reference has the larger error: cubature wins its one pair
    std::ofstream(dir / "pivot.py") << blocks[0] << "assert table.loc['cubature', ('strong MC', 'win')] == 1, table\n";
    EXPECT_EQ(sh("cd " + dir.string() + " && " + py + " pivot.py"), 0) << blocks[0];
    if (sh(py + " -c 'import seaborn' 2>/dev/null") != 0)
        GTEST_SKIP() << "/usr/bin/python3 has no seaborn (Debian: apt-get install python3-seaborn; "
                        "scripts/install-deps.sh installs it); the pivot example ran";
    std::ofstream(dir / "relplot.py") << blocks[1];
    EXPECT_EQ(sh("cd " + dir.string() + " && MPLBACKEND=Agg " + py + " relplot.py"), 0) << blocks[1];
    EXPECT_TRUE(fs::exists(dir / "nmse_time.png"));
}

// The report's main table is the NMSE of the rotations stitched into one
// image (metrics::pooled), not the mean of the rotations' NMSE: a nearly dark
// rotation with a large NMSE but tiny squared errors does not dominate it.
TEST_F(Report, MainTableStitchesTheRotations)
{
    // rotation 1: bright, 10 % off everywhere: NMSE = 0.01 / 1.1
    // rotation 2: nearly dark (1e-3 of the light), 100 % off: NMSE = 1 / 2
    Image bright(4, 4, 100.0), brightTest(4, 4, 110.0), dark(4, 4, 0.1), darkTest(4, 4, 0.2);
    results::Results doc;
    doc.records = {rec("cubature", "method", 1.5, bright, brightTest), rec("cubature", "method", 3.0, dark, darkTest)};
    results::save((dir / "results.json").string(), doc);
    experiments::writeReport(dir.string(), "test");
    const std::string md = slurp(dir / "report.md");
    // stitched: SSE = 16 (100 + 0.01), P = 32, means 50.05 and 55.1:
    // (1600.16 / 32) / (50.05 * 55.1) = 1.81324e-2; the mean of the two NMSE would be 0.2545
    const double want = (16 * (100.0 + 0.01) / 32) / (50.05 * 55.1);
    EXPECT_NE(md.find(fmt::format("| {:.3e} |", want)), std::string::npos) << want << "\n" << md;
    EXPECT_EQ(md.find("2.545e-01"), std::string::npos) << md;
    EXPECT_NE(md.find("rotations stitched"), std::string::npos) << md;
}

// Pixels of two screenshots that differ.
size_t differing(const tonemap::Picture& a, const tonemap::Picture& b)
{
    if (a.width != b.width || a.height != b.height) return size_t(-1);
    size_t n = 0;
    for (size_t i = 0; i < a.px.size(); ++i) n += !(a.px[i] == b.px[i]);
    return n;
}

// DIR/results.json of one scene (S150): cubature and its MCI partner, and
// their pictures in DIR/images/S150 (returned) as the runner saves them.
fs::path writeScene(const fs::path& dir, const json& context, const Image& ref, const Image& method, const Image& mci)
{
    results::Results doc;
    doc.context = context;
    doc.records = {rec("cubature", "method", 1.5, ref, method), rec("mc:n=4", "equal_time", 1.5, ref, mci)};
    results::save((dir / "results.json").string(), doc);
    const fs::path img = dir / "images" / "S150";
    fs::create_directories(img);
    writeExr((img / "reference.exr").string(), ref);
    writeExr((img / "cubature.exr").string(), method);
    writeExr((img / "mci_eq_cubature.exr").string(), mci);
    return img;
}

// The browser found on PATH, or "" (the browser parts are then skipped).
std::string chromium()
{
    for (const char* c : {"chromium", "chromium-browser", "google-chrome"})
        if (sh(std::string("command -v ") + c + " >/dev/null 2>&1") == 0) return c;
    return "";
}

// report.html: self-contained (no URL outside the file), tables and viewer
// data inline; opened in headless Chromium at two fragments the picture
// differs (the fragment goes through the same show() as keys and clicks).
TEST_F(Report, HtmlIsSelfContainedAndSwitchesViewsInChromium)
{
    const int n = 16;
    Image ref = ramp(n, 1), method(n, n), mci(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            method.at(y, x) = 1.3 * ref.at(y, x);
            mci.at(y, x) = ref.at(y, x) * (((x + y) & 1) ? 0.2 : 1.8);  // noisy: a checkerboard
        }
    const fs::path img = writeScene(
        dir, {{"device", "dev"}, {"commit", "abc123"}, {"date", "2026-11-30T00:00:00Z"}, {"experiment", "t"}}, ref,
        method, mci);
    writePng((img / "cubature_err.png").string(), tonemap::errorPicture(ref, method, 20, 1));
    writePng((img / "mci_eq_cubature_err.png").string(), tonemap::errorPicture(ref, mci, 20, 20));
    experiments::writeReport(dir.string(), "test");

    const std::string html = slurp(dir / "report.html");
    for (const char* s : {"abc123", "2026-11-30T00:00:00Z", "class=\"sortable\"", "rotations stitched", "id=\"lbdata\"",
                          "id=\"lbCanvas\"", "function show("})
        EXPECT_NE(html.find(s), std::string::npos) << s;
    // nothing fetched: no http(s) URL in a src or href, no external script or style
    for (const char* s : {"src=\"http", "href=\"http", "src=\"//", "<link", "@import", "fetch("})
        EXPECT_EQ(html.find(s), std::string::npos) << s;

    const std::string found = chromium();
    if (found.empty())
        GTEST_SKIP() << "no Chromium on this machine (Debian: apt-get install chromium; scripts/install-deps.sh "
                        "installs it): the browser part of this test is skipped";
    fs::path profile = dir / "chromium-profile";
    auto shot = [&](const std::string& fragment) {
        fs::path out = dir / ("shot_" + std::to_string(std::hash<std::string>{}(fragment)) + ".png");
        std::string cmd = fmt::format(
            "timeout 120 {} --headless --disable-gpu {} --user-data-dir='{}' --hide-scrollbars --window-size=1000,1500 "
            "--virtual-time-budget=3000 --screenshot='{}' 'file://{}#{}' >'{}/chromium.log' 2>&1",
            found, getuid() == 0 ? "--no-sandbox" : "", profile.string(), out.string(),
            fs::absolute(dir / "report.html").string(), fragment, dir.string());
        EXPECT_EQ(sh(cmd), 0) << cmd << "\n" << slurp(dir / "chromium.log");
        EXPECT_TRUE(fs::exists(out)) << cmd << "\n" << slurp(dir / "chromium.log");
        return fs::exists(out) ? readPng(out.string()) : tonemap::Picture{};
    };
    tonemap::Picture r = shot("view=reference"), m = shot("view=mci"), e = shot("view=error"),
                     z = shot("view=reference&zoom=4"), x = shot("view=reference&exposure=3");
    ASSERT_GT(r.width, 0);
    // not blank: many colours (the ramp's greys at least)
    std::set<int> colours;
    for (const auto& p : r.px) colours.insert(p.r << 16 | p.g << 8 | p.b);
    EXPECT_GT(colours.size(), 40u);
    // The canvas is 512 x 512 screen pixels; the caption's text changes a few
    // thousand: switching the picture must change far more than that.
    const size_t kCaption = 20000;
    EXPECT_GT(differing(r, m), kCaption) << "reference and MCI look alike";
    EXPECT_GT(differing(r, e), kCaption) << "reference and error picture look alike";
    EXPECT_GT(differing(r, z), kCaption) << "zoom changed nothing";
    EXPECT_GT(differing(r, x), kCaption) << "exposure changed nothing";
    // the same fragment twice: the same picture (the comparison can tell)
    EXPECT_EQ(differing(r, shot("view=reference")), 0u);
}

}  // namespace
}  // namespace lb

namespace lb {
namespace {

size_t near(const tonemap::Picture& p, tonemap::Rgb8 c, int tol)
{
    size_t n = 0;
    for (const auto& q : p.px)
        n += std::abs(q.r - c.r) <= tol && std::abs(q.g - c.g) <= tol && std::abs(q.b - c.b) <= tol;
    return n;
}

// One error scale per scene: the method's error of +1 lx and MCI's of +-4 lx
// are drawn on one bound (4 lx: the largest 99.9th percentile of |error|),
// in the viewer and in images/ (the runner wrote the method's at its own
// extremes, full orange); the viewer's colour bar says +-4 lx and +-40 % of
// the reference mean 10 lx.
TEST_F(Report, ErrorPicturesShareOneBoundPerSceneWithAColourBar)
{
    const int n = 16;
    Image ref(n, n, 10.0), method(n, n, 11.0), mci(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) mci.at(y, x) = ((x + y) & 1) ? 6.0 : 14.0;
    const fs::path img = writeScene(dir, {{"experiment", "t"}}, ref, method, mci);
    writePng((img / "cubature_err.png").string(), tonemap::errorPicture(ref, method, 1, 0));  // as the runner
    std::ofstream(img / "cubature.json") << R"({"nmse": 0.01, "k": 0.1})";
    experiments::writeReport(dir.string(), "test");

    const tonemap::Rgb8 pale = tonemap::errorColour(1.0, 4.0, 4.0);
    EXPECT_EQ(readPng((img / "cubature_err.png").string()).at(3, 3), pale);
    EXPECT_EQ(readPng((img / "mci_eq_cubature_err.png").string()).at(0, 0), tonemap::kOrange);
    const json j = json::parse(slurp(img / "cubature.json"));
    EXPECT_EQ(j["bound"].get<double>(), 4.0);
    EXPECT_EQ(j["mean_ref"].get<double>(), 10.0);
    EXPECT_EQ(j["nmse"].get<double>(), 0.01);  // the runner's keys kept
    EXPECT_EQ(j["colour_bar"].size(), 33u);

    const std::string browser = chromium();
    if (browser.empty()) GTEST_SKIP() << "no Chromium on this machine: the browser part of this test is skipped";
    const std::string page = fs::absolute(dir / "report.html").string();
    const std::string common =
        fmt::format("timeout 120 {} --headless --disable-gpu {} --user-data-dir='{}' "
                    "--hide-scrollbars --window-size=1000,1500 --virtual-time-budget=3000",
                    browser, getuid() == 0 ? "--no-sandbox" : "", (dir / "chromium-profile").string());
    ASSERT_EQ(sh(fmt::format("{} --dump-dom 'file://{}#view=error' > '{}' 2>/dev/null", common, page,
                             (dir / "dom.html").string())),
              0);
    const std::string dom = slurp(dir / "dom.html");
    for (const char* s : {"+4 lx", "\u22124 lx", "+2 lx", "0 lx", "+40 %", "\u221240 %",
                          "shared by every method and MCI: \u00b14 lx = \u00b140 % of the reference mean 10 lx"})
        EXPECT_NE(dom.find(s), std::string::npos) << s;
    EXPECT_EQ(dom.find("id=\"lbBar\" class=\"off\""), std::string::npos) << "the bar is hidden on the error view";
    auto shot = [&](const std::string& fragment) {
        fs::path out = dir / ("shot_" + std::to_string(std::hash<std::string>{}(fragment)) + ".png");
        EXPECT_EQ(sh(fmt::format("{} --screenshot='{}' 'file://{}#{}' >/dev/null 2>&1", common, out.string(), page,
                                 fragment)),
                  0);
        return fs::exists(out) ? readPng(out.string()) : tonemap::Picture{};
    };
    // The 512 x 512 canvas: the method's error in the pale orange of +1 of 4,
    // not the full orange of its own extremes; MCI's at the full colours.
    const tonemap::Picture e = shot("view=error"), m = shot("view=mci_error");
    EXPECT_GT(near(e, pale, 2), 200000u);
    EXPECT_LT(near(e, tonemap::kOrange, 2), 20000u);
    EXPECT_GT(near(m, tonemap::kOrange, 2), 100000u);
    EXPECT_GT(near(m, tonemap::kBlue, 2), 100000u);
}

// The report step says what it does, stage by stage, on stderr.
TEST_F(Report, ReportStepPrintsAProgressLinePerStage)
{
    Image ref(4, 4, 1.0);
    results::Results doc;
    doc.context = {{"experiment", "t"}};
    doc.records = {rec("cubature", "method", 1.5, ref, ref)};
    results::save((dir / "results.json").string(), doc);
    const test::CliResult r = test::runCli("report '" + dir.string() + "' --no-plots");
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string tag = "[" + dir.filename().string() + "] report ";
    for (const std::string s : {"1/3: error pictures on one bound per scene", "3/3: report.md and report.html", "done"})
        EXPECT_NE(r.err.find(tag + s), std::string::npos) << s << "\n" << r.err;
    EXPECT_EQ(r.err.find("2/3"), std::string::npos) << "--no-plots: no plot stage\n" << r.err;
}

}  // namespace
}  // namespace lb

namespace lb {
namespace {

// A column names the unit of its values: records of one unit get ueb_lux
// (or ueb_cd_m2, the specular scene's luminance), ...; where the units mix,
// ueb, leb, mean_ref and mean_test have no suffix and a column `unit` says
// each row's; plots/results_io.py reads either back under the record's key.
TEST_F(Report, CsvColumnsNameTheUnitOfTheirValues)
{
    Image ref = ramp(4, 1), test = ramp(4, 1.5);
    Record diffuse = rec("cubature", "method", 1.5, ref, test), specular = rec("ltc", "method", 1.5, ref, test);
    specular.sceneKeys = {{"scene_kind", "specular"}, {"alpha", 0.1}};
    specular.error.ueb = 7.25;
    results::Results doc;
    doc.records = {diffuse, specular};
    const fs::path file = dir / "results.json";
    results::save(file.string(), doc);
    results::saveCsv(file.string(), doc);
    const std::string script = (dir / "t.py").string();
    std::ofstream(script) << fmt::format(R"(import csv, sys
sys.path.insert(0, "{}/plots")
from results_io import load_records
rows = list(csv.DictReader(open("{}/results.csv")))
assert [r["unit"] for r in rows] == ["lux", "cd_m2"], rows
for k in ("ueb", "leb", "mean_ref", "mean_test"):
    assert rows[0][k] != "" and rows[1][k] != "", (k, rows)
    assert k + "_lux" not in rows[0] and k + "_cd_m2" not in rows[0], rows[0]
assert float(rows[1]["ueb"]) == 7.25
a, b = load_records("{}/results.csv")
assert b["ueb"] == 7.25 and a["ueb"] > 0, (a["ueb"], b["ueb"])
assert isinstance(a["mean_ref"], float) and isinstance(b["mean_ref"], float)
)",
                                         test::sourceDir(), dir.string(), dir.string());
    int code = -1;
    const std::string out = test::shellOutput("/usr/bin/python3 " + script + " 2>&1", &code);
    EXPECT_EQ(code, 0) << out;
    // diffuse alone: the columns of before, no cd/m^2
    doc.records = {diffuse};
    const std::string csv = results::toCsv(doc);
    EXPECT_NE(csv.find("ueb_lux"), std::string::npos);
    EXPECT_EQ(csv.find("cd_m2"), std::string::npos);
    EXPECT_EQ(csv.find(",unit,"), std::string::npos);
    doc.records = {specular};  // specular alone: cd/m^2 in the names
    EXPECT_NE(results::toCsv(doc).find("ueb_cd_m2"), std::string::npos);
}

}  // namespace
}  // namespace lb
