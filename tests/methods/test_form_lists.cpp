// The places outside the form table that name every straight-line form of the
// cubature (methods/specialize.h cubatureForms) are held to the table: the
// kernel's header (kernels/cubature.cl), the forms' includes
// (kernels/common/cubature_lanes.inc), the forms' table of docs/kernel-forms.md
// and docs/design.md section 12. Each must name exactly the table's forms, by
// their -D define (and design.md also by the JSON name), so that a form added
// to or removed from the table fails here until every list follows. No
// device needed.
#include "methods/specialize.h"
#include "testutil.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace lb::methods {
namespace {

std::string readSource(const std::string& rel)
{
    std::ifstream f(std::filesystem::path(test::sourceDir()) / rel);
    EXPECT_TRUE(f.good()) << rel;
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

// The forms' defines without "-D" (LB_CUB_RECT_FAN, ...).
std::set<std::string> formDefines()
{
    std::set<std::string> d;
    for (const auto& f : cubatureForms()) d.insert(std::string(f.name.define).substr(2));
    return d;
}

// The LB_CUB_RECT_* names in text, without the modifier that is no form
// (Rule::RectClip) and the how-to's placeholders (LB_CUB_RECT_NAME, LB_CUB_RECT_...).
std::set<std::string> namedForms(const std::string& text)
{
    const std::string clip = std::string(ruleName(Rule::RectClip).define).substr(2);
    std::set<std::string> found;
    std::regex re("LB_CUB_RECT_[A-Z0-9_]+");
    for (std::sregex_iterator it(text.begin(), text.end(), re), end; it != end; ++it)
        if (it->str() != clip && it->str() != "LB_CUB_RECT_NAME") found.insert(it->str());
    return found;
}

// The lines of text that start with prefix.
std::string linesStartingWith(const std::string& text, const std::string& prefix)
{
    std::istringstream in(text);
    std::string line, out;
    while (std::getline(in, line))
        if (line.rfind(prefix, 0) == 0) out += line + "\n";
    return out;
}

// The file under kernels/common/cubature/ whose `#ifdef define` makes it LB_CUB_FORM.
std::string formFile(const std::string& define)
{
    namespace fs = std::filesystem;
    for (auto& e : fs::directory_iterator(fs::path(test::sourceDir()) / "kernels/common/cubature"))
        if (readSource("kernels/common/cubature/" + e.path().filename().string()).find("#ifdef " + define + "\n") !=
            std::string::npos)
            return e.path().filename().string();
    return "";
}

TEST(CubatureForms, TheKernelHeaderNamesEveryForm)
{
    EXPECT_EQ(namedForms(readSource("kernels/cubature.cl")), formDefines());
}

TEST(CubatureForms, TheFormsIncludeNamesAndIncludesEveryForm)
{
    const std::string inc = readSource("kernels/common/cubature_lanes.inc");
    EXPECT_EQ(namedForms(inc), formDefines());
    for (const auto& d : formDefines()) {
        const std::string file = formFile(d);
        ASSERT_FALSE(file.empty()) << "no file under kernels/common/cubature/ has #ifdef " << d;
        EXPECT_NE(inc.find("#include \"cubature/" + file + "\""), std::string::npos) << file;
        EXPECT_NE(inc.find(file + " "), std::string::npos) << file << " missing from the header's list";
    }
}

TEST(CubatureForms, KernelFormsDocTableNamesEveryForm)
{
    const std::string rows = linesStartingWith(readSource("docs/kernel-forms.md"), "| `form_");
    EXPECT_EQ(namedForms(rows), formDefines());
    for (const auto& d : formDefines())
        EXPECT_NE(rows.find("| `" + formFile(d) + "` | `" + d + "` |"), std::string::npos) << d;
}

TEST(CubatureForms, DesignSection12NamesEveryForm)
{
    const std::string design = readSource("docs/design.md");
    const size_t from = design.find("\n## 12. "), to = design.find("\n## 13. ");
    ASSERT_NE(from, std::string::npos);
    ASSERT_NE(to, std::string::npos);
    const std::string section = design.substr(from, to - from);
    EXPECT_EQ(namedForms(section), formDefines());
    for (const auto& f : cubatureForms())
        EXPECT_NE(section.find(fmt::format("- `{}` (", f.name.json)), std::string::npos)
            << f.name.json << " has no item in design.md section 12";
}

}  // namespace
}  // namespace lb::methods
