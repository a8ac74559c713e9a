// docs/methods.md is `lumibench methods --markdown`: generated from the
// registry, so the documented parameters are the parsed ones.
#include "methods/method_docs.h"
#include "methods/registry.h"
#include "testutil.h"

#include <fstream>
#include <sstream>
#include "lb_build_config.h"

namespace lb::methods {
namespace {

TEST(Methods, DocsMatchTheRegistry)
{
    const std::string path = std::string(LB_SOURCE_DIR) + "/docs/methods.md";
    std::ifstream in(path);
    ASSERT_TRUE(in) << "missing " << path;
    std::stringstream want;
    want << in.rdbuf();
    EXPECT_EQ(want.str(), methodsMarkdown())
        << path << " differs from the registry: run build/lumibench methods --markdown > docs/methods.md";
}

// Every family has its parameter table, every parameter its row (a family
// or parameter the generator skipped would make the comparison above hold
// between two incomplete files).
TEST(Methods, MarkdownHasEveryFamilyAndParameter)
{
    const std::string md = methodsMarkdown();
    for (const auto& f : registry().all()) {
        EXPECT_NE(md.find("\n### " + f.name + " ("), std::string::npos) << f.name;
        for (const auto& p : f.params) EXPECT_NE(md.find("| `" + p.name + "` |"), std::string::npos) << p.name;
        EXPECT_NE(methodsText().find(f.summary), std::string::npos) << f.name;
    }
}

// The command prints the same document.
TEST(Methods, CliPrintsTheMarkdown)
{
    auto r = test::runCli("methods --markdown");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, methodsMarkdown());
}

}  // namespace
}  // namespace lb::methods
