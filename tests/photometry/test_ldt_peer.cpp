// Peer check of the EULUMDAT reader: every .ldt of luminaires/ and
// ../shared/luminaires read by pyldt (PyPI eulumdat-py, written by others)
// and by `lumibench luminaire eval`, node by node (tests/photometry/ldt_peer.py
// has the tolerance and its reason). A round trip through our own reader and
// writer cannot catch a layout both of them get wrong; a peer can.
#include "testutil.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace lb {
namespace {

namespace fs = std::filesystem;

// The project-local environment scripts/install-deps.sh makes.
std::string venvPython() { return test::sourceDir() + "/.venv/bin/python"; }

std::vector<std::string> ldtFiles(const std::string& dir)
{
    std::vector<std::string> v;
    if (!fs::is_directory(dir)) return v;
    for (auto& e : fs::recursive_directory_iterator(dir)) {
        std::string ext = e.path().extension().string();
        if (ext == ".ldt" || ext == ".LDT") v.push_back(e.path().string());
    }
    std::sort(v.begin(), v.end());
    return v;
}

TEST(LdtPeer, EveryLdtAgreesWithPyldtNodeByNode)
{
    std::string py = venvPython();
    if (!fs::exists(py) || std::system(("'" + py + "' -c 'import pyldt' 2>/dev/null").c_str()) != 0)
        GTEST_SKIP() << "pyldt is not installed in .venv (scripts/install-deps.sh could not reach PyPI)";
    std::vector<std::string> files = ldtFiles(test::sourceDir() + "/luminaires");
    ASSERT_GE(files.size(), 9u) << "the suite's own luminaires";
    std::string shared = test::sharedDir();
    size_t own = files.size();
    if (!shared.empty()) {
        auto more = ldtFiles(shared + "/luminaires");
        files.insert(files.end(), more.begin(), more.end());
        EXPECT_GE(files.size(), own + 7) << "the seven published files";
    }
    std::string cmd = "'" + py + "' '" + test::sourceDir() + "/tests/photometry/ldt_peer.py' '" + test::binary() + "'";
    for (const auto& f : files) cmd += " '" + f + "'";
    cmd += " 2>&1";
    std::string out;
    int code = -1;
    if (FILE* p = popen(cmd.c_str(), "r")) {
        char buf[4096];
        while (fgets(buf, sizeof buf, p)) out += buf;
        int st = pclose(p);
        code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    }
    EXPECT_EQ(code, 0) << out;
    std::string agree = std::to_string(files.size()) + " of " + std::to_string(files.size()) + " files agree";
    EXPECT_NE(out.find(agree), std::string::npos) << out;
    std::printf("%s", out.c_str());
    if (shared.empty()) GTEST_SKIP() << "../shared is not present: checked the suite's own files only";
}

}  // namespace
}  // namespace lb
