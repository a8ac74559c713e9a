// Every plot kind of plots/ rendered from the small results in
// tests/plots/data by tests/plots/check_figures.py, which checks PNG + PDF,
// 300 dpi, at most the text width, no text below 8 pt, each series in the
// colour and marker of plots/style.py, legends outside the data, pooled NMSE
// per height and N on the MCI curve, and shows that each check can fail.
#include "testutil.h"

#include <filesystem>
#include <string>

#include <unistd.h>

namespace lb {
namespace {

namespace fs = std::filesystem;

// The Debian interpreter, which has python3-matplotlib (a python3 earlier on
// PATH, e.g. pyenv's, may not).
std::string python() { return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3"; }

TEST(Plots, FiguresFollowTheSuiteStyle)
{
    int code = -1;
    test::shellOutput(python() + " -c 'import matplotlib, PIL' 2>/dev/null", &code);
    if (code != 0 && !test::deviceRequired())
        GTEST_SKIP() << python() << " has no matplotlib (Debian: apt-get install python3-matplotlib)";
    const fs::path work = fs::temp_directory_path() / ("lb_figures_" + std::to_string(getpid()));
    fs::remove_all(work);
    const std::string src = test::sourceDir();
    const std::string out = test::shellOutput(python() + " '" + src + "/tests/plots/check_figures.py' '" + src +
                                                  "/plots' '" + src + "/tests/plots/data' '" + work.string() + "' 2>&1",
                                              &code);
    EXPECT_EQ(code, 0) << out;
    EXPECT_NE(out.find("check_figures: 17 figures of 8 kinds pass"), std::string::npos) << out;
    fs::remove_all(work);
}

}  // namespace
}  // namespace lb
