// report.html's layout in a real browser: `lumibench report` of the small
// results in tests/plots/data, opened in headless Chromium at 800 and 1400 px.
// The page is no wider than the window, tables scroll inside their own box
// with their first column sticky, and plots are no wider than the page. A
// page with one over-wide element, measured the same way, fails the check.
// The first screen holds the answer: the verdict table per method.
#include "testutil.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <unistd.h>

namespace lb {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string slurp(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Measures at load (before adding itself): the page's scroll width against
// the viewport, every table that scrolls inside its box, first cells that are
// sticky, images wider than their parent; written to a hidden element.
const char* kProbe = R"(<script>
window.addEventListener("load", function () {
  var de = document.documentElement, tables = document.querySelectorAll("table"), r = {
    width: de.clientWidth, scrollWidth: de.scrollWidth, tables: tables.length, scrolling: 0, sticky: 0, wideImages: 0,
    images: document.querySelectorAll("figure img").length };
  tables.forEach(function (t) {
    if (t.scrollWidth > t.clientWidth + 1) r.scrolling++;
    var c = t.querySelector("tr > :first-child");
    if (c && getComputedStyle(c).position === "sticky") r.sticky++;
  });
  document.querySelectorAll("img, canvas").forEach(function (im) {
    if (im.getBoundingClientRect().width > im.parentElement.getBoundingClientRect().width + 1) r.wideImages++;
  });
  // the opening verdict table: where it lies in the window, what it says
  var v = document.querySelector("#verdicts table"), viewer = document.getElementById("viewer");
  r.height = window.innerHeight;
  if (v) {
    var box = v.getBoundingClientRect(), text = function (e) { return e.textContent.trim(); };
    r.verdicts = { top: box.top, bottom: box.bottom,
      heads: Array.prototype.map.call(v.querySelectorAll("thead th"), text),
      rows: Array.prototype.map.call(v.querySelectorAll("tbody tr"), function (tr) {
        return Array.prototype.map.call(tr.children, text); }),
      links: Array.prototype.map.call(v.querySelectorAll("a"), function (a) { return a.getAttribute("href"); }),
      beforeViewer: viewer ? (v.compareDocumentPosition(viewer) & Node.DOCUMENT_POSITION_FOLLOWING) !== 0 : null };
  }
  var out = document.createElement("div");
  out.hidden = true;
  out.id = "lbprobe";
  out.textContent = JSON.stringify(r);
  document.body.appendChild(out);
});
</script>)";

struct Browser {
    std::string exe;  // empty when there is none
    Browser()
    {
        for (const char* c : {"chromium", "chromium-browser", "google-chrome"}) {
            int code = -1;
            test::shellOutput(std::string("command -v ") + c + " >/dev/null 2>&1", &code);
            if (code == 0) {
                exe = c;
                break;
            }
        }
    }
    // The probe's measurement of `html` (a copy with the probe added) at `width` px.
    json measure(const fs::path& dir, const fs::path& html, int width) const
    {
        std::string page = slurp(html);
        const size_t end = page.rfind("</body>");
        page.insert(end == std::string::npos ? page.size() : end, kProbe);
        const fs::path probe = dir / ("probe_" + std::to_string(width) + ".html");
        std::ofstream(probe) << page;
        int code = -1;
        const std::string cmd = fmt::format(
            "timeout 120 {} --headless --disable-gpu {} --user-data-dir='{}' --hide-scrollbars --window-size={},1000 "
            "--virtual-time-budget=5000 --dump-dom 'file://{}' 2>'{}/chromium.log'",
            exe, getuid() == 0 ? "--no-sandbox" : "", (dir / "chromium-profile").string(), width,
            fs::absolute(probe).string(), dir.string());
        const std::string dom = test::shellOutput(cmd, &code);
        EXPECT_EQ(code, 0) << cmd << "\n" << slurp(dir / "chromium.log");
        const size_t a = dom.find("id=\"lbprobe\">");
        if (a == std::string::npos) {
            ADD_FAILURE() << "no measurement in the DOM at " << width << " px:\n"
                          << dom.substr(0, 2000) << "\n"
                          << slurp(dir / "chromium.log");
            return json::object();
        }
        const size_t b = dom.find('<', a + 13);
        std::string text = dom.substr(a + 13, b - a - 13);
        for (size_t p; (p = text.find("&quot;")) != std::string::npos;) text.replace(p, 6, "\"");
        return json::parse(text, nullptr, false);
    }
};

// The matched methods of the equal-time partners in results.json, with
// their number of scenes: the rows the verdict table must have.
std::map<std::string, int> equalTimeMethods(const fs::path& results)
{
    std::map<std::string, int> rows;
    const json doc = json::parse(slurp(results));
    for (const auto& r : doc["records"])
        if (r.contains("equal_time")) ++rows[r["equal_time"]["label"].get<std::string>()];
    return rows;
}

TEST(ReportLayout, PageFitsTheWindowAt800And1400PxAndOpensWithTheVerdicts)
{
    const fs::path dir = test::freshDir("report-layout");
    fs::copy_file(test::sourceDir() + "/tests/plots/data/results.json", dir / "results.json");
    int code = -1;
    const std::string out = test::shellOutput(test::binary() + " report '" + dir.string() + "' 2>&1", &code);
    ASSERT_EQ(code, 0) << out;
    ASSERT_TRUE(fs::exists(dir / "report.html")) << out;
    const std::map<std::string, int> expectRows = equalTimeMethods(dir / "results.json");
    ASSERT_GE(expectRows.size(), 2u);  // the data has equal-time partners of several methods
    const Browser browser;
    if (browser.exe.empty())
        GTEST_SKIP() << "no Chromium on this machine (Debian: apt-get install chromium; scripts/install-deps.sh "
                        "installs it): the page's width in a browser is not checked";
    for (int width : {800, 1400}) {
        const json m = browser.measure(dir, dir / "report.html", width);
        ASSERT_TRUE(m.is_object() && m.contains("scrollWidth")) << m.dump();
        // the viewport as the page sees it: the window without a scroll bar (hidden)
        EXPECT_EQ(m["width"].get<int>(), width) << m.dump();
        EXPECT_LE(m["scrollWidth"].get<int>(), m["width"].get<int>()) << width << " px: " << m.dump();
        EXPECT_EQ(m["sticky"], m["tables"]) << width << " px: every table's first column sticky: " << m.dump();
        EXPECT_EQ(m["wideImages"].get<int>(), 0) << width << " px: " << m.dump();
        // the plots experiment.py made (6: 2 per luminaire, 2 pooled, 2 per height; each wider
        // than 800 px at 300 dpi), scaled to the page
        if (fs::exists(dir / "plots" / "nmse_h0.1_float.png")) {
            EXPECT_EQ(m["images"].get<int>(), 6) << m.dump();
        }
        // The pairs table (14 columns) is wider than 800 px: the check above
        // sees a table that scrolls in its box, not one that happens to fit.
        if (width == 800) {
            EXPECT_GE(m["scrolling"].get<int>(), 1) << m.dump();
        }
        // The answer on the first screen: the verdict table lies wholly inside
        // the window's viewport (857 px high of the 1000 px window; the table
        // ends at 529 px at 800 px wide, 392 px at 1400), before the pictures,
        // one row per method with equal-time partners, wins + ties + losses +
        // off-time = scenes.
        ASSERT_TRUE(m.contains("verdicts")) << width << " px: no #verdicts table: " << m.dump();
        const json& v = m["verdicts"];
        EXPECT_GE(v["top"].get<double>(), 0.0) << v.dump();
        EXPECT_LE(v["bottom"].get<double>(), m["height"].get<double>())
            << width << " px: below the first screen " << v.dump();
        EXPECT_EQ(v["beforeViewer"], true) << v.dump();
        // one column group per baseline (this file has one, MCI): wins / ties / losses in
        // NMSE and FLIP, the off-time pairs, the ratio
        EXPECT_EQ(v["heads"],
                  json({"method", "MCI: NMSE W / T / L", "MCI: FLIP W / T / L", "MCI: off-time", "MCI: NMSE ratio"}))
            << v.dump();
        ASSERT_EQ(v["rows"].size(), expectRows.size()) << v.dump();
        for (const auto& row : v["rows"]) {
            const std::string method = row[0].get<std::string>();
            ASSERT_TRUE(expectRows.count(method)) << method << " " << v.dump();
            int w = 0, t = 0, l = 0;  // "w / t / l", or blank where every pair is off-time
            std::sscanf(row[1].get<std::string>().c_str(), "%d / %d / %d", &w, &t, &l);
            EXPECT_EQ(w + t + l + std::stoi(row[3].get<std::string>()), expectRows.at(method))
                << method << ": pairs at equal time and off-time make every scene " << row.dump();
        }
    }
    // The measurement can fail: one element wider than the window.
    std::ofstream(dir / "wide.html") << "<!DOCTYPE html><html><body><div style=\"width:1200px\">x</div></body></html>";
    const json w = browser.measure(dir, dir / "wide.html", 800);
    ASSERT_TRUE(w.is_object() && w.contains("scrollWidth")) << w.dump();
    EXPECT_GT(w["scrollWidth"].get<int>(), 800) << w.dump();
    fs::remove_all(dir);
}

}  // namespace
}  // namespace lb
