// Inputs that once broke a reader, or that a fuzzer or a person thought
// might: every file in tests/photometry/regress/ must end in lb::InputError
// from both readers, never in a crash, a hang or another exception. The
// libFuzzer runs of fuzz/README.md (2 x 150 s, ~600k inputs) found no crasher;
// these hand-made ones cover the caps and end-of-file paths they exercise.
#include "photometry/ies.h"
#include "photometry/ldt.h"
#include "testutil.h"
#include "util/error.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace lb::photometry {
namespace {

TEST(Regress, EveryInputEndsInInputError)
{
    namespace fs = std::filesystem;
    size_t n = 0;
    for (auto& e : fs::directory_iterator(test::sourceDir() + "/tests/photometry/regress")) {
        std::ifstream in(e.path(), std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        TextFile f = TextFile::fromString(e.path().filename().string(), ss.str());
        EXPECT_THROW(readLdt(f), InputError) << e.path();
        EXPECT_THROW(readIes(f), InputError) << e.path();
        ++n;
    }
    EXPECT_GE(n, 8u);
}

}  // namespace
}  // namespace lb::photometry
