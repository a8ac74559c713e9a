// The readers' limits: candela beyond what the kernels can hold, counts the
// file cannot hold (refused before anything is allocated from them), values
// beyond the declared counts, directories, endless inputs, decimal commas in
// IES. Each message names FILE:LINE and what was expected.
#include "photometry/ies.h"
#include "photometry/ldt.h"
#include "photometry/load.h"
#include "photometry/text.h"
#include "util/error.h"

#include "../testutil.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

namespace lb::photometry {
namespace {

namespace fs = std::filesystem;

// Valid EULUMDAT, Isym 2, Nc = 4, Ng = 3 (as test_malformed.cpp): lines 4 Nc,
// 6 Ng, 28 lamp flux, 50-58 the 3 x 3 intensities.
std::vector<std::string> ldtLines()
{
    std::vector<std::string> l = {"co", "1", "2", "4", "90", "3", "45", "r", "n", "num", "f", "d"};
    for (int i = 13; i <= 21; ++i) l.push_back("100");
    for (const char* x : {"100", "80", "1", "0", "1", "1", "lamp", "1000", "3000", "80", "10"}) l.push_back(x);
    for (int i = 0; i < 10; ++i) l.push_back("0.5");
    for (const char* x : {"0", "90", "180", "270"}) l.push_back(x);
    for (const char* x : {"0", "45", "90"}) l.push_back(x);
    for (int i = 0; i < 9; ++i) l.push_back(std::to_string(10 + i));
    return l;
}

std::string join(const std::vector<std::string>& l)
{
    std::string s;
    for (const auto& x : l) s += x + "\r\n";
    return s;
}

// Valid IES: 3 vertical x 2 horizontal angles; line 3 the counts, 4 the
// ballast factors, 5-6 the angles, 7-8 the candela values.
const std::string kIes = "IESNA:LM-63-2002\n"  // 1
                         "TILT=NONE\n"  // 2
                         "1 -1 1 3 2 1 2 0 0 0\n"  // 3: lamps, lumens, multiplier, Nv, Nh, type, units, w, l, h
                         "1 1 0\n"  // 4
                         "0 45 90\n"  // 5
                         "0 180\n"  // 6
                         "10 11 12\n"  // 7
                         "20 21 22\n";  // 8

using test::inputErrorOf;

std::string ldtError(const std::vector<std::string>& l)
{
    return inputErrorOf([&] { readLdt(TextFile::fromString("t.ldt", join(l))); });
}
std::string iesError(const std::string& s)
{
    return inputErrorOf([&] { readIes(TextFile::fromString("t.ies", s)); });
}

// gtest prints both strings when the prefix is missing.
#define EXPECT_PREFIX(prefix, text) EXPECT_EQ(std::string(text).substr(0, std::string(prefix).size()), prefix)

std::string replaced(std::string s, const std::string& from, const std::string& to)
{
    s.replace(s.find(from), from.size(), to);
    return s;
}

TEST(ReaderLimits, TemplatesAreValid)
{
    EXPECT_EQ(ldtError(ldtLines()), "(no error)");
    EXPECT_EQ(iesError(kIes), "(no error)");
}

// Before: 1e39 cd (and a multiplier of 1e300) were read, and every render
// of the table had non-finite pixels.
TEST(ReaderLimits, CandelaBeyondTheKernelsRange)
{
    auto l = ldtLines();
    l[53] = "1e39";
    EXPECT_PREFIX("t.ldt:54: expected an intensity in [0, 1e+20] cd after the file's multipliers", ldtError(l));
    l = ldtLines();
    l[28] = "1e300";  // lamp flux: cd/klm x 1e297
    EXPECT_PREFIX("t.ldt:50: expected an intensity in [0, 1e+20]", ldtError(l));
    EXPECT_PREFIX("t.ies:7: expected a candela value in [0, 1e+20]",
                  iesError(replaced(kIes, "1 -1 1 3 2", "1 -1 1e300 3 2")));
    EXPECT_PREFIX("t.ies:8: expected a candela value in [0, 1e+20]", iesError(replaced(kIes, "21", "1e39")));
}

// 10000 ascending angles from 0 in steps of `step`, one per line.
std::string angles(double step)
{
    std::string s;
    for (int i = 0; i < 10000; ++i) s += std::to_string(i * step) + "\n";
    return s;
}

// Before: a ~250 kB file declaring 10000 x 10000 values (its angles all
// there) allocated the 800 MB table before it failed at its end.
TEST(ReaderLimits, CountsBeyondTheFileAreRefusedBeforeAllocating)
{
    auto l = ldtLines();
    l[2] = "0", l[3] = "10000", l[5] = "10000";  // Isym 0: all 10000 planes stored
    l.resize(42);  // header and direct ratios
    std::string ldt = join(l) + angles(0.036) + angles(0.018) + "1\n";
    auto t0 = std::chrono::steady_clock::now();
    EXPECT_PREFIX("t.ldt:4: expected Mc x Ng = 10000 x 10000 intensities (Nc = 10000, Isym = 0) that the rest of the "
                  "file can hold (at most 2 numbers in 2 bytes), got 100000000 numbers",
                  inputErrorOf([&] { readLdt(TextFile::fromString("t.ldt", ldt)); }));
    std::string ies = "TILT=NONE\n1 -1 1 10000 10000 1 2 0 0 0\n1 1 0\n" + angles(180.0 / 9999) + angles(0.036) + "1\n";
    EXPECT_PREFIX("t.ies:2: expected Nh x Nv = 10000 x 10000 candela values that the rest of the file can hold",
                  iesError(ies));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0);
    // A file cut a few values short still names the line where it ends.
    EXPECT_EQ(iesError(replaced(kIes, "20 21 22\n", "20\n")),
              "t.ies:9: expected candela 2 of 3 at horizontal angle 180, got end of file");
}

// Before: values after the declared ones were ignored silently.
TEST(ReaderLimits, ExtraValuesAreRefused)
{
    auto l = ldtLines();
    l.push_back("19");
    EXPECT_EQ(ldtError(l),
              "t.ldt:59: expected the end of the file after the 3 x 3 intensities (Mc x Ng for Nc = 4, "
              "Isym = 2), got \"19\"");
    l = ldtLines();
    l.push_back("");  // blank lines at the end are fine
    EXPECT_EQ(ldtError(l), "(no error)");
    EXPECT_EQ(iesError(kIes + "23\n"),
              "t.ies:9: expected the end of the file after the 2 x 3 candela values, got \"23\"");
    EXPECT_EQ(iesError(kIes + "\n  \n"), "(no error)");
}

// Before: "12,5" split into 12 and 5, and the reader said "vertical angles ascending".
TEST(ReaderLimits, DecimalCommaInIesIsNamed)
{
    std::string s = replaced(kIes, "0 45 90", "0 22,5 90");
    std::string e = iesError(s);
    EXPECT_PREFIX("t.ies:5: expected '.' as the decimal mark (IES LM-63 separates numbers by blanks or commas)", e);
    EXPECT_NE(e.find("got a decimal comma in \"22,5\""), std::string::npos) << e;
    // Commas as separators stay valid.
    EXPECT_EQ(iesError(replaced(kIes, "0 45 90", "0,45,90")), "(no error)");
}

// Before: a directory said "empty file"; /dev/zero read 1 GiB first.
TEST(ReaderLimits, DirectoriesAndEndlessFiles)
{
    fs::path d = fs::temp_directory_path() / ("lumibench-test-lumdir-" + std::to_string(::getpid()) + ".ldt");
    fs::create_directories(d);
    EXPECT_EQ(inputErrorOf([&] { load(d.string()); }), d.string() + ": expected a luminaire file, got a directory");
    fs::remove_all(d);
    auto t0 = std::chrono::steady_clock::now();
    EXPECT_EQ(inputErrorOf([&] { load("/dev/zero"); }), "/dev/zero: expected a luminaire file, got a character device");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
}

}  // namespace
}  // namespace lb::photometry
