#include "experiments/report.h"

#include "experiments/results.h"
#include "metrics/metrics.h"
#include "util/error.h"
#include "util/fileio.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <sys/wait.h>

namespace lb::experiments {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string str(const json& j, const std::string& key, const std::string& def = "")
{
    return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : def;
}

// The column a record belongs to: the SPEC as the experiment wrote it, and
// "MCI=<spec>" for the equal-time partner of <spec>.
std::string label(const results::Record& r)
{
    if (r.equal_time_to) return "MCI=" + str(r.extra, "equal_time_label", *r.equal_time_to);
    return str(r.extra, "spec", r.method);
}

std::string role(const results::Record& r)
{
    return r.equal_time_to ? "equal_time" : str(r.extra, "role", "method");
}

std::string sci(double v) { return std::isfinite(v) ? fmt::format("{:.3e}", v) : "n/a"; }

std::string sceneKey(const results::Record& r)
{
    return fmt::format("{}|{}|{}|{}|{}|{}", r.luminaire, r.height, r.rotation, r.res, r.precision, r.device);
}

} // namespace

std::string makePlots(const std::string& dir)
{
    const char* py = std::getenv("LUMIBENCH_PYTHON");
    std::string python = py && *py ? py : "/usr/bin/python3";
    if (!fs::exists(python)) return fmt::format("no Python at {} (set LUMIBENCH_PYTHON)", python);
    std::string script = (fs::path(LB_SOURCE_DIR) / "plots" / "experiment.py").string();
    std::string cmd = fmt::format("'{}' '{}' '{}'", python, script, dir);
    int rc = std::system(cmd.c_str());
    if (rc == -1) return "could not start " + python;
    int code = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    if (code == 3) return fmt::format("{} has no matplotlib (Debian: apt-get install python3-matplotlib)", python);
    if (code != 0) return fmt::format("{} failed (exit {})", script, code);
    return "";
}

void writeReport(const std::string& dir, const std::string& plotNote)
{
    const std::string path = (fs::path(dir) / "results.json").string();
    results::Results doc = results::load(path);
    results::dedupe(doc.records);  // files of older versions may hold two partners of one method
    const json& c = doc.context;
    std::ostringstream o;

    o << fmt::format("# Experiment `{}`\n\n", str(c, "experiment", "?"));
    o << "| | |\n|---|---|\n";
    for (const char* k : {"device", "driver", "platform", "commit", "date", "host", "os", "lumibench_version", "shard",
                          "experiment_file", "luminaire_dir"})
        if (c.contains(k)) o << fmt::format("| {} | {} |\n", k, c[k].is_string() ? c[k].get<std::string>() : c[k].dump());
    std::set<std::string> devices, drivers;
    for (const auto& r : doc.records) {
        devices.insert(r.device);
        drivers.insert(r.driver);
    }
    if (devices.size() > 1) {
        o << "| devices in the records |";
        for (const auto& d : devices) o << ' ' << d << ';';
        o << " |\n";
    }
    if (c.contains("merged_from")) o << fmt::format("| merged from | {} files |\n", c["merged_from"].size());

    // Columns: methods in the order first met, then their equal-time partners.
    std::vector<std::string> cols;
    std::set<std::string> scenes;
    size_t eqOk = 0, eqAll = 0, eqClosest = 0;
    for (const auto& r : doc.records) {
        scenes.insert(sceneKey(r));
        if (role(r) == "mci_curve") continue;
        if (std::find(cols.begin(), cols.end(), label(r)) == cols.end()) cols.push_back(label(r));
        if (r.equal_time_to) {
            ++eqAll;
            eqOk += r.extra.value("equal_time_ok", false);
            eqClosest += r.extra.value("equal_time_ok", false) || r.extra.value("equal_time_bracketed", false);
        }
    }
    std::stable_partition(cols.begin(), cols.end(), [](const std::string& s) { return s.rfind("MCI=", 0) != 0; });
    int res = doc.records.empty() ? 0 : doc.records.front().res;
    int timeRes = doc.records.empty() ? 0 : doc.records.front().time_ms.res;
    double tol = doc.context.value("equal_time_tolerance", NAN);
    o << fmt::format("\n{} records, {} scenes, {} x {} pixels{}; {} of {} equal-time MCI partners ({:.0f} %) within "
                     "{} of the matched method's median time, {} ({:.0f} %) within or at the closest integer N.\n",
                     doc.records.size(), scenes.size(), res, res,
                     timeRes > 0 ? fmt::format(", timed at {} x {}", timeRes, timeRes) : std::string(), eqOk, eqAll,
                     eqAll ? 100.0 * eqOk / eqAll : 0.0,
                     std::isfinite(tol) ? fmt::format("+-{:g} %", 100 * tol) : std::string("the tolerance"), eqClosest,
                     eqAll ? 100.0 * eqClosest / eqAll : 0.0);
    o << "Times are OpenCL profiling-event medians (DESIGN section 6); errors against the reference (section 5).\n";

    // Main tables: the mean of each error metric over the rotations per
    // luminaire and height (NMSE, then grad_nmse and flip of DESIGN section 5).
    auto table = [&](const std::string& key, const std::string& title, const std::string& note) {
        struct Acc {
            double sum = 0;
            int n = 0;
            double nsum = 0;
            int records = 0;
        };
        std::map<std::tuple<std::string, std::string, double>, std::map<std::string, Acc>> rows;
        size_t carried = 0;
        for (const auto& r : doc.records) {
            if (role(r) == "mci_curve") continue;
            auto& a = rows[{r.luminaire, r.precision, r.height}][label(r)];
            const double v = metrics::minimisable(r.error, key);
            if (std::isfinite(v)) {
                a.sum += v;
                ++a.n;
                ++carried;
            }
            if (r.n) a.nsum += double(*r.n);
            ++a.records;
        }
        o << fmt::format("\n## {} per luminaire and height (mean over the rotations)\n\n{}", title, note);
        if (carried == 0) {
            o << fmt::format("No record carries {} (records of an older lumibench{}).\n", key,
                             key == "flip" ? ", or flip-evaluator was not available: scripts/install-deps.sh" : "");
            return;
        }
        o << "MCI=M is Monte Carlo at the time of method M (its mean N in brackets).\n\n";
        o << "| luminaire | precision | h |";
        for (const auto& col : cols) o << ' ' << col << " |";
        o << "\n|---|---|---|";
        for (size_t i = 0; i < cols.size(); ++i) o << "---|";
        o << '\n';
        for (const auto& [k, m] : rows) {
            o << fmt::format("| {} | {} | {} |", std::get<0>(k), std::get<1>(k), std::get<2>(k));
            for (const auto& col : cols) {
                auto it = m.find(col);
                if (it == m.end() || it->second.n == 0) {
                    o << " |";
                    continue;
                }
                o << ' ' << sci(it->second.sum / it->second.n);
                if (col.rfind("MCI=", 0) == 0) o << fmt::format(" ({:.0f})", it->second.nsum / it->second.records);
                o << " |";
            }
            o << '\n';
        }
    };
    table("nmse", "NMSE", "");
    table("grad_nmse", "grad_nmse",
          "NMSE of the neighbouring-pixel differences: ripples and bumps, not a smooth bias.\n");
    table("flip", "FLIP", "Mean HDR-FLIP (NVIDIA flip-evaluator), in [0, 1].\n");

    // Relative times (paper Table 1): geometric mean over scenes of the median over point's median.
    std::map<std::string, double> pointMs;
    for (const auto& r : doc.records)
        if (label(r) == "point") pointMs[sceneKey(r)] = r.time_ms.median;
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
    o << "\n## Run time (paper Table 1)\n\nMean median kernel time over the scenes, and the geometric mean over "
         "the scenes of the time relative to `point`. Kernel form: whether the timed kernel was the method's "
         "straight-line form or its general kernel (records' `stats.form`; blank for methods with one form). "
         "An equal-time verdict is fair only where the method ran its fastest form.\n\n"
         "| method | time (ms) | relative to point | kernel form |\n|---|---|---|---|\n";
    for (const auto& col : cols) {
        auto a = abs[col];
        auto rr = rel.find(col);
        auto [straight, general] = forms[col];
        std::string form = general == 0 ? (straight ? "straight-line" : "")
                           : straight == 0 ? "**general**"
                                           : fmt::format("**general** in {} of {} scenes", general, straight + general);
        o << fmt::format("| {} | {:.4f} | {} | {} |\n", col, a.second ? a.first / a.second : NAN,
                         rr != rel.end() && rr->second.second ? fmt::format("{:.2f}", std::exp(rr->second.first / rr->second.second))
                                                               : "n/a",
                         form);
    }

    // Equal-time pairs.
    if (eqAll) {
        std::map<std::string, metrics::Metrics> errBy;  // scene|label -> errors
        for (const auto& r : doc.records) errBy[sceneKey(r) + "|" + str(r.extra, "spec", r.method)] = r.error;
        o << "\n## Equal-time pairs\n\n| luminaire | h | R (rad) | method | t method (ms) | N | t MCI (ms) | ratio | "
             "NMSE method | NMSE MCI | grad_nmse method | grad_nmse MCI | FLIP method | FLIP MCI |\n"
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
        for (const auto& r : doc.records) {
            if (!r.equal_time_to) continue;
            std::string m = str(r.extra, "equal_time_label", *r.equal_time_to);
            auto it = errBy.find(sceneKey(r) + "|" + m);
            auto of = [&](double metrics::Metrics::*f) { return it != errBy.end() ? sci(it->second.*f) : "n/a"; };
            o << fmt::format("| {} | {} | {:.4f} | {} | {:.4f} | {} | {:.4f} | {:.3f}{} | {} | {} | {} | {} | {} | {} |\n",
                             r.luminaire, r.height, r.rotation, m, r.extra.value("equal_time_target_ms", NAN),
                             r.n ? *r.n : 0, r.time_ms.median, r.extra.value("equal_time_ratio", NAN),
                             r.extra.value("equal_time_ok", false) ? "" : " (!)", of(&metrics::Metrics::nmse),
                             sci(r.error.nmse), of(&metrics::Metrics::grad_nmse), sci(r.error.grad_nmse),
                             of(&metrics::Metrics::flip), sci(r.error.flip));
        }
    }

    // Plots.
    o << "\n## Plots\n\n";
    std::vector<std::string> pngs;
    fs::path pd = fs::path(dir) / "plots";
    if (fs::is_directory(pd))
        for (const auto& e : fs::directory_iterator(pd))
            if (e.path().extension() == ".png") pngs.push_back(e.path().filename().string());
    std::sort(pngs.begin(), pngs.end());
    if (!plotNote.empty()) o << "Plots not made: " << plotNote << ".\n\n";
    for (const auto& p : pngs) o << fmt::format("![{}](plots/{})\n\n", p, p);
    if (pngs.empty() && plotNote.empty()) o << "No plots in `plots/` (run `lumibench report DIR`).\n";

    util::writeFileAtomic((fs::path(dir) / "report.md").string(), o.str());
}

} // namespace lb::experiments
