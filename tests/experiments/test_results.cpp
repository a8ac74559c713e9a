// The results JSON document: round trip, atomic append, merge.
#include "experiments/report.h"
#include "experiments/results.h"
#include "testutil.h"
#include "util/error.h"
#include "util/fileio.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <string>

#include <sys/wait.h>
#include <sys/stat.h>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include "lb_build_config.h"

namespace lb {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using results::Record;

Record cell(const std::string& method, double height, double nmse)
{
    Record r;
    r.method = method;
    r.params = {{"n", 24}, {"sampler", "poisson"}};
    r.luminaire = "ARCOS.ldt";
    r.height = height;
    r.rotation = 3 * M_PI / 4;
    r.res = 256;
    r.precision = "float";
    r.device = "cpu-pocl";
    r.driver = "5.0";
    r.time_ms = {1.25, 1.125, 1.5, 5, 512};  // median, min, max, reps, timing res
    r.error.nmse = nmse;
    r.error.nrmse = 0.5;
    r.error.relmse = 0.03125;
    r.error.ueb = 160.25;
    r.error.leb = -8.4375;
    r.error.nonfinite = 0;
    r.error.pixels = 65536;
    r.error.mean_ref = 10;
    r.error.mean_test = 11;
    return r;
}

struct Scratch : ::testing::Test {
    fs::path dir;
    void SetUp() override
    {
        dir = fs::temp_directory_path() /
            ("lb_results_" + std::to_string(getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string file(const std::string& name) const { return (dir / name).string(); }
    // Files in dir other than results and lock files (i.e. left-over temporaries).
    int strays() const
    {
        int n = 0;
        for (auto& e : fs::directory_iterator(dir))
            if (e.path().string().find(".tmp.") != std::string::npos) ++n;
        return n;
    }
};

using Results = Scratch;

TEST_F(Results, RecordRoundTripKeepsEveryField)
{
    Record r = cell("mc", 0.1, 565.1048);
    r.equal_time_to = "cubature:triangulation=delaunay";
    r.n = 40;
    r.error.relmse = std::numeric_limits<double>::quiet_NaN();  // undefined: null in the file
    r.error.grad_nmse = 0.75;
    r.error.grad_pairs = 130560;
    r.error.flip = 0.1875;
    r.extra["shard"] = 3;  // a key this code does not know
    results::Results doc;
    doc.context = results::makeContext("cpu-pocl", "5.0");
    doc.records = {r, cell("cubature", 1.1, 27.9669)};  // flip not computed: NaN
    results::save(file("r.json"), doc);

    auto raw = json::parse(std::ifstream(file("r.json")));
    EXPECT_TRUE(raw["records"][0]["relmse"].is_null());
    for (const char* k : {"method",        "params", "luminaire", "height",    "rotation",   "res", "precision",
                          "time_ms",       "nmse",   "nrmse",     "relmse",    "ueb",        "leb", "nonfinite",
                          "equal_time_to", "n",      "device",    "grad_nmse", "grad_pairs", "flip"})
        EXPECT_TRUE(raw["records"][0].contains(k)) << k;
    EXPECT_TRUE(raw["records"][1]["flip"].is_null());  // not available: null, never 0
    EXPECT_FALSE(raw["records"][1].contains("equal_time_to"));  // optional fields only when set

    auto back = results::load(file("r.json"));
    ASSERT_EQ(back.records.size(), 2u);
    const Record& b = back.records[0];
    // JSON keeps 17 significant digits: every double comes back bit for bit.
    EXPECT_EQ(b.method, "mc");
    EXPECT_EQ(b.params, r.params);
    EXPECT_EQ(b.luminaire, "ARCOS.ldt");
    EXPECT_EQ(b.height, 0.1);
    EXPECT_EQ(b.rotation, 3 * M_PI / 4);
    EXPECT_EQ(b.res, 256);
    EXPECT_EQ(b.precision, "float");
    EXPECT_EQ(b.device, "cpu-pocl");
    EXPECT_EQ(b.driver, "5.0");
    EXPECT_EQ(b.time_ms.median, 1.25);
    EXPECT_EQ(b.time_ms.min, 1.125);
    EXPECT_EQ(b.time_ms.reps, 5);
    EXPECT_EQ(b.time_ms.max, 1.5);
    EXPECT_EQ(b.time_ms.res, 512);
    EXPECT_EQ(b.error.nmse, 565.1048);
    EXPECT_TRUE(std::isnan(b.error.relmse));
    EXPECT_EQ(b.error.ueb, 160.25);
    EXPECT_EQ(b.error.leb, -8.4375);
    EXPECT_EQ(b.error.pixels, 65536);
    EXPECT_EQ(b.error.grad_nmse, 0.75);
    EXPECT_EQ(b.error.grad_pairs, 130560);
    EXPECT_EQ(b.error.flip, 0.1875);
    EXPECT_TRUE(std::isnan(back.records[1].error.flip));
    EXPECT_FALSE(b.extra.contains("flip"));  // a known key, not an unknown one kept aside
    EXPECT_EQ(b.equal_time_to.value_or(""), "cubature:triangulation=delaunay");
    EXPECT_EQ(b.n.value_or(0), 40);
    EXPECT_EQ(b.extra["shard"], 3);
    EXPECT_EQ(b.key(), r.key());
    EXPECT_FALSE(back.records[1].equal_time_to.has_value());
    EXPECT_EQ(back.context["device"], "cpu-pocl");
    EXPECT_EQ(strays(), 0);
}

// Records of a runner that had no grad_nmse and flip load with both NaN, and
// the report says no record carries them instead of printing a table of gaps.
TEST_F(Results, OlderRecordsWithoutTheNewMetricsLoadAndReport)
{
    json rec = json(cell("mc", 0.1, 2.5));
    rec.erase("grad_nmse");
    rec.erase("grad_pairs");
    rec.erase("flip");
    std::ofstream(file("results.json")) << json{{"context", {{"device", "cpu-pocl"}}}, {"records", {rec}}}.dump();
    auto doc = results::load(file("results.json"));
    ASSERT_EQ(doc.records.size(), 1u);
    EXPECT_TRUE(std::isnan(doc.records[0].error.grad_nmse));
    EXPECT_TRUE(std::isnan(doc.records[0].error.flip));
    experiments::writeReport(dir.string(), "test");
    std::ifstream in(dir / "report.md");
    std::string report{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_NE(report.find("| ARCOS.ldt | float | 0.1 | 2.500e+00 |"), std::string::npos) << report;
    EXPECT_NE(report.find("No record carries grad_nmse"), std::string::npos) << report;
    EXPECT_NE(report.find("No record carries flip"), std::string::npos) << report;
}

TEST(ResultsContext, HasTheDocumentedKeys)
{
    auto c = results::makeContext("dev", "drv", {{"experiment", "smoke"}, {"driver", "override"}});
    EXPECT_EQ(c["device"], "dev");
    EXPECT_EQ(c["driver"], "override");  // extra keys win
    EXPECT_EQ(c["experiment"], "smoke");
    EXPECT_EQ(c["lumibench_version"], LB_VERSION);
    EXPECT_FALSE(c["host"].get<std::string>().empty());
    EXPECT_TRUE(std::regex_match(c["date"].get<std::string>(), std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")))
        << c["date"];
    const std::string commit = c["commit"];
    if (fs::exists(fs::path(LB_SOURCE_DIR) / ".git")) {
        // A checkout: the commit is a full SHA-1, and commit_dirty says whether the tree differs.
        EXPECT_TRUE(std::regex_match(commit, std::regex("[0-9a-f]{40}"))) << commit;
        EXPECT_TRUE(c["commit_dirty"].is_boolean());
    } else {
        EXPECT_EQ(commit, "unknown");
    }
}

TEST(ResultsKey, TellsCellsApart)
{
    Record a = cell("mc", 0.1, 1), b = a;
    b.error.nmse = 2;  // results are not part of the key
    b.time_ms.median = 9;
    EXPECT_EQ(a.key(), b.key());
    b.params = {{"sampler", "poisson"}, {"n", 24}};  // same object, other insertion order
    EXPECT_EQ(a.key(), b.key());
    for (auto change : {+[](Record& r) { r.params["n"] = 40; }, +[](Record& r) { r.height = 1.1; },
                        +[](Record& r) { r.rotation = M_PI; }, +[](Record& r) { r.precision = "double"; },
                        +[](Record& r) { r.res = 512; }, +[](Record& r) { r.luminaire = "x.ies"; },
                        +[](Record& r) { r.device = "gpu"; }, +[](Record& r) { r.equal_time_to = "cp"; },
                        +[](Record& r) { r.method = "point"; }}) {
        Record c = a;
        change(c);
        EXPECT_NE(a.key(), c.key()) << c.key();
    }
}

TEST_F(Results, AppendCreatesAddsAndReplacesByKey)
{
    const std::string p = file("run.json");
    results::appendRecord(p, results::makeContext("first", "1"), cell("mc", 0.1, 1.0));
    results::appendRecord(p, results::makeContext("second", "2"), cell("mc", 1.1, 2.0));
    auto d = results::load(p);
    ASSERT_EQ(d.records.size(), 2u);
    EXPECT_EQ(d.context["device"], "first");  // an existing file keeps its context
    // The same cell again (a re-run): replaced, not counted twice.
    results::appendRecord(p, results::makeContext("first", "1"), cell("mc", 0.1, 3.0));
    d = results::load(p);
    ASSERT_EQ(d.records.size(), 2u);
    EXPECT_EQ(d.records[0].error.nmse, 3.0);
    EXPECT_EQ(d.records[1].error.nmse, 2.0);
    EXPECT_EQ(strays(), 0);
}

// Appending does not rewrite the document: one journal line per record, so
// a run of n cells costs O(n), not O(n^2). The document of 2000 records stays
// untouched (same inode and size) by the next append; load sees all 2001.
TEST_F(Results, AppendWritesOneJournalLineNotTheDocument)
{
    const std::string p = file("big.json");
    results::Results doc{json{{"device", "x"}}, {}};
    for (int i = 0; i < 2000; ++i) doc.records.push_back(cell("mc", 0.001 * (i + 1), i));
    results::save(p, doc);
    struct stat before {};
    ASSERT_EQ(stat(p.c_str(), &before), 0);
    results::appendRecord(p, json::object(), cell("point", 0.1, 7.0));
    struct stat after {};
    ASSERT_EQ(stat(p.c_str(), &after), 0);
    EXPECT_EQ(before.st_ino, after.st_ino);
    EXPECT_EQ(before.st_size, after.st_size);
    const std::string journal = util::readFile(results::journalPath(p), "journal", 1 << 20);
    EXPECT_EQ(std::count(journal.begin(), journal.end(), '\n'), 1) << journal;  // no context line: the document has it
    auto d = results::load(p);
    ASSERT_EQ(d.records.size(), 2001u);
    EXPECT_EQ(d.records.back().method, "point");
    // compact folds it in: the document alone holds every record, the journal is gone
    results::compact(p, json::object());
    EXPECT_FALSE(fs::exists(results::journalPath(p)));
    EXPECT_EQ(json::parse(util::readFile(p, "results", 1 << 26))["records"].size(), 2001u);
    EXPECT_EQ(strays(), 0);
}

// The journal is folded into the document once it outgrows it (and 64 KiB):
// appends stay amortised O(1) and results.json is never far behind.
TEST_F(Results, JournalIsFoldedInOnceItOutgrowsTheDocument)
{
    const std::string p = file("grow.json");
    for (int i = 0; i < 400; ++i) results::appendRecord(p, json{{"device", "x"}}, cell("mc", 0.01 * (i + 1), i));
    ASSERT_TRUE(fs::exists(p));  // 400 lines of ~500 bytes exceed 64 KiB: folded in at least once
    const auto docBytes = fs::file_size(p);
    const auto journalBytes = fs::exists(results::journalPath(p)) ? fs::file_size(results::journalPath(p)) : 0;
    EXPECT_LE(journalBytes, std::max<uintmax_t>(64 << 10, docBytes) + 2048);
    auto d = results::load(p);
    EXPECT_EQ(d.records.size(), 400u);
    EXPECT_EQ(d.context["device"], "x");
}

// An append cut off by a crash or a full disk leaves a line without its
// newline: no record on load, cut off by the next append. A broken complete
// line is an error naming the journal and the line.
TEST_F(Results, CutOffJournalLineIsNoRecord)
{
    const std::string p = file("torn.json");
    results::appendRecord(p, json{{"device", "x"}}, cell("mc", 0.1, 1.0));
    results::appendRecord(p, json::object(), cell("mc", 1.1, 2.0));
    {
        std::ofstream j(results::journalPath(p), std::ios::app);
        j << "{\"record\": {\"method\": \"mc\", \"par";
    }
    auto d = results::load(p);
    ASSERT_EQ(d.records.size(), 2u);
    EXPECT_EQ(d.context["device"], "x");  // from the journal's context line: no document yet
    results::appendRecord(p, json::object(), cell("mc", 3.1, 3.0));
    d = results::load(p);
    ASSERT_EQ(d.records.size(), 3u);
    EXPECT_EQ(d.records[2].error.nmse, 3.0);
    {
        std::ofstream j(results::journalPath(p), std::ios::app);
        j << "{\"recor\": 1}\n";
    }
    std::string msg = test::inputErrorOf([&] { results::load(p); });
    EXPECT_NE(msg.find(results::journalPath(p) + ":5:"), std::string::npos) << msg;  // context, 3 records, then it
}

// A reader takes the shared lock: it waits while an appender holds the
// exclusive one (which may be folding the journal into the document), so it
// never reads the document before and the journal after a fold.
TEST_F(Results, LoadWaitsForAnAppendersLock)
{
    const std::string p = file("live.json");
    results::appendRecord(p, json{{"device", "x"}}, cell("mc", 0.1, 1.0));  // creates live.json.lock
    int ready[2];
    ASSERT_EQ(pipe(ready), 0);
    pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        int fd = ::open((p + ".lock").c_str(), O_RDWR);
        int rc = fd >= 0 && ::flock(fd, LOCK_EX) == 0 ? 0 : 1;
        char c = 'x';
        if (::write(ready[1], &c, 1) != 1) rc = 1;
        ::usleep(300000);  // hold it 0.3 s
        _exit(rc);
    }
    char c;
    ASSERT_EQ(::read(ready[0], &c, 1), 1);
    auto t0 = std::chrono::steady_clock::now();
    EXPECT_EQ(results::load(p).records.size(), 1u);
    double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    int st = 0;
    waitpid(pid, &st, 0);
    EXPECT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0);
    // the child holds the lock 0.3 s after signalling; without the lock load takes ~1 ms
    EXPECT_GE(waited, 0.2);
    ::close(ready[0]);
    ::close(ready[1]);
}

TEST_F(Results, ConcurrentAppendsLoseNothing)
{
    // Eight processes append one cell each at the same time; the lock must
    // serialise their read-modify-write so that all eight survive.
    const std::string p = file("shared.json");
    const int n = 8;
    std::vector<pid_t> kids;
    for (int i = 0; i < n; ++i) {
        pid_t pid = fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            int rc = 0;
            try {
                results::appendRecord(p, json{{"device", "x"}}, cell("mc", 0.1 * (i + 1), i));
            } catch (...) {
                rc = 1;
            }
            _exit(rc);
        }
        kids.push_back(pid);
    }
    for (pid_t k : kids) {
        int st = 0;
        waitpid(k, &st, 0);
        EXPECT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0);
    }
    EXPECT_EQ(results::load(p).records.size(), static_cast<size_t>(n));
    EXPECT_EQ(strays(), 0);
}

TEST_F(Results, FailedSaveLeavesTheOldFileAndNoTemporary)
{
    const std::string p = file("keep.json");
    results::Results doc;
    doc.records = {cell("mc", 0.1, 1.0)};
    results::save(p, doc);
    // A directory where the file should go: the rename fails after the temporary is written.
    fs::create_directories(file("dir.json"));
    EXPECT_THROW(results::save(file("dir.json"), doc), Error);
    EXPECT_EQ(strays(), 0);
    EXPECT_THROW(results::save(file("no/such/dir/x.json"), doc), Error);
    EXPECT_EQ(results::load(p).records.size(), 1u);
}

TEST_F(Results, MergeDeduplicatesLaterFileWins)
{
    results::Results a, b;
    a.context = {{"device", "A"}};
    b.context = {{"device", "B"}};
    a.records = {cell("mc", 0.1, 1.0), cell("mc", 1.1, 1.0)};
    b.records = {cell("mc", 1.1, 2.0), cell("cubature", 1.1, 2.0)};
    results::save(file("a.json"), a);
    results::save(file("b.json"), b);
    results::MergeStats st;
    auto m = results::mergeResults({file("a.json"), file("b.json")}, &st);
    ASSERT_EQ(m.records.size(), 3u);
    EXPECT_EQ(st.files, 2u);
    EXPECT_EQ(st.records_in, 4u);
    EXPECT_EQ(st.records_out, 3u);
    EXPECT_EQ(st.replaced, 1u);
    EXPECT_EQ(m.records[0].error.nmse, 1.0);  // only in a
    EXPECT_EQ(m.records[1].error.nmse, 2.0);  // in both: b, the later, wins (in a's position)
    EXPECT_EQ(m.records[2].method, "cubature");
    EXPECT_EQ(m.context["device"], "A");
    ASSERT_EQ(m.context["merged_from"].size(), 2u);
    EXPECT_EQ(m.context["merged_from"][1]["file"], file("b.json"));
    EXPECT_EQ(m.context["merged_from"][1]["context"]["device"], "B");
    // Merged output is a results document itself.
    results::save(file("m.json"), m);
    EXPECT_EQ(results::load(file("m.json")).records.size(), 3u);
}

TEST_F(Results, BadFilesAreInputErrorsNamingFileAndRecord)
{
    auto expectError = [](const std::string& path, const std::string& part) {
        try {
            results::load(path);
            ADD_FAILURE() << path << " should not load";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
    };
    expectError(file("missing.json"), "cannot open");
    std::ofstream(file("trunc.json")) << R"({"context": {}, "records": [)";
    expectError(file("trunc.json"), "not valid JSON");
    std::ofstream(file("shape.json")) << R"({"records": []})";
    expectError(file("shape.json"), "\"context\"");
    json doc = {{"context", json::object()}, {"records", {cell("mc", 0.1, 1), cell("mc", 0.2, 1)}}};
    doc["records"][1].erase("nmse");
    std::ofstream(file("key.json")) << doc.dump();
    expectError(file("key.json"), "record 1: missing key \"nmse\"");
    doc["records"][1]["nmse"] = "big";
    std::ofstream(file("type.json")) << doc.dump();
    expectError(file("type.json"), "record 1: key \"nmse\": expected a number");
    doc["records"][1]["nmse"] = 1;
    doc["records"][0]["precision"] = "half";
    std::ofstream(file("prec.json")) << doc.dump();
    expectError(file("prec.json"), "record 0: key \"precision\"");
    EXPECT_THROW(results::mergeResults({file("missing.json")}), InputError);
}

}  // namespace
}  // namespace lb
