// test_hostile_outputs.cpp -- what lands in an output folder and nowhere else:
// links planted inside --out are replaced or refused, never followed; the
// FLIP helper's temporaries do not outlive a killed run; a scene that cannot
// be pictured keeps its records; two experiments cannot share one --out at
// once. Every folder is fresh, and the files outside --out that a link points
// to are checked unchanged.
#include "hostile.h"

#include "experiments/results.h"
#include "experiments/run_lock.h"
#include "metrics/flip.h"
#include "testutil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace lb {
namespace {

using namespace hostile;

// A file outside every output folder that a planted link points to.
struct Victim {
    fs::path path;
    std::string text;
};

Victim victim(const fs::path& dir, const std::string& name, const std::string& text = "precious\n")
{
    fs::create_directories(dir);
    writeText(dir / name, text);
    return {dir / name, text};
}

void expectUntouched(const Victim& v) { EXPECT_EQ(slurp(v.path), v.text) << v.path << " was written through a link"; }

// The one scene's label (its images folder) of a run into `out`.
std::string onlyScene(const fs::path& out)
{
    for (const auto& e : fs::directory_iterator(out / "images")) return e.path().filename().string();
    return "";
}

TEST(HostileOutputs, FileLinksInsideTheOutputAreReplacedNotFollowed)
{
    LB_REQUIRE_RUNTIME(rt);
    const fs::path d = tmpDir("links-files"), outside = d.parent_path() / "outside";
    fs::copy_file(lambert(), d / "lum.ldt");
    writeText(d / "e.json", tinyExperiment(d, {"lum.ldt"}).dump());
    fs::create_directories(d / "o");
    std::vector<Victim> victims;
    for (const char* f : {"report.html", "report.md", "results.csv"}) {
        victims.push_back(victim(outside, f));
        fs::create_symlink(victims.back().path, d / "o" / f);
    }
    CliRun r = lumibench(d, {"run", "e.json", "--out", "o", "--no-report"});
    ASSERT_EQ(r.code, 0) << r.err;
    r = lumibench(d, {"report", "o", "--no-plots"});
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* f : {"report.html", "report.md", "results.csv"})
        EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(d / "o" / f))) << f << " is still a link";
    // a picture the report draws again, and results.json written by merge --force
    const fs::path err = d / "o" / "images" / onlyScene(d / "o") / "point_err.png";
    ASSERT_TRUE(fs::is_regular_file(err)) << err;
    fs::remove(err);
    victims.push_back(victim(outside, "point_err.png"));
    fs::create_symlink(victims.back().path, err);
    fs::create_directories(d / "m");
    victims.push_back(victim(outside, "results.json"));
    fs::create_symlink(victims.back().path, d / "m" / "results.json");
    r = lumibench(d, {"report", "o", "--no-plots"});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_FALSE(fs::is_symlink(err));
    r = lumibench(d, {"merge", "o", "--out", "m", "--force", "--no-report"});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_FALSE(fs::is_symlink(d / "m" / "results.json"));
    for (const auto& v : victims) expectUntouched(v);
}

TEST(HostileOutputs, LinkedFoldersAndJournalsInsideTheOutputAreRefusedNamingThem)
{
    LB_REQUIRE_RUNTIME(rt);
    const fs::path d = tmpDir("links-dirs"), outside = d.parent_path() / "outside";
    fs::copy_file(lambert(), d / "lum.ldt");
    writeText(d / "e.json", tinyExperiment(d, {"lum.ldt"}).dump());
    ASSERT_EQ(lumibench(d, {"run", "e.json", "--out", "first", "--no-report"}).code, 0);
    const std::string label = onlyScene(d / "first");
    fs::create_directories(outside / "dir");

    // images/ and images/<label>/ as links to a folder outside
    fs::create_directories(d / "a");
    fs::create_directory_symlink(outside / "dir", d / "a" / "images");
    fs::create_directories(d / "b" / "images");
    fs::create_directory_symlink(outside / "dir", d / "b" / "images" / label);
    for (const auto& [out, named] :
         {std::pair<std::string, std::string>{"a", "a/images"}, {"b", "b/images/" + label}}) {
        CliRun r = lumibench(d, {"run", "e.json", "--out", out, "--no-report"});
        EXPECT_EQ(r.code, 2) << out << ": " << r.err;
        EXPECT_NE(r.err.find(named + ": a symbolic link"), std::string::npos) << r.err;
    }
    // the journal, empty (where an append once wrote the context through it)
    const Victim journal = victim(outside, "journal", "");
    fs::create_directories(d / "c");
    fs::create_symlink(journal.path, d / "c" / "results.json.journal");
    CliRun r = lumibench(d, {"run", "e.json", "--out", "c", "--no-report"});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("c/results.json.journal: the results journal is a symbolic link"), std::string::npos) << r.err;
    expectUntouched(journal);
    // plots/ during report: the scripts would follow it
    fs::create_directory_symlink(outside / "dir", d / "first" / "plots");
    r = lumibench(d, {"report", "first"});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("first/plots: a symbolic link"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_empty(outside / "dir")) << "a file was written through a linked folder";
}

// ---- temporaries of the FLIP helper ----

// A PID that no longer runs.
pid_t deadPid()
{
    pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ::waitpid(child, nullptr, 0);
    return child;
}

bool flipHere()
{
    std::string why;
    return metrics::flipAvailable(&why);
}

TEST(HostileOutputs, FlipFoldersOfKilledRunsAreRemovedByTheNext)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!flipHere()) GTEST_SKIP() << "flip-evaluator not installed: no FLIP helper starts";
    const fs::path d = tmpDir("flip-temps"), tmp = d.parent_path() / "tmp";
    fs::create_directories(tmp);
    // a folder of a killed lumibench (kill -9 runs no destructor), one of a running one
    const fs::path stale = tmp / fmt::format("lumibench-flip-{}-Ab12Cd", deadPid());
    const fs::path live = tmp / fmt::format("lumibench-flip-{}-Ef34Gh", ::getpid());
    for (const auto& f : {stale, live}) {
        fs::create_directories(f);
        writeText(f / "reference.f32", std::string(4096, 'x'));
    }
    ASSERT_EQ(lumibench(d,
                        {"render", "--luminaire", lambert().string(), "--method", "point", "--height", "1",
                         "--rotation", "pi", "--res", "8", "--out", "p.exr"})
                  .code,
              0);
    CliRun r = lumibench(d, {"compare", "p.exr", "p.exr", "--json"}, 120, {"TMPDIR=" + tmp.string()});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(json::parse(r.out)["flip"].is_number()) << r.out;  // FLIP ran, in this TMPDIR
    EXPECT_FALSE(fs::exists(stale)) << "the killed run's folder is still there";
    EXPECT_TRUE(fs::exists(live / "reference.f32")) << "a running process's folder was removed";
    EXPECT_EQ(tree(tmp), (std::set<std::string>{live.filename().string(), live.filename().string() + "/reference.f32"}))
        << "the compare left its own folder behind";
}

// A FLIP helper that dies at its first request (as at a black reference
// before): started again, the image gets its FLIP.
TEST(HostileOutputs, FlipHelperThatDiesIsStartedAgain)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!flipHere()) GTEST_SKIP() << "flip-evaluator not installed";
    const fs::path d = tmpDir("flip-restart");
    const fs::path mark = d.parent_path() / "died-once", wrapper = d.parent_path() / "python";
    writeText(wrapper,
              "#!/bin/sh\n"
              "if [ ! -e \"$LB_TEST_MARK\" ]; then : > \"$LB_TEST_MARK\"; echo '{\"ready\": \"dies\"}'; "
              "read line; exit 1; fi\n"
              "exec \"$LB_TEST_PYTHON\" \"$@\"\n");
    fs::permissions(wrapper, fs::perms::owner_all);
    ASSERT_EQ(lumibench(d,
                        {"render", "--luminaire", lambert().string(), "--method", "point", "--height", "1",
                         "--rotation", "pi", "--res", "8", "--out", "p.exr"})
                  .code,
              0);
    CliRun r = lumibench(d, {"compare", "p.exr", "p.exr", "--json"}, 120,
                         {"LUMIBENCH_FLIP_PYTHON=" + wrapper.string(), "LB_TEST_MARK=" + mark.string(),
                          "LB_TEST_PYTHON=" + metrics::flipPython()});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(mark)) << "the dying helper never ran";
    EXPECT_NE(r.err.find("starting it again"), std::string::npos) << r.err;
    EXPECT_TRUE(json::parse(r.out)["flip"].is_number()) << r.out;  // not null
}

// ---- scenes that cannot be pictured ----

TEST(HostileOutputs, BlackOrOnePixelScenesKeepTheirRecords)
{
    LB_REQUIRE_RUNTIME(rt);
    const fs::path d = tmpDir("black");
    fs::copy_file(lambert(), d / "lambert.ldt");
    fs::copy_file(luminaire("spot.ldt"), d / "spot.ldt");
    json e = tinyExperiment(d, {"lambert.ldt", "spot.ldt"});
    e["heights"] = {5.1};
    e["rotations"] = {"pi/2"};  // the spot looks along the receiver: nothing reaches it
    writeText(d / "e.json", e.dump());
    for (const std::vector<std::string>& extra : {std::vector<std::string>{}, {"--res", "1"}}) {
        const std::string out = extra.empty() ? "o" : "o1";
        std::vector<std::string> args = {"run", "e.json", "--out", out, "--no-report"};
        args.insert(args.end(), extra.begin(), extra.end());
        for (int pass = 0; pass < 2; ++pass) {  // and a rerun finds them done
            CliRun r = lumibench(d, args);
            ASSERT_EQ(r.code, 0) << what(args) << r.err;
            if (pass == 0) {
                EXPECT_NE(r.err.find("no pictures and no FLIP for this scene"), std::string::npos) << r.err;
            }
        }
        const auto recs = results::load((d / out / "results.json").string()).records;
        ASSERT_EQ(recs.size(), 2u) << out;
        for (const auto& rec : recs) {
            const bool black = rec.luminaire == "spot.ldt" || !extra.empty();
            const fs::path img = d / out / "images" / rec.extra.value("scene", "");
            EXPECT_EQ(fs::exists(img / "point_ref.png"), !black) << out << " " << rec.luminaire;
            if (black) {
                EXPECT_TRUE(std::isnan(rec.error.flip)) << out << " " << rec.luminaire;
            } else if (flipHere()) {
                EXPECT_TRUE(std::isfinite(rec.error.flip)) << rec.luminaire;
            }
        }
    }
}

// ---- one experiment at a time in one output folder ----

TEST(HostileOutputs, TwoExperimentsCannotWriteIntoOneFolderAtOnce)
{
    LB_REQUIRE_RUNTIME(rt);
    const fs::path d = tmpDir("run-lock");
    fs::copy_file(lambert(), d / "lum.ldt");
    writeText(d / "e.json", tinyExperiment(d, {"lum.ldt"}).dump());
    fs::create_directories(d / "o");
    const std::string results = (d / "o" / "results.json").string();
    {
        // another experiment, running (the lock as its run holds it)
        const experiments::RunLock other(results, "another-identity", "other", "other.json");
        CliRun r = lumibench(d, {"run", "e.json", "--out", "o", "--no-report"});
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_NE(r.err.find("another run is writing into this folder (experiment 'other' from other.json"),
                  std::string::npos)
            << r.err;
        EXPECT_FALSE(fs::exists(results)) << "the refused run wrote records";
        // shards of one experiment share the folder
        EXPECT_NO_THROW(experiments::RunLock(results, "another-identity", "other", "other.json"));
        EXPECT_THROW(experiments::RunLock(results, "a third", "third", "third.json"), InputError);
    }
    CliRun r = lumibench(d, {"run", "e.json", "--out", "o", "--no-report"});  // the other one ended
    EXPECT_EQ(r.code, 0) << r.err;
}

// A luminaire named like an option: its scene's image grid gets its title
// (plots/experiment.py passes --title=LABEL as one argument).
TEST(HostileOutputs, NamesThatLookLikeOptionsGetTheirPlots)
{
    LB_REQUIRE_RUNTIME(rt);
    if (std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") != 0)
        GTEST_SKIP() << "no matplotlib for /usr/bin/python3: no plots are made";
    const fs::path d = tmpDir("option-names");
    fs::copy_file(lambert(), d / "-h.ldt");
    writeText(d / "e.json", tinyExperiment(d, {"-h.ldt"}).dump());
    CliRun r = lumibench(d, {"run", "e.json", "--out", "o"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("plots not made"), std::string::npos) << r.err;
    bool grid = false;
    for (const auto& e : fs::directory_iterator(d / "o" / "plots" / "grids"))
        grid = grid || e.path().filename().string().rfind("grid_-h-", 0) == 0;
    EXPECT_TRUE(grid) << "no image grid for the scene of -h.ldt";
}

}  // namespace
}  // namespace lb
