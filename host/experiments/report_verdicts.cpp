#include "experiments/report_verdicts.h"

#include "experiments/report_bounds.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lb::experiments {

using nlohmann::json;
using report::Cell;
using report::mdLiteral;
using report::num;
using report::Table;

namespace {

std::string methodOf(const results::Record& partner)
{
    return partner.equalTime && !partner.equalTime->label.empty() ? partner.equalTime->label
                                                                  : partner.equal_time_to.value_or("");
}

std::string baselineOf(const results::Record& partner) { return partner.baseline ? partner.baseline->label : "MCI"; }

void count(VerdictCount& c, results::Verdict v)
{
    c.win += v == results::Verdict::Win;
    c.tie += v == results::Verdict::Tie;
    c.loss += v == results::Verdict::Loss;
    c.undefined += v == results::Verdict::Undefined;
}

// The run's baselines in their order: the context's list, then any other met.
std::vector<std::string> baselineOrder(const results::Results& doc)
{
    std::vector<std::string> out;
    const json& c = doc.context;
    if (c.is_object() && c.contains("baselines") && c["baselines"].is_array())
        for (const auto& b : c["baselines"])
            if (b.is_object() && b.contains("label") && b["label"].is_string())
                out.push_back(b["label"].get<std::string>());
    return out;
}

std::string wtl(const VerdictCount& c)
{
    if (c.onTime() == 0) return "";
    std::string t = fmt::format("{} / {} / {}", c.win, c.tie, c.loss);
    if (c.undefined) t += fmt::format(" ({} n/a)", c.undefined);
    return t;
}

std::string sceneLink(const results::Record& r, const std::map<std::string, size_t>& viewerIndex)
{
    const std::string scene = jsonText(r.extra, "scene", r.luminaire);
    auto vi = viewerIndex.find(scene);
    return vi == viewerIndex.end() ? mdLiteral(scene)
                                   : fmt::format("[{}](#scene={}&view=mci)", mdLiteral(scene), vi->second);
}

std::string baselineSpec(const results::Results& doc, const std::string& label)
{
    for (const auto& r : doc.records)
        if (r.baseline && r.baseline->label == label) return r.baseline->spec;
    return "";
}

Table verdictTable(const results::Results& doc, const Tallies& t)
{
    int seeds = 1;
    for (const auto& r : doc.records)
        if (r.equal_time_to) seeds = std::max(seeds, r.seeds);
    Table out{
        "Verdicts at equal time",
        fmt::format("Each method against each Monte Carlo baseline at the method's own time, scene by scene: wins / "
                    "ties / losses in NMSE and in FLIP, a win where the method's error (its 95 % interval where it "
                    "has seeds) lies below the MC's (the mean over {} seed{}), a loss where above, a tie where they "
                    "overlap. Only pairs at equal time count: a pair whose paired times differ by more than the "
                    "tolerance is **off-time**, counted apart (the reasons are under the table). The ratio is the "
                    "geometric mean over the pairs at equal time of NMSE method / NMSE MC (below 1: the method is "
                    "better). Baselines: {}.",
                    seeds, seeds == 1 ? ", one draw: no interval" : "s with its 95 % interval",
                    [&] {
                        std::string s;
                        for (const auto& b : t.baselines)
                            s += (s.empty() ? "" : "; ") + mdLiteral(b) + " `" + baselineSpec(doc, b) + "`";
                        return s;
                    }()),
        {"method"},
        {},
        "No equal-time pairs in these results."};
    for (const auto& b : t.baselines)
        for (const char* col : {"NMSE W / T / L", "FLIP W / T / L", "off-time", "NMSE ratio"})
            out.head.push_back(mdLiteral(b) + ": " + col);
    for (const auto& m : t.methods) {
        std::vector<Cell> row = {{mdLiteral(m)}};
        for (const auto& b : t.baselines) {
            auto it = t.by.at(m).find(b);
            if (it == t.by.at(m).end()) {
                row.insert(row.end(), {Cell{}, Cell{}, Cell{}, Cell{}});
                continue;
            }
            const PairTally& p = it->second;
            const double g = p.ratio();
            row.push_back(num(p.nmse.win, wtl(p.nmse)));
            row.push_back(num(p.flip.win, wtl(p.flip)));
            row.push_back(num(p.offTime, std::to_string(p.offTime)));
            row.push_back(num(g, std::isfinite(g) ? fmt::format("{:.3g}", g) : "n/a"));
        }
        out.rows.push_back(std::move(row));
    }
    return out;
}

const char* reasonText(const std::string& cls)
{
    if (cls == "floor") return "MC's floor (N = 1, or its least scale) exceeds the method's time";
    if (cls == "ceiling") return "MC's largest N is still faster than the method";
    if (cls == "step") return "no integer N closer (N and N + 1 bracket the method's time)";
    return "no N found within the tolerance";
}

Table detailsTable(const Tallies& t, const std::map<std::string, size_t>& viewerIndex)
{
    Table out{"Off-time pairs and losses",
              "Per method and baseline: the pairs not at equal time, by reason (no verdict is drawn from them), and "
              "the scenes where the method loses in NMSE at equal time (links open the picture viewer).",
              {"method", "baseline", "off-time", "why", "loses at (NMSE)"},
              {},
              "Every pair is at equal time, and no method loses."};
    for (const auto& m : t.methods)
        for (const auto& b : t.baselines) {
            auto it = t.by.at(m).find(b);
            if (it == t.by.at(m).end() || (it->second.offTime == 0 && it->second.lost.empty())) continue;
            const PairTally& p = it->second;
            std::string why, lost;
            for (const auto& [cls, n] : p.offTimeBy)
                why += (why.empty() ? "" : "; ") + fmt::format("{} {}", n, reasonText(cls));
            for (const auto* r : p.lost) lost += (lost.empty() ? "" : ", ") + sceneLink(*r, viewerIndex);
            out.rows.push_back({{mdLiteral(m)},
                                {mdLiteral(b)},
                                num(p.offTime, std::to_string(p.offTime)),
                                {why},
                                {lost.empty() ? "none" : lost}});
        }
    return out;
}

std::string headline(const results::Results& doc, const Tallies& t)
{
    int on = 0, off = 0;
    for (const auto& [m, byB] : t.by)
        for (const auto& [b, p] : byB) on += p.nmse.onTime(), off += p.offTime;
    const std::string device = jsonText(doc.context, "device", "this device");
    int timeRes = 0;
    for (const auto& r : doc.records) timeRes = std::max(timeRes, r.time_ms.res);
    const std::string where =
        fmt::format("on {}{}", mdLiteral(device), timeRes > 0 ? fmt::format(" (timed at {0} x {0})", timeRes) : "");
    if (on + off == 0) return "";
    const std::string strong = strongestBaseline(t);
    if (strong.empty())
        return fmt::format("**No verdict:** none of the {} pairs {} is at equal time (the reasons are under the "
                           "verdict table).",
                           off, where);
    std::string best;
    const PairTally* bp = nullptr;
    for (const auto& m : t.methods) {
        auto it = t.by.at(m).find(strong);
        if (it == t.by.at(m).end() || it->second.nmse.onTime() == 0) continue;
        const PairTally& p = it->second;
        if (!bp || std::make_pair(p.nmse.win, -p.nmse.loss) > std::make_pair(bp->nmse.win, -bp->nmse.loss))
            best = m, bp = &p;
    }
    return fmt::format("**At equal time {}, `{}` wins {}, ties {} and loses {} of its {} pairs against the "
                       "strongest Monte Carlo here, {}, in NMSE;** {} of the {} pairs of {} method{} and {} "
                       "baseline{} are at equal time, {} off-time and not counted (the baselines' SPECs are under "
                       "the verdict table).",
                       where, mdLiteral(best), bp->nmse.win, bp->nmse.tie, bp->nmse.loss, bp->nmse.onTime(),
                       mdLiteral(strong), on, on + off, t.methods.size(), t.methods.size() == 1 ? "" : "s",
                       t.baselines.size(), t.baselines.size() == 1 ? "" : "s", off);
}

}  // namespace

Tallies tallyPairs(const results::Results& doc)
{
    Tallies t;
    t.baselines = baselineOrder(doc);
    for (const results::Pair& p : results::pairsOf(doc.records)) {
        const std::string m = methodOf(*p.partner), b = baselineOf(*p.partner);
        if (!t.by.count(m)) t.methods.push_back(m);
        if (std::find(t.baselines.begin(), t.baselines.end(), b) == t.baselines.end()) t.baselines.push_back(b);
        PairTally& a = t.by[m][b];
        if (!p.method) {
            ++a.nmse.undefined, ++a.flip.undefined;
            continue;
        }
        const results::Verdict v = results::verdict(*p.method, *p.partner, "nmse");
        if (v == results::Verdict::OffTime) {
            ++a.offTime;
            ++a.offTimeBy[results::offTimeClass(*p.partner)];
            continue;
        }
        count(a.nmse, v);
        count(a.flip, results::verdict(*p.method, *p.partner, "flip"));
        const double q = p.method->error.nmse / p.partner->error.nmse;
        if (std::isfinite(q) && q > 0) a.logSum += std::log(q), ++a.logs;
        if (v == results::Verdict::Loss) a.lost.push_back(p.partner);
    }
    // baselines of the context without a pair here stay out of the table
    t.baselines.erase(std::remove_if(t.baselines.begin(), t.baselines.end(),
                                     [&](const std::string& b) {
                                         return std::none_of(t.by.begin(), t.by.end(),
                                                             [&](const auto& kv) { return kv.second.count(b) > 0; });
                                     }),
                      t.baselines.end());
    return t;
}

std::string strongestBaseline(const Tallies& t)
{
    std::map<std::string, std::pair<int, double>> on;  // baseline -> (pairs at equal time, sum of log ratios)
    std::map<std::string, int> logs;
    for (const auto& [m, byB] : t.by)
        for (const auto& [b, p] : byB) {
            on[b].first += p.nmse.onTime();
            on[b].second += p.logSum;
            logs[b] += p.logs;
        }
    int most = 0;
    for (const auto& [b, v] : on) most = std::max(most, v.first);
    if (most == 0) return "";
    std::string best;
    double bestRatio = -INFINITY;
    for (const auto& b : t.baselines) {
        if (2 * on[b].first < most || logs[b] == 0) continue;
        const double g = on[b].second / logs[b];
        if (g > bestRatio) bestRatio = g, best = b;
    }
    return best;
}

VerdictReport verdictReport(const results::Results& doc, const std::map<std::string, size_t>& viewerIndex)
{
    const Tallies t = tallyPairs(doc);
    return {verdictTable(doc, t), detailsTable(t, viewerIndex), headline(doc, t)};
}

}  // namespace lb::experiments
