// Bad input ends in lb::InputError "FILE:LINE: expected ..., got ..." (exit
// code 2 in the CLI), never a crash or a partial table. Each case mutates a
// small valid file and checks the whole message prefix, line number included.
#include "photometry/ies.h"
#include "photometry/ldt.h"
#include "photometry/load.h"
#include "util/error.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace lb::photometry {
namespace {

// Valid EULUMDAT, Isym 2, Nc = 4, Ng = 3: 3 stored planes; line numbers in
// comments are the ones the messages must name.
std::vector<std::string> ldtLines()
{
    std::vector<std::string> l = {"co", "1", "2", "4", "90", "3", "45", "r", "n", "num", "f", "d"};  // 1-12
    for (int i = 13; i <= 21; ++i) l.push_back("100");
    for (const char* x : {"100", "80", "1", "0", "1", "1", "lamp", "1000", "3000", "80", "10"})
        l.push_back(x);  // 22-32
    for (int i = 0; i < 10; ++i) l.push_back("0.5");  // 33-42
    for (const char* x : {"0", "90", "180", "270"}) l.push_back(x);  // 43-46: C
    for (const char* x : {"0", "45", "90"}) l.push_back(x);  // 47-49: gamma
    for (int i = 0; i < 9; ++i) l.push_back(std::to_string(10 + i));  // 50-58: data
    return l;
}

std::string join(const std::vector<std::string>& l)
{
    std::string s;
    for (const auto& x : l) s += x + "\r\n";
    return s;
}

void expectLdtError(std::vector<std::string> l, const std::string& message)
{
    try {
        readLdt(TextFile::fromString("t.ldt", join(l)));
        ADD_FAILURE() << "no error, expected: " << message;
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).substr(0, message.size()), message) << e.what();
        EXPECT_EQ(e.code, 2);
    }
}

TEST(Malformed, LdtTemplateIsValid)
{
    Table t = readLdt(TextFile::fromString("t.ldt", join(ldtLines())));
    EXPECT_EQ(t.nc(), 5u);
}

TEST(Malformed, Ldt)
{
    expectLdtError({}, "t.ldt:1: expected a company line (line 1), got end of file");
    auto l = ldtLines();
    expectLdtError({l.begin(), l.begin() + 52},
                   "t.ldt:53: expected intensity 1 of plane C = 90 (cd/klm), got end of file");
    l = ldtLines(), l[3] = "abc";
    expectLdtError(l, "t.ldt:4: expected the number of C planes Nc (an integer in [0, 10000]), got \"abc\"");
    l = ldtLines(), l[3] = "-4";
    expectLdtError(l, "t.ldt:4: expected the number of C planes Nc (an integer in [0, 10000]), got \"-4\"");
    l = ldtLines(), l[5] = "100000";  // capped before anything is allocated
    expectLdtError(l, "t.ldt:6: expected the number of gamma angles Ng (an integer in [2, 10000]), got \"100000\"");
    l = ldtLines(), l[2] = "4", l[43] = "80";  // Isym 4 stores Nc/4 + 1 = 2 planes: 0 and 80, not 90
    expectLdtError(l, "t.ldt:3: expected stored planes ending at C = 90 for Isym 4, got C = 80");
    l = ldtLines(), l[3] = "3", l.erase(l.begin() + 45);
    expectLdtError(l, "t.ldt:4: expected an even Nc for Isym 2, got Nc = 3 with Isym = 2");
    l = ldtLines(), l[47] = "95";
    expectLdtError(l, "t.ldt:49: expected gamma angles ascending (after 95), got 90");
    l = ldtLines(), l[45] = "90";
    expectLdtError(l, "t.ldt:46: expected C angles ascending (after 180), got 90");
    l = ldtLines(), l[51] = "nan";
    expectLdtError(l, "t.ldt:52: expected intensity 3 of plane C = 0 (cd/klm), got \"nan\"");
    l = ldtLines(), l[53] = "-5";
    expectLdtError(l, "t.ldt:54: expected an intensity >= 0, got -5");
    l = ldtLines(), l[28] = "12 lm";
    expectLdtError(l, "t.ldt:29: expected the total lamp flux in lm of set 1, got \"12 lm\"");
    l = ldtLines(), l[25] = "0";
    expectLdtError(l, "t.ldt:26: expected the number of lamp sets n (field 26) (an integer in [1, 1000]), got \"0\"");
    l = ldtLines(), l[50] = "1e999";  // overflows: not finite
    expectLdtError(l, "t.ldt:51: expected intensity 2 of plane C = 0 (cd/klm), got \"1e999\"");
}

const char* kIes = "IESNA:LM-63-2002\n"  // 1
                   "[TEST] t\n"  // 2
                   "TILT=NONE\n"  // 3
                   "1 -1 1 3 2 1 2 0 0 0\n"  // 4
                   "1 1 100\n"  // 5
                   "0 45 90\n"  // 6
                   "0 180\n"  // 7
                   "10 11 12\n"  // 8
                   "20 21 22\n";  // 9

void expectIesError(const std::string& from, const std::string& to, const std::string& message)
{
    std::string s = kIes;
    if (!from.empty()) {
        auto k = s.find(from);
        ASSERT_NE(k, std::string::npos) << from;
        s.replace(k, from.size(), to);
    }
    try {
        readIes(TextFile::fromString("t.ies", s));
        ADD_FAILURE() << "no error, expected: " << message;
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).substr(0, message.size()), message) << e.what();
    }
}

TEST(Malformed, IesTemplateIsValid)
{
    Table t = readIes(TextFile::fromString("t.ies", kIes));
    EXPECT_EQ(t.isym, 2);
}

TEST(Malformed, Ies)
{
    expectIesError("TILT=NONE", "NOTILT", "t.ies:10: expected a TILT= line (IES LM-63), got end of file");
    expectIesError("TILT=NONE", "TILT=lamp.tlt", "t.ies:3: expected TILT=NONE or TILT=INCLUDE");
    expectIesError("1 2 0 0 0", "2 2 0 0 0",
                   "t.ies:4: expected photometric type 1 (C); type B (2, floodlights) is not supported");
    expectIesError("1 2 0 0 0", "3 2 0 0 0", "t.ies:4: expected photometric type 1 (C); type A (3) is not supported");
    expectIesError("20 21 22\n", "20 21\n",
                   "t.ies:10: expected candela 3 of 3 at horizontal angle 180, got end of file");
    expectIesError("20 21 22", "20 -21 22", "t.ies:9: expected a candela value >= 0, got -21");
    expectIesError("20 21 22", "20 21 x22", "t.ies:9: expected candela 3 of 3 at horizontal angle 180, got \"x22\"");
    expectIesError("20 21 22", "20 inf 22", "t.ies:9: expected candela 2 of 3 at horizontal angle 180, got \"inf\"");
    expectIesError("0 45 90", "0 90 45", "t.ies:6: expected vertical angles ascending (after 90), got 45");
    expectIesError("0 45 90", "10 45 90", "t.ies:6: expected vertical angles 0-90, 90-180 or 0-180, got 10-90");
    expectIesError("0 180\n", "0 45\n",
                   "t.ies:7: expected horizontal angles {0}, 0-90, 0-180, 90-270, 0-360 or 0 to (180, 360), got 0-45");
    expectIesError("1 -1 1 3 2", "1 -1 1 3 -2",
                   "t.ies:4: expected the number of horizontal angles (an integer in [1, 10000]), got \"-2\"");
    expectIesError("1 -1 1 3 2", "1 -1 0 3 2", "t.ies:4: expected a candela multiplier > 0, got 0");
    expectIesError("0 45 90\n0 180\n10 11 12\n20 21 22\n", "0 45\n",
                   "t.ies:7: expected vertical angle 3 of 3, got end of file");
}

TEST(Malformed, EmptyAndMissingFiles)
{
    auto p = std::filesystem::temp_directory_path() / "lumibench_empty.ldt";
    std::ofstream(p).close();
    try {
        load(p.string());
        ADD_FAILURE() << "empty file read";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), p.string() + ":1: expected a luminaire file, got an empty file");
    }
    std::filesystem::remove(p);
    EXPECT_THROW(load("/nonexistent/x.ies"), InputError);
}

}  // namespace
}  // namespace lb::photometry
