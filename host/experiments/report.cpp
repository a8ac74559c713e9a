#include "experiments/report.h"

#include "experiments/report_bounds.h"
#include "experiments/report_page.h"
#include "experiments/report_table.h"
#include "experiments/report_verdicts.h"
#include "experiments/results.h"
#include "experiments/runner.h"
#include "metrics/image.h"
#include "metrics/metrics.h"
#include "metrics/colour_bar.h"
#include "metrics/tonemap.h"
#include "util/base64.h"
#include "util/error.h"
#include "util/fileio.h"
#include "util/process.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <sys/wait.h>
#include "lb_build_config.h"

namespace lb::experiments {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string str(const json& j, const std::string& key, const std::string& def = "") { return jsonText(j, key, def); }

// The method an equal-time partner was timed against, as the experiment wrote it.
std::string matched(const results::Record& r)
{
    return r.equalTime ? r.equalTime->label : r.equal_time_to.value_or("");
}

// A partner's or MC curve point's baseline label ("MCI" in files of before baselines had names).
std::string baselineOf(const results::Record& r) { return r.baseline ? r.baseline->label : "MCI"; }

// The column a record belongs to: the SPEC as the experiment wrote it, and
// "<baseline>=<spec>" for the equal-time partner of <spec>.
std::string label(const results::Record& r)
{
    if (r.equal_time_to) return baselineOf(r) + "=" + matched(r);
    return str(r.extra, "spec", r.method);
}

// The luminaire as people know it: the name its file gives it (the runner's
// luminaire_name, photometry::displayName), else its file name.
std::string lumName(const results::Record& r)
{
    return str(r.extra, "luminaire_name", fs::path(r.luminaire).filename().string());
}

std::string role(const results::Record& r) { return cellRole(r); }

std::string sci(double v) { return std::isfinite(v) ? fmt::format("{:.3e}", v) : "n/a"; }

// The scene kind and its values ("specular alpha=0.1 eye=[0,4,2]", "disk
// 0.08 x 0.08 m"), "" for the diffuse scene of a 1 x 1 m rectangle, whose
// records carry none.
std::string kindText(const results::Record& r)
{
    if (!r.sceneKeys.is_object() || r.sceneKeys.empty()) return "";
    std::string t = str(r.sceneKeys, "scene_kind");
    const json& k = r.sceneKeys;
    if (k.contains("shape")) t += (t.empty() ? "" : " ") + str(k, "shape", k["shape"].dump());
    if (k.contains("size") && k["size"].is_array() && k["size"].size() == 2)
        t += fmt::format("{}{} x {} m", t.empty() ? "" : " ", k["size"][0].dump(), k["size"][1].dump());
    for (auto it = k.begin(); it != k.end(); ++it)
        if (it.key() != "scene_kind" && it.key() != "shape" && it.key() != "size")
            t += (t.empty() ? "" : " ") + it.key() + "=" + it.value().dump();
    return t;
}

std::string sceneKey(const results::Record& r)
{
    return fmt::format("{}|{}|{}|{}|{}|{}|{}", r.luminaire, r.height, r.rotation, r.res, r.precision, r.device,
                       kindText(r));
}

using report::Cell;
using report::mdLiteral;
using report::num;
using report::Table;

std::string htmlEscape(const std::string& s)
{
    std::string o;
    for (char c : s) {
        switch (c) {
        case '&':
            o += "&amp;";
            break;
        case '<':
            o += "&lt;";
            break;
        case '>':
            o += "&gt;";
            break;
        case '"':
            o += "&quot;";
            break;
        default:
            o += c;
        }
    }
    return o;
}

// The Markdown the notes use (`code`, **bold**, backslash escapes), as HTML.
std::string inlineHtml(const std::string& md)
{
    std::string o;
    bool code = false, bold = false;
    for (size_t i = 0; i < md.size(); ++i) {
        if (!code && md[i] == '\\' && i + 1 < md.size() && std::ispunct(static_cast<unsigned char>(md[i + 1]))) {
            o += htmlEscape(std::string(1, md[++i]));
        } else if (md[i] == '`') {
            o += code ? "</code>" : "<code>";
            code = !code;
        } else if (!code && md[i] == '[' && md.find("](", i) != std::string::npos &&
                   md.find(')', md.find("](", i)) != std::string::npos) {
            // [text](#fragment): the report's own links (record text inside is
            // mdLiteral-escaped, so a '[' of a name never gets here)
            const size_t mid = md.find("](", i), end = md.find(')', mid);
            o += "<a href=\"" + htmlEscape(md.substr(mid + 2, end - mid - 2)) + "\">" +
                inlineHtml(md.substr(i + 1, mid - i - 1)) + "</a>";
            i = end;
        } else if (!code && md.compare(i, 2, "**") == 0) {
            o += bold ? "</b>" : "<b>";
            bold = !bold;
            ++i;
        } else {
            o += htmlEscape(std::string(1, md[i]));
        }
    }
    return o;
}

std::string mdTable(const Table& t)
{
    std::ostringstream o;
    o << "\n## " << t.title << "\n\n";
    if (!t.note.empty()) o << t.note << "\n\n";
    if (t.rows.empty()) {
        o << t.empty << '\n';
        return o.str();
    }
    o << '|';
    for (const auto& h : t.head) o << ' ' << h << " |";
    o << "\n|";
    for (size_t i = 0; i < t.head.size(); ++i) o << "---|";
    o << '\n';
    for (const auto& row : t.rows) {
        o << '|';
        for (const auto& c : row) o << ' ' << c.text << (c.text.empty() ? "|" : " |");
        o << '\n';
    }
    return o.str();
}

std::string htmlTable(const Table& t)
{
    std::ostringstream o;
    o << "<h2>" << htmlEscape(t.title) << "</h2>\n";
    if (!t.note.empty()) o << "<p>" << inlineHtml(t.note) << "</p>\n";
    if (t.rows.empty()) {
        o << "<p>" << inlineHtml(t.empty) << "</p>\n";
        return o.str();
    }
    o << "<table class=\"sortable\"><thead><tr>";
    for (const auto& h : t.head) o << "<th title=\"sort\">" << inlineHtml(h) << "</th>";
    o << "</tr></thead><tbody>\n";
    for (const auto& row : t.rows) {
        o << "<tr>";
        for (const auto& c : row) {
            o << "<td";
            if (std::isfinite(c.sort)) o << fmt::format(" data-sort=\"{}\"", c.sort);
            o << '>' << inlineHtml(c.text) << "</td>";
        }
        o << "</tr>\n";
    }
    o << "</tbody></table>\n";
    return o.str();
}

std::string dataUri(const fs::path& png)
{
    std::string bytes = util::readFile(png.string(), "a PNG picture", size_t(64) << 20);
    return "data:image/png;base64," + util::base64(bytes.data(), bytes.size());
}

// Float32 little-endian samples of an image, base64 (the viewer tone maps them).
std::string floatsB64(const Image& img)
{
    std::vector<float> v(img.px.begin(), img.px.end());
    return util::base64(v.data(), v.size() * sizeof(float));
}

std::string caption(const metrics::Metrics& m)
{
    std::string s = fmt::format("NMSE {:.3g}, UEB {:+.3g} lx, LEB {:+.3g} lx", m.nmse, m.ueb, m.leb);
    if (std::isfinite(m.grad_nmse)) s += fmt::format(", grad_nmse {:.3g}", m.grad_nmse);
    if (std::isfinite(m.flip)) s += fmt::format(", FLIP {:.3g}", m.flip);
    if (m.nonfinite) s += fmt::format(", {} non-finite pixels", m.nonfinite);
    return s;
}

// The viewer's data: {"scenes": [...], "bar": colours}; per scene with saved
// pictures the reference and every method's and equal-time partner's image as
// floats (the page draws their errors at the scene's `bound`), captions.
// Sets `shown`, and `left` to the scenes left out by the size limit.
json viewerData(const std::string& dir, const std::vector<results::Record>& recs,
                const std::map<std::string, SceneScale>& scales, size_t& shown, size_t& left)
{
    std::vector<std::string> order;
    std::map<std::string, std::vector<const results::Record*>> byScene;
    for (const auto& r : recs) {
        const std::string s = str(r.extra, "scene");
        if (s.empty() || role(r) == "mci_curve") continue;
        if (!byScene.count(s)) order.push_back(s);
        byScene[s].push_back(&r);
    }
    json scenes = json::array();
    size_t bytes = 0;
    shown = left = 0;
    for (const auto& s : order) {
        fs::path idir = fs::path(dir) / "images" / s;
        if (!fs::is_regular_file(idir / "reference.exr")) continue;
        if (bytes > kMaxInlineBytes) {
            ++left;
            continue;
        }
        Image ref = readExr((idir / "reference.exr").string());
        const results::Record& r0 = *byScene[s].front();
        double k = 1;
        try {
            k = tonemap::defaultK(ref);
        } catch (const InputError&) {
        }
        json sc = {{"label", s},
                   {"luminaire", lumName(r0)},
                   {"height", r0.height},
                   {"rotation", r0.rotation},
                   {"precision", r0.precision},
                   {"width", ref.width},
                   {"height_px", ref.height},
                   {"k", k},
                   {"bound", scales.count(s) ? scales.at(s).bound : 0.0},
                   {"mean_ref", scales.count(s) ? scales.at(s).meanRef : 0.0},
                   {"unit",
                    r0.sceneKeys.is_object() && r0.sceneKeys.value("scene_kind", json("")) == "specular" ? "cd/m\u00b2"
                                                                                                         : "lx"},
                   {"ref", floatsB64(ref)}};
        json methods = json::array(), mci = json::object();
        std::string primary;  // the baseline of the view "MC at equal time"
        for (const auto* r : byScene[s]) {
            const bool eq = role(*r) == "equal_time";
            const std::string spec = eq ? matched(*r) : label(*r);
            fs::path exr = (idir / cellStem(*r)).string() + ".exr";
            if (!fs::is_regular_file(exr)) continue;
            Image img = readExr(exr.string());
            if (img.width != ref.width || img.height != ref.height) continue;
            const std::string base = eq ? baselineOf(*r) : "";
            const std::string pairText = eq && r->equalTime
                ? fmt::format("; paired: {} {:.4g} ms, {} {:.4g} ms{}", spec, r->equalTime->method_ms, base,
                              r->equalTime->partner_ms, r->equalTime->ok ? "" : ", off-time")
                : std::string();
            json m = {
                {"label",
                 eq ? fmt::format("{} at the time of {} (N = {}{})", base, spec, r->n ? *r->n : 0, pairText) : spec},
                {"img", floatsB64(img)},
                {"caption", caption(r->error)},
                {"ms", r->time_ms.median}};
            // the view "MC at equal time" shows the first baseline; the others are methods of the list
            if (eq && (primary.empty() || primary == base) && !mci.contains(spec)) {
                primary = base;
                mci[spec] = m;
            } else {
                methods.push_back(m);
            }
        }
        sc["methods"] = methods;
        sc["mci"] = mci;
        std::string dump = sc.dump();
        bytes += dump.size();
        scenes.push_back(std::move(sc));
        ++shown;
    }
    return {{"scenes", scenes}, {"bar", tonemap::colourBar(257)}};
}

}  // namespace

// Text from the records (luminaire names, SPECs, the run's context) as
// literal Markdown: every character Markdown or HTML would read as markup
// is backslash-escaped (CommonMark), line breaks become spaces (a table row
// is one line). report.md shows it as written; inlineHtml() undoes the
// escapes and HTML-escapes the character.
std::string report::mdLiteral(const std::string& s)
{
    std::string o;
    for (char c : s) {
        if (c == '\n' || c == '\r') {
            o += ' ';
            continue;
        }
        if (std::strchr("\\`*_[]<>&|~#", c) && c != '\0') o += '\\';
        o += c;
    }
    return o;
}

std::string makePlots(const std::string& dir)
{
    const char* py = std::getenv("LUMIBENCH_PYTHON");
    std::string python = py && *py ? py : "/usr/bin/python3";
    if (!fs::exists(python)) return fmt::format("no Python at {} (set LUMIBENCH_PYTHON)", python);
    std::string script = (fs::path(LB_SOURCE_DIR) / "plots" / "experiment.py").string();
    util::refuseLinksBelow(dir, "plots");  // the scripts' writes would follow a link
    std::string why;
    int code = util::runProcess({python, script, dir}, {}, &why);
    if (code == -1) return fmt::format("could not start {}: {}", python, why);
    if (code == 3) return fmt::format("{} has no matplotlib (Debian: apt-get install python3-matplotlib)", python);
    if (code != 0) return fmt::format("{} failed (exit {})", script, code);
    return "";
}

namespace {

// The report's first table: the run's context (device, commit, ...).
Table runInfo(const results::Results& doc)
{
    const json& c = doc.context;
    Table info{"Run", "", {"", ""}, {}, ""};
    for (const char* k : {"device", "driver", "platform", "commit", "date", "host", "os", "lumibench_version", "shard",
                          "experiment_file", "luminaire_dir"})
        if (c.contains(k))
            info.rows.push_back({{k}, {mdLiteral(c[k].is_string() ? c[k].get<std::string>() : c[k].dump())}});
    std::set<std::string> devices;
    for (const auto& r : doc.records) devices.insert(r.device);
    if (devices.size() > 1) {
        std::string d;
        for (const auto& x : devices) d += x + "; ";
        info.rows.push_back({{"devices in the records"}, {mdLiteral(d)}});
    }
    if (c.contains("merged_from"))
        info.rows.push_back({{"merged from"}, {fmt::format("{} files", c["merged_from"].size())}});
    if (c.contains("commits") && c["commits"].is_array()) {
        std::set<std::string> commits;
        for (const auto& x : c["commits"]) commits.insert(x.is_string() ? x.get<std::string>() : x.dump());
        std::string t;
        for (const auto& x : commits) t += (t.empty() ? "" : ", ") + x;
        info.rows.push_back({{"commits of the inputs"}, {mdLiteral(t)}});
    }
    return info;
}

// The main tables' columns: methods in the order first met, then their
// equal-time partners; and the summary line (records, scenes, pixels, how
// many equal-time pairs met the tolerance).
std::vector<std::string> columns(const results::Results& doc, std::string* summary)
{
    std::vector<std::string> cols;
    std::set<std::string> scenes, partnerCols;
    size_t eqOk = 0, eqAll = 0, eqClosest = 0;
    for (const auto& r : doc.records) {
        scenes.insert(sceneKey(r));
        if (role(r) == "mci_curve") continue;
        if (std::find(cols.begin(), cols.end(), label(r)) == cols.end()) cols.push_back(label(r));
        if (r.equal_time_to) {
            partnerCols.insert(label(r));
            ++eqAll;
            const bool ok = r.equalTime && r.equalTime->ok;
            eqOk += ok;
            eqClosest += ok || (r.equalTime && r.equalTime->bracketed);
        }
    }
    std::stable_partition(cols.begin(), cols.end(), [&](const std::string& s) { return !partnerCols.count(s); });
    int res = doc.records.empty() ? 0 : doc.records.front().res;
    int timeRes = doc.records.empty() ? 0 : doc.records.front().time_ms.res;
    double tol = doc.context.value("equal_time_tolerance", NAN);
    *summary = fmt::format(
        "{} records, {} scenes, {} x {} pixels{}; {} of {} equal-time MC partners ({:.0f} %) within "
        "{} of the matched method's time in their paired rounds (the `ratio` of the equal-time pairs): the "
        "others are off-time and give no verdict; {} ({:.0f} %) within or at the closest integer N.\n"
        "Times are OpenCL profiling-event medians (DESIGN section 6); errors against the reference (section 5). "
        "The same records as a table: `results.csv`.\n",
        doc.records.size(), scenes.size(), res, res,
        timeRes > 0 ? fmt::format(", timed at {} x {}", timeRes, timeRes) : std::string(), eqOk, eqAll,
        eqAll ? 100.0 * eqOk / eqAll : 0.0,
        std::isfinite(tol) ? fmt::format("+-{:g} %", 100 * tol) : std::string("the tolerance"), eqClosest,
        eqAll ? 100.0 * eqClosest / eqAll : 0.0);

    return cols;
}

// Main tables: per luminaire, precision and height, the rotations' images
// pooled into one (metrics::pooled: the thesis' stitched image), of metric `key`.
Table mainTable(const results::Results& doc, const std::vector<std::string>& cols, const std::string& key,
                const std::string& heading, const std::string& note)
{
    struct Acc {
        std::vector<metrics::Metrics> parts;
        double nsum = 0;
    };
    std::map<std::tuple<std::string, std::string, std::string, double>, std::map<std::string, Acc>> rows;
    std::map<std::string, std::string> names;  // luminaire file -> the name shown
    std::map<std::string, std::string> partnerOf;  // partner column -> its method
    std::set<std::string> baselines;
    size_t carried = 0;
    bool kinds = false;  // records of a scene kind other than diffuse: a column for it
    for (const auto& r : doc.records) {
        if (role(r) == "mci_curve") continue;
        kinds = kinds || !kindText(r).empty();
        auto& a = rows[{r.luminaire, kindText(r), r.precision, r.height}][label(r)];
        if (r.equal_time_to) partnerOf[label(r)] = matched(r), baselines.insert(baselineOf(r));
        names[r.luminaire] = lumName(r);
        a.parts.push_back(r.error);
        carried += std::isfinite(metrics::minimisable(r.error, key));
        if (r.n) a.nsum += r.equalTime ? r.equalTime->n : double(*r.n);  // N + extra: MC's mean count
    }
    Table t{heading, note, {"luminaire", "precision", "h"}, {}, ""};
    if (kinds) t.head.insert(t.head.begin() + 1, "scene");
    if (carried == 0) {
        t.empty = fmt::format("No record carries {} (records of an older lumibench{}).", key,
                              key == "flip" ? ", or flip-evaluator was not available: scripts/install-deps.sh" : "");
        return t;
    }
    t.note += "B=M is Monte Carlo baseline B at the time of method M (its mean N over the rotations in brackets)";
    t.note += baselines.size() == 1 ? "; M / B is the ratio of the two (below 1: M is better)." : ".";
    t.note += " The lowest of each row is bold.";
    for (const auto& col : cols) t.head.push_back(mdLiteral(col));
    std::vector<std::string> ratioOf;  // the methods with a partner column, where there is one baseline
    for (const auto& [col, m] : partnerOf)
        if (baselines.size() == 1 && std::find(cols.begin(), cols.end(), m) != cols.end()) ratioOf.push_back(m);
    const std::string base = baselines.empty() ? "" : *baselines.begin();
    for (const auto& m : ratioOf) t.head.push_back(mdLiteral(m) + " / " + mdLiteral(base));
    for (const auto& [k, m] : rows) {
        std::vector<Cell> row = {{mdLiteral(names[std::get<0>(k)])},
                                 {mdLiteral(std::get<2>(k))},
                                 num(std::get<3>(k), fmt::format("{}", std::get<3>(k)))};
        if (kinds) row.insert(row.begin() + 1, Cell{mdLiteral(std::get<1>(k))});
        std::map<std::string, double> value;
        for (const auto& [col, acc] : m) value[col] = metrics::minimisable(metrics::pooled(acc.parts), key);
        double best = INFINITY;  // bold where there is a choice: two values or more
        int finite = 0;
        for (const auto& [col, v] : value)
            if (std::isfinite(v)) best = std::min(best, v), ++finite;
        if (finite < 2) best = NAN;
        for (const auto& col : cols) {
            auto it = m.find(col);
            if (it == m.end()) {
                row.push_back({});
                continue;
            }
            const double v = value[col];
            std::string text = sci(v);
            if (v == best) text = "**" + text + "**";
            if (partnerOf.count(col))
                text += fmt::format(" ({:.0f})", it->second.nsum / double(it->second.parts.size()));
            row.push_back(num(v, text));
        }
        for (const auto& mname : ratioOf) {
            const bool both = value.count(mname) && value.count(base + "=" + mname);
            const double q = both ? value[mname] / value[base + "=" + mname] : NAN;
            row.push_back(both ? num(q, std::isfinite(q) ? fmt::format("{:.3g}", q) : "n/a") : Cell{});
        }
        t.rows.push_back(std::move(row));
    }
    return t;
}

// Relative times (paper Table 1) and each method's kernel form.
Table timesTable(const results::Results& doc, const std::vector<std::string>& cols)
{
    // geometric mean over scenes of the median over the reference method's
    // median: `point` (paper Table 1), else the first method of the tables
    const bool point =
        std::any_of(doc.records.begin(), doc.records.end(), [](const auto& r) { return label(r) == "point"; });
    const std::string refMethod = point || cols.empty() ? "point" : cols.front();
    std::map<std::string, double> pointMs;
    for (const auto& r : doc.records)
        if (label(r) == refMethod) pointMs[sceneKey(r)] = r.time_ms.median;
    std::map<std::string, std::pair<double, int>> rel, abs;
    std::map<std::string, std::pair<int, int>> forms;  // label -> (straight-line, general) records
    for (const auto& r : doc.records) {
        if (role(r) == "mci_curve") continue;
        const std::string form = r.extra.contains("stats") ? str(r.extra["stats"], "form") : "";
        if (form == "straight-line") ++forms[label(r)].first;
        if (form == "general") ++forms[label(r)].second;
        auto& b = abs[label(r)];
        b.first += r.time_ms.median;
        ++b.second;
        auto p = pointMs.find(sceneKey(r));
        if (p != pointMs.end() && p->second > 0 && r.time_ms.median > 0) {
            auto& a = rel[label(r)];
            a.first += std::log(r.time_ms.median / p->second);
            ++a.second;
        }
    }
    Table times{
        "Run time (paper Table 1)",
        fmt::format("Mean median kernel time over the scenes, and the geometric mean over the scenes of the time "
                    "relative to `{}`{}. Kernel form: whether the timed kernel was the method's straight-line "
                    "form or its general kernel (records' `stats.form`; blank for methods with one form). An "
                    "equal-time verdict is fair only where the method ran its fastest form.",
                    mdLiteral(refMethod), point ? "" : " (these results have no `point`, the paper's reference)"),
        {"method", "time (ms)", "relative to " + mdLiteral(refMethod), "kernel form"},
        {},
        ""};
    for (const auto& col : cols) {
        auto a = abs[col];
        auto rr = rel.find(col);
        auto [straight, general] = forms[col];
        std::string form = general == 0 ? (straight ? "straight-line" : "")
            : straight == 0             ? "**general**"
                                        : fmt::format("**general** in {} of {} scenes", general, straight + general);
        const double ms = a.second ? a.first / a.second : NAN;
        const double relv = rr != rel.end() && rr->second.second ? std::exp(rr->second.first / rr->second.second) : NAN;
        times.rows.push_back({{mdLiteral(col)},
                              num(ms, fmt::format("{:.4f}", ms)),
                              num(relv, std::isfinite(relv) ? fmt::format("{:.2f}", relv) : "n/a"),
                              {form}});
    }
    return times;
}

// The luminaires: the name shown in the tables (the file's own, lumName)
// beside the file the records name.
Table luminairesTable(const results::Results& doc)
{
    Table t{"Luminaires",
            "The tables name a luminaire as its file does (IES `[LUMINAIRE]` and `[LUMCAT]`, EULUMDAT fields 9 "
            "and 10); the file, relative to `luminaire_dir`, is `luminaire` in results.csv.",
            {"name shown", "file"},
            {},
            "No records."};
    std::set<std::string> seen;
    for (const auto& r : doc.records)
        if (seen.insert(r.luminaire).second) t.rows.push_back({{mdLiteral(lumName(r))}, {mdLiteral(r.luminaire)}});
    return t;
}

// A value with its 95 % interval where the record has one (seeds > 1).
std::string withInterval(const results::Record& r, double v, const std::string& key)
{
    auto it = r.ci95.find(key);
    if (it == r.ci95.end()) return sci(v);
    return fmt::format("{} [{}, {}]", sci(v), sci(it->second[0]), sci(it->second[1]));
}

// Every equal-time pair: the two times of its paired rounds and the errors.
Table pairsTable(const results::Results& doc)
{
    Table pairs{"Equal-time pairs",
                "t method and t MC are the medians of the same alternating rounds (method, then the baseline's MC at "
                "N, round after round); ratio is the median over those rounds of t MC / t method, (!) where it lies "
                "outside the tolerance: the pair is off-time and its verdict `off-time`. "
                "N is the MC's mean sample count (N + extra). The MC's errors are means over its seeds "
                "with their 95 % intervals in brackets; the verdict (NMSE) is a win where the method's interval "
                "(or value) lies below the MC's, a loss where above, a tie where they overlap.",
                {"luminaire", "h", "R (rad)", "method", "baseline", "t method (ms)", "N", "t MC (ms)", "ratio",
                 "NMSE method", "NMSE MC", "verdict", "grad_nmse method", "grad_nmse MC", "FLIP method", "FLIP MC"},
                {},
                ""};
    for (const results::Pair& p : results::pairsOf(doc.records)) {
        const results::Record& r = *p.partner;
        auto of = [&](double metrics::Metrics::*f, const char* key) {
            double v = p.method ? p.method->error.*f : NAN;
            return num(v, p.method ? withInterval(*p.method, v, key) : sci(v));
        };
        const results::EqualTime et = r.equalTime.value_or(results::EqualTime{});
        const char* v = p.method ? results::verdictName(results::verdict(*p.method, r)) : "n/a";
        pairs.rows.push_back({{mdLiteral(lumName(r))},
                              num(r.height, fmt::format("{}", r.height)),
                              num(r.rotation, fmt::format("{:.4f}", r.rotation)),
                              {mdLiteral(matched(r))},
                              {mdLiteral(baselineOf(r))},
                              num(et.method_ms, fmt::format("{:.4f}", et.method_ms)),
                              num(et.n, fmt::format("{:g}", et.n)),
                              num(et.partner_ms, fmt::format("{:.4f}", et.partner_ms)),
                              num(et.ratio, fmt::format("{:.3f}{}", et.ratio, et.ok ? "" : " (!)")),
                              of(&metrics::Metrics::nmse, "nmse"),
                              num(r.error.nmse, withInterval(r, r.error.nmse, "nmse")),
                              {v},
                              of(&metrics::Metrics::grad_nmse, "grad_nmse"),
                              num(r.error.grad_nmse, withInterval(r, r.error.grad_nmse, "grad_nmse")),
                              of(&metrics::Metrics::flip, "flip"),
                              num(r.error.flip, withInterval(r, r.error.flip, "flip"))});
    }
    return pairs;
}

// What report.md and report.html both show.
struct ReportContent {
    std::string title;
    std::string description;  // the experiment's, Markdown literal
    std::string headline;  // the answer in one sentence, first on the page
    Table verdicts, details;  // the verdicts per method and baseline, then the off-time pairs and losses
    Table info;
    std::string summary;
    std::vector<Table> tables;
    fs::path plotDir;
    std::vector<std::string> pngs;  // in plotDir
    std::vector<std::string> grids;  // in plotDir/grids: one figure per scene, linked, not inlined
    std::string plotsMissing;  // why there are none, where there are none
};

// DIR/plots/*.png: NMSE first, then grad_nmse, FLIP and the image grids, each by name.
std::vector<std::string> plotFiles(const fs::path& pd)
{
    std::vector<std::string> pngs;
    if (fs::is_directory(pd))
        for (const auto& e : fs::directory_iterator(pd))
            if (e.path().extension() == ".png") pngs.push_back(e.path().filename().string());
    auto rank = [](const std::string& f) {
        return f.rfind("nmse_", 0) == 0 ? 0 : f.rfind("grad_nmse_", 0) == 0 ? 1 : f.rfind("flip_", 0) == 0 ? 2 : 3;
    };
    std::sort(pngs.begin(), pngs.end(), [&](const std::string& a, const std::string& b) {
        return std::make_pair(rank(a), a) < std::make_pair(rank(b), b);
    });
    return pngs;
}

ReportContent reportContent(const std::string& dir, const results::Results& doc, const std::string& plotNote,
                            const std::map<std::string, size_t>& viewerIndex)
{
    ReportContent c;
    c.title = "Experiment " + mdLiteral(str(doc.context, "experiment", "?"));
    if (doc.context.contains("experiment_spec") && doc.context["experiment_spec"].is_object())
        c.description = mdLiteral(str(doc.context["experiment_spec"], "description"));
    VerdictReport v = verdictReport(doc, viewerIndex);
    c.headline = v.headline;
    c.verdicts = std::move(v.verdicts);
    c.details = std::move(v.details);
    c.info = runInfo(doc);
    const std::vector<std::string> cols = columns(doc, &c.summary);
    const std::string pooledNote =
        "Each cell is the error of the rotations' images stitched into one, as in the thesis: squared errors summed "
        "over all rotations' pixels, against the pooled means (`metrics::pooled`; docs/studies/thesis-sct-vs-mci.md), "
        "not the mean of the rotations' values, which one nearly dark rotation can dominate. ";
    c.tables = {
        mainTable(doc, cols, "nmse", "NMSE per luminaire and height (rotations stitched)", pooledNote),
        mainTable(doc, cols, "grad_nmse", "grad_nmse per luminaire and height (rotations stitched)",
                  "NMSE of the neighbouring-pixel differences: ripples and bumps, not a smooth bias. " + pooledNote),
        mainTable(doc, cols, "flip", "FLIP per luminaire and height (pixel mean over the rotations)",
                  "Mean HDR-FLIP (NVIDIA flip-evaluator), in [0, 1], over all rotations' pixels. "),
        timesTable(doc, cols)};
    if (std::any_of(doc.records.begin(), doc.records.end(), [](const auto& r) { return bool(r.equal_time_to); }))
        c.tables.push_back(pairsTable(doc));
    c.tables.push_back(luminairesTable(doc));
    c.plotDir = fs::path(dir) / "plots";
    c.pngs = plotFiles(c.plotDir);
    c.grids = plotFiles(c.plotDir / "grids");
    if (!plotNote.empty())
        c.plotsMissing = "Plots not made: " + plotNote + ".";
    else if (c.pngs.empty())
        c.plotsMissing = "No plots in `plots/` (run `lumibench report DIR`).";
    return c;
}

// The per-scene image grids: a list of links (PNG and the PDF beside it).
std::string gridsMarkdown(const std::vector<std::string>& grids)
{
    if (grids.empty()) return "";
    std::string o = fmt::format("\n## Image grids\n\nReference | method | error of every method and its MCI "
                                "partner, one figure per scene ({}), the error pictures on the scene's one scale "
                                "with its colour bar: PNG (300 dpi) and PDF in `plots/grids/`.\n\n",
                                grids.size());
    for (const auto& g : grids) {
        const std::string stem = g.substr(0, g.size() - 4);
        o += fmt::format("- [{}](plots/grids/{}) ([PDF](plots/grids/{}.pdf))\n", mdLiteral(stem), g, stem);
    }
    return o;
}

std::string reportMarkdown(const ReportContent& c)
{
    std::ostringstream o;
    o << "# " << c.title << "\n\n";
    if (!c.headline.empty()) o << c.headline << "\n\n";
    if (!c.description.empty()) o << c.description << "\n";
    o << mdTable(c.verdicts) << mdTable(c.details) << "\n## Run\n\n| | |\n|---|---|\n";
    for (const auto& row : c.info.rows) o << "| " << row[0].text << " | " << row[1].text << " |\n";
    o << '\n' << c.summary;
    for (const auto& t : c.tables) o << mdTable(t);
    o << "\n## Plots\n\n";
    if (!c.plotsMissing.empty()) o << c.plotsMissing << "\n\n";
    for (const auto& p : c.pngs) o << fmt::format("![{}](plots/{})\n\n", p, p);
    o << gridsMarkdown(c.grids);
    return o.str();
}

// The page's picture viewer section (its data goes in at the end of the page).
std::string viewerSection(size_t shown, size_t left)
{
    std::ostringstream o;
    o << "<section id=\"viewer\"><h2>Pictures</h2>\n";
    if (shown == 0)
        o << "<p>No saved pictures (the experiment's <code>save_images</code> is off, or <code>images/</code> is "
             "missing).</p>\n";
    else
        o << report_page::kViewerHtml;
    if (left)
        o << fmt::format("<p>{} more scenes with pictures are not inlined (the page holds at most {} MB of "
                         "pictures); they are in <code>images/</code>.</p>\n",
                         left, kMaxInlineBytes >> 20);
    o << "</section>\n";
    return o.str();
}

std::string reportHtml(const ReportContent& c, const json& viewer, size_t shown, size_t left)
{
    std::ostringstream o;
    o << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>" << inlineHtml(c.title)
      << "</title>\n<style>" << report_page::kCss << "</style></head>\n<body>\n<h1>" << inlineHtml(c.title)
      << "</h1>\n";
    if (!c.headline.empty()) o << "<p class=\"headline\">" << inlineHtml(c.headline) << "</p>\n";
    if (!c.description.empty()) o << "<p class=\"description\">" << inlineHtml(c.description) << "</p>\n";
    o << "<section id=\"verdicts\">" << htmlTable(c.verdicts) << "</section>\n<section id=\"offtime\">"
      << htmlTable(c.details) << "</section>\n<h2>Run</h2>\n<table class=\"info\">";
    for (const auto& row : c.info.rows)
        o << "<tr><th>" << inlineHtml(row[0].text) << "</th><td>" << inlineHtml(row[1].text) << "</td></tr>";
    o << "</table>\n<p>" << inlineHtml(c.summary) << " Click a column head to sort.</p>\n";
    o << "<nav>Sections: <a href=\"#viewer\">pictures</a>";
    for (size_t i = 0; i < c.tables.size(); ++i)
        o << fmt::format(" · <a href=\"#t{}\">{}</a>", i, htmlEscape(c.tables[i].title));
    o << " · <a href=\"#plots\">plots</a></nav>\n";
    o << viewerSection(shown, left);
    for (size_t i = 0; i < c.tables.size(); ++i)
        o << fmt::format("<section id=\"t{}\">", i) << htmlTable(c.tables[i]) << "</section>\n";
    o << "<section id=\"plots\"><h2>Plots</h2>\n";
    if (!c.plotsMissing.empty()) o << "<p>" << inlineHtml(c.plotsMissing) << "</p>\n";
    for (const auto& p : c.pngs)
        o << "<figure><img alt=\"" << htmlEscape(p) << "\" src=\"" << dataUri(c.plotDir / p) << "\"><figcaption>"
          << htmlEscape(p) << "</figcaption></figure>\n";
    if (!c.grids.empty()) {
        o << "<h3>Image grids</h3>\n<ul class=\"grids\">";
        for (const auto& g : c.grids) {
            const std::string stem = g.substr(0, g.size() - 4);
            o << fmt::format("<li><a href=\"plots/grids/{0}\">{1}</a> (<a href=\"plots/grids/{1}.pdf\">PDF</a>)</li>",
                             htmlEscape(g), htmlEscape(stem));
        }
        o << "</ul>\n<p>One figure per scene (reference | method | error on the scene's one scale, with its "
             "colour bar), beside this page in <code>plots/grids/</code>; the viewer above shows the same "
             "pictures.</p>\n";
    }
    o << "</section>\n";
    std::string data = viewer.dump();
    // JSON inside <script>: "</script" would end the element and "<!--" opens
    // an HTML comment state that can swallow it. '<' and '>' occur only inside
    // JSON strings, where \u003c and \u003e mean the same characters.
    for (size_t pos = 0; (pos = data.find_first_of("<>", pos)) != std::string::npos;)
        data.replace(pos, 1, data[pos] == '<' ? "\\u003c" : "\\u003e");
    o << "<script type=\"application/json\" id=\"lbdata\">" << data << "</script>\n<script>" << report_page::kScript
      << "</script>\n</body></html>\n";
    return o.str();
}

}  // namespace

void writeReport(const std::string& dir, const std::string& plotNote, const std::map<std::string, SceneScale>* scales)
{
    results::Results doc = results::load((fs::path(dir) / "results.json").string());
    results::dedupe(doc.records);  // files of older versions may hold two partners of one method
    nameLuminaires(doc);
    size_t shown = 0, left = 0;
    const std::map<std::string, SceneScale> own =
        scales ? std::map<std::string, SceneScale>{} : shareErrorBounds(dir, doc.records);
    json viewer = viewerData(dir, doc.records, scales ? *scales : own, shown, left);
    std::map<std::string, size_t> viewerIndex;  // scene label -> its index in the viewer (the #scene= fragment)
    for (size_t i = 0; i < viewer["scenes"].size(); ++i)
        viewerIndex[viewer["scenes"][i]["label"].get<std::string>()] = i;
    const ReportContent c = reportContent(dir, doc, plotNote, viewerIndex);
    util::writeFileAtomic((fs::path(dir) / "report.md").string(), reportMarkdown(c));
    util::writeFileAtomic((fs::path(dir) / "report.html").string(), reportHtml(c, viewer, shown, left));
}

void makeReport(const std::string& dir, const ReportSteps& steps)
{
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
    auto say = [&](const std::string& line) {
        if (steps.progress) std::cerr << fmt::format("[{}] report {} ({:.1f} s)\n", steps.tag, line, since(t0));
    };
    util::refuseLinksBelow(dir, "images", true);  // the error pictures are written again in its folders
    results::Results doc = results::load((fs::path(dir) / "results.json").string());
    results::dedupe(doc.records);
    say("1/3: error pictures on one bound per scene (images/)");
    const std::map<std::string, SceneScale> scales = shareErrorBounds(dir, doc.records);
    std::string note = steps.plotNote;
    if (note.empty()) {
        say(fmt::format("2/3: plots, and an image grid for each of {} scenes (plots/experiment.py)", scales.size()));
        note = makePlots(dir);
        if (!note.empty()) std::cerr << "lumibench: warning: plots not made: " << note << '\n';
    }
    say("3/3: report.md and report.html");
    writeReport(dir, note, &scales);
    say(fmt::format("done: {}/report.html", dir));
}

}  // namespace lb::experiments
