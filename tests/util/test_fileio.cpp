// util/fileio.h: atomic writes (nothing left behind on a full disk, groups
// all or nothing), stale temporaries removed, input files read with limits.
// The full disk is /dev/full dup2'ed onto the temporary file's descriptor
// (every write fails with ENOSPC, as on a full file system), and, where user
// namespaces allow it, a real 64 kB tmpfs filled up for the CLI.
#include "experiments/results.h"
#include "metrics/image.h"
#include "metrics/png.h"
#include "photometry/ies.h"
#include "photometry/ldt.h"
#include "photometry/synth.h"
#include "util/error.h"
#include "util/fileio.h"

#include "../testutil.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>

namespace lb {
namespace {

namespace fs = std::filesystem;

fs::path tmpDir(const std::string& name) { return test::freshDir("fileio-" + name); }

std::vector<std::string> entries(const fs::path& d)
{
    std::vector<std::string> v;
    for (auto& e : fs::directory_iterator(d)) v.push_back(e.path().filename().string());
    std::sort(v.begin(), v.end());
    return v;
}

std::string slurp(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Temporary files are created as usual, then their descriptor writes to
// /dev/full: the first `okFiles` temporaries are written normally.
struct FullDisk {
    explicit FullDisk(int okFiles = 0)
    {
        util::setTempOpenerForTesting([n = std::make_shared<int>(okFiles)](const std::string& tmp) {
            int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            if (fd < 0 || (*n)-- > 0) return fd;
            int full = ::open("/dev/full", O_WRONLY | O_CLOEXEC);
            ::dup2(full, fd);
            ::close(full);
            return fd;
        });
    }
    ~FullDisk() { util::setTempOpenerForTesting({}); }
};

TEST(AtomicWrite, WritesAndReplaces)
{
    fs::path d = tmpDir("ok");
    util::writeFileAtomic((d / "a.txt").string(), "one");
    util::writeFileAtomic((d / "a.txt").string(), "two");
    EXPECT_EQ(slurp(d / "a.txt"), "two");
    EXPECT_EQ(entries(d), std::vector<std::string>{"a.txt"});  // no temporary left
}

// Outputs that are not plain files: a FIFO (as --out /dev/null or a pipe) is
// refused with an input error and stays a FIFO (writing would block until a
// reader comes; a rename would replace the node with a plain file: run as
// root, `--out /dev/full` once turned /dev/full into one); a symbolic link
// is replaced by the file, its target left as it was (a link planted in an
// output folder must not carry the bytes elsewhere).
TEST(AtomicWrite, SpecialFilesAreRefusedAndLinksReplaced)
{
    ASSERT_TRUE(fs::is_character_file("/dev/full")) << "/dev/full is not a device here; the full-disk tests need it";
    fs::path d = tmpDir("special");
    fs::path fifo = d / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_THROW(util::writeFileAtomic(fifo.string(), "through the pipe"), InputError);  // no reader: would block
    EXPECT_THROW(util::writeFileAtomic("/dev/full", "x"), InputError);
    EXPECT_TRUE(fs::is_fifo(fifo));
    EXPECT_TRUE(fs::is_character_file("/dev/full"));
    EXPECT_EQ(entries(d), std::vector<std::string>{"pipe"});  // no temporary beside it

    util::writeFileAtomic((d / "real.json").string(), "old");
    fs::create_symlink("real.json", d / "link.json");
    util::writeFileAtomic((d / "link.json").string(), "new");
    EXPECT_FALSE(fs::is_symlink(d / "link.json"));  // the link replaced, its target untouched
    EXPECT_EQ(slurp(d / "link.json"), "new");
    EXPECT_EQ(slurp(d / "real.json"), "old");
    EXPECT_EQ(entries(d), (std::vector<std::string>{"link.json", "pipe", "real.json"}));
}

// A full disk: the write fails with an error naming the file, the old
// content stays, and no temporary or empty file is left (before: OpenEXR and
// the LDT writer left a 0-byte file and exited 0).
TEST(AtomicWrite, FullDiskLeavesTheOldFileAndNoTemporary)
{
    fs::path d = tmpDir("full");
    std::ofstream(d / "keep.exr") << "old";
    FullDisk full;
    try {
        util::writeFileAtomic((d / "keep.exr").string(), std::string(100, 'x'));
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("keep.exr: cannot write 100 bytes: No space left on device"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_EQ(slurp(d / "keep.exr"), "old");
    EXPECT_EQ(entries(d), std::vector<std::string>{"keep.exr"});
}

// Every writer of the suite goes through it: EXR (render, runner, cache),
// PNG, LDT/IES (luminaire synth), results JSON.
TEST(AtomicWrite, EveryFormatFailsCleanlyOnAFullDisk)
{
    fs::path d = tmpDir("formats");
    photometry::Table t = photometry::synth("lambert", {});
    std::vector<std::pair<std::string, std::function<void(const std::string&)>>> writers = {
        {"small.exr", [](const std::string& p) { writeExr(p, Image(2, 2, 1.0)); }},
        {"big.exr", [](const std::string& p) { writeExr(p, Image(256, 256, 1.0)); }},
        {"x.png", [](const std::string& p) { writePng(p, tonemap::Picture(4, 4)); }},
        {"x.ldt", [&](const std::string& p) { photometry::writeLdt(t, p, "x"); }},
        {"x.ies", [&](const std::string& p) { photometry::writeIes(t, p, "x"); }},
        {"results.json", [](const std::string& p) { results::save(p, {}); }},
    };
    FullDisk full;
    for (auto& [name, write] : writers) {
        EXPECT_THROW(write((d / name).string()), Error) << name;
        EXPECT_TRUE(entries(d).empty()) << name << " left " << entries(d).front();
    }
}

// A group (render's image and its FILE.err.exr): the second failing leaves
// neither (before: the main image stayed behind).
TEST(AtomicWrite, GroupIsAllOrNothing)
{
    fs::path d = tmpDir("group");
    FullDisk full(1);  // the first temporary is written, the second hits the full disk
    EXPECT_THROW(util::writeFilesAtomic({{(d / "ref.exr").string(), encodeExr(Image(2, 2, 1.0))},
                                         {(d / "ref.err.exr").string(), encodeExr(Image(2, 2, 0.0))}}),
                 Error);
    EXPECT_TRUE(entries(d).empty());
}

TEST(AtomicWrite, RemovesOnlyTemporariesOfDeadProcesses)
{
    fs::path d = tmpDir("stale");
    pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ::waitpid(child, nullptr, 0);  // its PID is now free (not reused within the test, in practice)
    const std::string dead = std::to_string(child), alive = std::to_string(::getpid());
    for (const std::string& n :
         std::vector<std::string>{"results.json.tmp." + dead, "results.json.tmp." + dead + ".7",
                                  "results.json.tmp." + alive + ".1", "notes.tmp.txt", "results.json"})
        std::ofstream(d / n) << "x";
    EXPECT_EQ(util::removeStaleTemporaries(d.string()), 2u);
    EXPECT_EQ(entries(d),
              (std::vector<std::string>{"notes.tmp.txt", "results.json", "results.json.tmp." + alive + ".1"}));
}

TEST(ReadFile, NamesDirectoriesAndStopsAtTheLimit)
{
    fs::path d = tmpDir("read");
    try {
        util::readFile(d.string(), "a luminaire file", 1000);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), d.string() + ": expected a luminaire file, got a directory");
    }
    // /dev/zero never ends: a device is refused before any read.
    auto t0 = std::chrono::steady_clock::now();
    EXPECT_THROW(util::readFile("/dev/zero", "a luminaire file", 1u << 20), InputError);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
    // A regular file over the limit: refused at the limit, naming it.
    std::ofstream(d / "big") << std::string(2000, 'x');
    try {
        util::readFile((d / "big").string(), "a luminaire file", 1000);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  (d / "big").string() + ": expected a luminaire file of at most 1000 bytes, got more");
    }
    EXPECT_THROW(util::readFile((d / "missing").string(), "x", 10), InputError);
}

// The CLI on a real full file system: a 64 kB tmpfs, filled, in a private
// mount namespace (unshare -rm). `luminaire synth` and `render` must exit
// non-zero and leave nothing (before: exit 0 and a 0-byte file).
TEST(AtomicWrite, CliOnAFullTmpfs)
{
    if (std::system("unshare -rm true 2>/dev/null") != 0) GTEST_SKIP() << "no user namespaces (unshare -rm)";
    fs::path m = tmpDir("tmpfs");
    auto inFullTmpfs = [&](const std::string& args) {
        std::string cmd = "unshare -rm sh -c 'mount -t tmpfs -o size=64k tmpfs " + m.string() +
            " && (dd if=/dev/zero of=" + m.string() + "/fill bs=4k 2>/dev/null; true) && " + test::binary() + " " +
            args + " >/dev/null 2>&1; rc=$?; ls -A " + m.string() + " > " + m.string() + ".ls; exit $rc'";
        int st = std::system(cmd.c_str());
        return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    };
    int rc = inFullTmpfs("luminaire synth lambert --out " + (m / "x.ldt").string());
    EXPECT_EQ(rc, 1);
    EXPECT_EQ(slurp(m.string() + ".ls"), "fill\n");
    if (test::runtime()) {
        rc = inFullTmpfs("render --luminaire analytic:cos1 --method point --height 1 --rotation pi --res 2 --out " +
                         (m / "x.exr").string());
        EXPECT_EQ(rc, 1);
        EXPECT_EQ(slurp(m.string() + ".ls"), "fill\n");
    }
}

}  // namespace
}  // namespace lb
