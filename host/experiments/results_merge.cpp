// mergeResults (results.h): the shards of one run, or runs of one experiment
// with other baselines, into one document; differences of experiment, commit
// and cell inputs refused by name unless forced.
#include "experiments/results.h"

#include "util/error.h"

#include <fmt/format.h>

#include <map>
#include <set>
#include <unordered_map>

namespace lb::results {

namespace {

using json = nlohmann::json;

std::string contextText(const json& context, const char* key)
{
    if (!context.is_object() || !context.contains(key)) return "(none)";
    return context[key].is_string() ? context[key].get<std::string>() : context[key].dump();
}

// A record as people name it: its scene and SPEC (with the baseline of a partner).
std::string recordName(const Record& r)
{
    const std::string scene =
        r.extra.is_object() ? r.extra.value("scene", json(r.luminaire)).get<std::string>() : r.luminaire;
    if (!r.equal_time_to) return fmt::format("{} at scene {}", canonicalSpec(r), scene);
    return fmt::format("the partner of {} against {} at scene {}", *r.equal_time_to,
                       r.baseline ? r.baseline->label + " (" + r.baseline->spec + ")" : std::string("MC"), scene);
}

// The input keys whose values differ between two records' `inputs`.
std::string differingInputs(const json& a, const json& b)
{
    std::set<std::string> keys;
    for (const json* o : {&a, &b})
        if (o->is_object())
            for (auto it = o->begin(); it != o->end(); ++it)
                if (!a.contains(it.key()) || !b.contains(it.key()) || a[it.key()] != b[it.key()]) keys.insert(it.key());
    std::string out;
    for (const auto& k : keys) out += (out.empty() ? "" : ", ") + k;
    return out;
}

struct Input {
    std::string path;
    json context;
};

// The run-level differences between two inputs: experiment and commit.
std::vector<std::string> contextDifferences(const Input& a, const Input& b)
{
    std::vector<std::string> out;
    for (const char* k : {"experiment", "commit"}) {
        const std::string x = contextText(a.context, k), y = contextText(b.context, k);
        if (x != y) out.push_back(fmt::format("{} '{}' in {} but '{}' in {}", k, x, a.path, y, b.path));
    }
    return out;
}

// Refused, or with `force` said in `forced`.
void differ(const std::string& what, bool force, std::vector<std::string>& forced)
{
    if (!force)
        throw InputError(
            fmt::format("merge: {}; give --force to merge anyway (later inputs replace earlier ones)", what));
    forced.push_back(what);
}

}  // namespace

Results mergeResults(const std::vector<std::string>& paths, MergeStats* stats, const MergeOptions& options)
{
    Results out;
    MergeStats s;
    json sources = json::array(), commits = json::array();
    std::vector<Input> inputs;
    std::unordered_map<std::string, std::pair<size_t, size_t>> cells;  // cell key -> (input, position in out)
    for (const auto& p : paths) {
        Results d = load(p);
        inputs.push_back({p, d.context});
        if (s.files == 0) out.context = d.context;
        for (const auto& diff : contextDifferences(inputs.front(), inputs.back()))
            differ(diff, options.force, s.forced);
        sources.push_back({{"file", p}, {"context", d.context}});
        commits.push_back(d.context.value("commit", json("unknown")));
        s.records_in += d.records.size();
        for (auto& r : d.records) {
            auto [it, fresh] = cells.emplace(r.key(), std::make_pair(s.files, out.records.size()));
            if (fresh) {
                out.records.push_back(std::move(r));
                continue;
            }
            Record& old = out.records[it->second.second];
            const std::string& from = inputs[it->second.first].path;
            if (old.inputs != r.inputs)
                differ(fmt::format("{} of {} would be replaced by that of {} computed from other inputs ({})",
                                   recordName(r), from, p, differingInputs(old.inputs, r.inputs)),
                       options.force, s.forced);
            old = std::move(r);  // the later input wins
            it->second.first = s.files;
            ++s.replaced;
        }
        ++s.files;
    }
    out.context["merged_from"] = sources;
    out.context["commits"] = commits;
    s.records_out = out.records.size();
    if (stats) *stats = s;
    return out;
}

}  // namespace lb::results
