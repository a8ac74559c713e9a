#include "experiments/results.h"

#include "experiments/experiment.h"
#include "scene/scene.h"
#include "equaltime/equaltime.h"
#include "methods/mc_denoise.h"
#include "methods/spec.h"
#include "util/error.h"
#include "util/fileio.h"
#include "util/json_file.h"
#include "util/process.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <cstring>
#include <unordered_map>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/utsname.h>
#include <unistd.h>
#include "lb_build_config.h"

namespace lb::results {

namespace {

using json = nlohmann::json;

const double kNaN = std::numeric_limits<double>::quiet_NaN();

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

const char* typeName(const json& v) { return v.type_name(); }

// The value of `key` in `j` as T, or an InputError saying which key was
// expected and what was found.
template <class T>
T field(const json& j, const char* key)
{
    auto it = j.find(key);
    if (it == j.end()) throw InputError(fmt::format("missing key \"{}\"", key));
    try {
        return it->get<T>();
    } catch (const json::exception&) {
        throw InputError(fmt::format("key \"{}\": unexpected {} {}", key, typeName(*it), it->dump()));
    }
}

// A number that may be null (undefined, read as NaN).
double numField(const json& j, const char* key)
{
    auto it = j.find(key);
    if (it == j.end()) throw InputError(fmt::format("missing key \"{}\"", key));
    if (it->is_null()) return kNaN;
    if (!it->is_number())
        throw InputError(
            fmt::format("key \"{}\": expected a number or null, found {} {}", key, typeName(*it), it->dump()));
    return it->get<double>();
}

const std::set<std::string> kKnownKeys = {
    "method", "params",     "luminaire", "height",    "rotation",   "res",  "precision",     "device",
    "driver", "time_ms",    "nmse",      "nrmse",     "relmse",     "ueb",  "leb",           "nonfinite",
    "pixels", "mean_ref",   "mean_test", "grad_nmse", "grad_pairs", "flip", "equal_time_to", "n",
    "inputs", "equal_time", "seeds",     "ci95",      "baseline"};
// The equal-time result's columns of the CSV (equal_time_<key>), its
// candidates and fit (lists) left out.
const char* const kEqualTimeCsv[] = {"label",     "n",          "ratio",      "ok",      "bracketed", "method_ms",
                                     "method_cv", "partner_ms", "partner_cv", "cell_ms", "tolerance"};
// The equal-time fields of a version 1 record, read into Record::equalTime.
const char* const kLegacyEqualTime[] = {"equal_time_n",     "equal_time_candidates", "equal_time_cell_ms",
                                        "equal_time_label", "equal_time_target_ms",  "equal_time_ratio",
                                        "equal_time_ok",    "equal_time_bracketed",  "equal_time_fit"};
// The scene-kind keys (scene/scene_keys.h), collected into Record::sceneKeys.
const std::set<std::string> kSceneKeys = {"scene_kind", "alpha", "eye", "albedo", "shape", "size"};

// Standard output of git with white space around it trimmed, "" on failure.
std::string gitOutput(const std::vector<std::string>& args)
{
    std::vector<std::string> argv{"git"};
    argv.insert(argv.end(), args.begin(), args.end());
    std::string out;
    util::ProcessOptions opt;
    opt.out = &out;
    opt.quietStderr = true;
    if (util::runProcess(argv, opt) != 0) return "";
    auto b = out.find_first_not_of(" \t\r\n"), e = out.find_last_not_of(" \t\r\n");
    return b == std::string::npos ? "" : out.substr(b, e - b + 1);
}

// A version 1 record's equal-time fields (extra keys, read with their
// defaults as the code of that version did) as the typed result.
EqualTime legacyEqualTime(const json& x, const Record& r)
{
    EqualTime e;
    e.label = x.value("equal_time_label", r.equal_time_to.value_or(""));
    e.n = x.contains("equal_time_n") && x["equal_time_n"].is_number() ? x["equal_time_n"].get<double>()
                                                                      : double(r.n.value_or(0));
    e.method_ms = x.value("equal_time_target_ms", kNaN);
    e.partner_ms = r.time_ms.median;  // version 1 timed the partner in the pairing too
    e.method_cv = e.partner_cv = kNaN;
    e.ratio = x.value("equal_time_ratio", kNaN);
    e.cell_ms = x.value("equal_time_cell_ms", kNaN);
    e.tolerance = kNaN;
    e.ok = x.value("equal_time_ok", false);
    e.bracketed = x.value("equal_time_bracketed", false);
    e.candidates = x.value("equal_time_candidates", json::array());
    e.fit = x.value("equal_time_fit", json::array());
    return e;
}

// The values a runner writes, held to the ranges it writes them in: a file
// edited by hand (or damaged) is refused naming the key, never reported.
void checkRanges(const Record& r)
{
    for (const auto& [k, v] : r.ci95)
        if (v[0] > v[1])
            throw InputError(
                fmt::format("key \"ci95\".{}: expected [lo, hi] with lo <= hi, found [{}, {}]", k, v[0], v[1]));
    if (r.sceneKeys.contains("shape")) {
        const json& s = r.sceneKeys["shape"];
        try {
            parseLightShape(s.is_string() ? s.get<std::string>() : s.dump());
        } catch (const InputError& e) {
            throw InputError(fmt::format("key \"shape\": {}", e.what()));
        }
    }
    if (r.sceneKeys.contains("size")) {
        const json& s = r.sceneKeys["size"];
        const auto inRange = [](const json& v) {
            return v.is_number() && v.get<double>() > 0 && v.get<double>() <= kMaxSceneLength;
        };
        if (!s.is_array() || s.size() != 2 || !inRange(s[0]) || !inRange(s[1]))
            throw InputError(
                fmt::format("key \"size\": expected [W, L] in (0, {}] m, found {}", kMaxSceneLength, s.dump()));
    }
}

// The baseline of a record written before baselines had names: a partner's
// from its inputs.mc (the canonical SPEC it was found with), an MC curve
// point's from its parameters without n and extra; none for other records
// and where neither is there.
std::optional<BaselineRef> legacyBaseline(const Record& r)
{
    std::string spec;
    if (r.equal_time_to && r.inputs.is_object() && r.inputs.contains("mc") && r.inputs["mc"].is_string()) {
        spec = baselineSpec(r.inputs["mc"].get<std::string>());
    } else if (!r.equal_time_to && r.method == "mc" && r.extra.is_object() &&
               r.extra.value("role", json("")) == "mci_curve") {
        Record base = r;
        base.params.erase("n");
        base.params.erase("extra");
        spec = baselineSpec(canonicalSpec(base));
    }
    if (spec.empty()) return std::nullopt;
    return BaselineRef{defaultBaselineLabel(spec), spec};
}

// A record's baseline: its "baseline" key, or the legacy one of its inputs.
std::optional<BaselineRef> readBaseline(const json& j, const Record& r)
{
    if (!j.contains("baseline")) return legacyBaseline(r);
    const json b = field<json>(j, "baseline");
    try {
        return BaselineRef{field<std::string>(b, "label"), baselineSpec(field<std::string>(b, "spec"))};
    } catch (const InputError& err) {
        throw InputError(fmt::format("key \"baseline\": {}", err.what()));
    }
}

}  // namespace

void to_json(json& j, const EqualTime& e)
{
    j = json{{"label", e.label},
             {"n", num(e.n)},
             {"method_ms", num(e.method_ms)},
             {"partner_ms", num(e.partner_ms)},
             {"method_cv", num(e.method_cv)},
             {"partner_cv", num(e.partner_cv)},
             {"ratio", num(e.ratio)},
             {"cell_ms", num(e.cell_ms)},
             {"tolerance", num(e.tolerance)},
             {"ok", e.ok},
             {"bracketed", e.bracketed},
             {"candidates", e.candidates},
             {"fit", e.fit}};
    if (e.scale < 1) j["scale"] = num(e.scale);
}

void from_json(const json& j, EqualTime& e)
{
    if (!j.is_object()) throw InputError(fmt::format("key \"equal_time\": expected an object, found {}", j.dump()));
    try {
        e.label = field<std::string>(j, "label");
        e.n = numField(j, "n");
        e.method_ms = numField(j, "method_ms");
        e.partner_ms = numField(j, "partner_ms");
        e.method_cv = numField(j, "method_cv");
        e.partner_cv = numField(j, "partner_cv");
        e.ratio = numField(j, "ratio");
        e.cell_ms = numField(j, "cell_ms");
        e.tolerance = numField(j, "tolerance");
        e.ok = field<bool>(j, "ok");
        e.bracketed = field<bool>(j, "bracketed");
        e.candidates = field<json>(j, "candidates");
        e.fit = field<json>(j, "fit");
        if (j.contains("scale")) e.scale = numField(j, "scale");
    } catch (const InputError& err) {
        throw InputError(fmt::format("key \"equal_time\": {}", err.what()));
    }
}

std::string Record::key() const
{
    const bool partner = equal_time_to.has_value();
    json k = json::array({partner ? std::string("equal_time") : method, partner ? json::object() : params, luminaire,
                          num(height), num(rotation), res, precision, device,
                          partner ? json(*equal_time_to) : json(nullptr)});
    if (!sceneKeys.empty()) k.push_back(sceneKeys);  // diffuse keys stay as they were
    if (partner && baseline) k.push_back(json::array({"baseline", baseline->spec}));
    return k.dump();  // objects dump with sorted keys: a canonical string
}

namespace {

// [lo, hi] of metric `key` as a quantity to minimise (metrics::minimisable):
// the interval where the record has one, else the value twice.
std::array<double, 2> minimisableRange(const Record& r, const std::string& key)
{
    const double v = metrics::minimisable(r.error, key);
    auto it = r.ci95.find(key);
    if (it == r.ci95.end()) return {v, v};
    return key == "leb" ? std::array<double, 2>{-it->second[1], -it->second[0]} : it->second;
}

}  // namespace

Verdict verdict(const Record& method, const Record& partner, const std::string& metric)
{
    if (partner.equalTime && !partner.equalTime->ok) return Verdict::OffTime;
    const auto m = minimisableRange(method, metric), p = minimisableRange(partner, metric);
    for (double v : {m[0], m[1], p[0], p[1]})
        if (!std::isfinite(v)) return Verdict::Undefined;
    if (m[1] < p[0]) return Verdict::Win;
    if (m[0] > p[1]) return Verdict::Loss;
    return Verdict::Tie;
}

const char* verdictName(Verdict v)
{
    switch (v) {
    case Verdict::Win:
        return "win";
    case Verdict::Tie:
        return "tie";
    case Verdict::Loss:
        return "loss";
    case Verdict::OffTime:
        return "off-time";
    default:
        return "n/a";
    }
}

std::string baselineSpec(const std::string& canonical)
{
    const size_t colon = canonical.find(':');
    if (colon == std::string::npos) return canonical;
    std::string out = canonical.substr(0, colon);
    char sep = ':';
    size_t from = colon + 1;
    while (from <= canonical.size()) {
        size_t to = canonical.find(',', from);
        if (to == std::string::npos) to = canonical.size();
        const std::string kv = canonical.substr(from, to - from);
        if (!kv.empty() && kv.rfind("n=", 0) != 0 && kv.rfind("extra=", 0) != 0) {
            out += sep + kv;
            sep = ',';
        }
        from = to + 1;
    }
    return out;
}

std::string defaultBaselineLabel(const std::string& written)
{
    static const std::string thesis = methods::parseSpec("mc").canonical();
    try {
        if (methods::parseSpec(written).canonical() == thesis) return "MCI";
    } catch (const InputError&) {
    }
    return written;
}

std::string canonicalSpec(const Record& r)
{
    std::string text = r.method;
    char sep = ':';
    if (r.params.is_object())
        for (auto it = r.params.begin(); it != r.params.end(); ++it) {  // sorted keys
            text += sep + it.key() + "=" + (it->is_string() ? it->get<std::string>() : it->dump());
            sep = ',';
        }
    const std::string kind =
        r.sceneKeys.is_object() && r.sceneKeys.contains("scene_kind") && r.sceneKeys["scene_kind"].is_string()
        ? r.sceneKeys["scene_kind"].get<std::string>()
        : "diffuse";
    static std::mutex mutex;
    static std::map<std::string, std::string> cache;  // the report and the CSV ask for every record
    std::lock_guard<std::mutex> lock(mutex);
    const std::string key = kind + "|" + text;
    auto hit = cache.find(key);
    if (hit != cache.end()) return hit->second;
    std::string out = text;  // a SPEC this version does not parse (for this scene kind): as the record gives it
    try {
        out = methods::parseSpec(text, parseSceneKind(kind)).canonical();
    } catch (const std::exception&) {
    }
    return cache.emplace(key, out).first->second;
}

namespace {

// What pairs a partner with its method: the scene, device and scene kind.
std::string pairKey(const Record& r)
{
    return json::array({r.luminaire, num(r.height), num(r.rotation), r.res, r.precision, r.device, r.sceneKeys}).dump();
}

}  // namespace

std::vector<Pair> pairsOf(const std::vector<Record>& records)
{
    std::map<std::string, const Record*> bySpec;  // scene|SPEC as written -> the method's record
    for (const auto& r : records)
        if (!r.equal_time_to && r.extra.is_object() && r.extra.value("role", json("method")) == "method")
            bySpec[pairKey(r) + "|" + r.extra.value("spec", json(r.method)).get<std::string>()] = &r;
    std::vector<Pair> out;
    for (const auto& r : records) {
        if (!r.equal_time_to) continue;
        const std::string label = r.equalTime && !r.equalTime->label.empty() ? r.equalTime->label : *r.equal_time_to;
        auto it = bySpec.find(pairKey(r) + "|" + label);
        out.push_back({it == bySpec.end() ? nullptr : it->second, &r});
    }
    return out;
}

std::string offTimeClass(const Record& partner)
{
    if (!partner.equalTime || partner.equalTime->ok) return "";
    const EqualTime& e = *partner.equalTime;
    const double n = partner.n ? double(*partner.n) : e.n;
    bool oneTooSlow = n <= 1;  // MC at N = 1 timed slower than the tolerance allows
    bool scaled = false, leastTooSlow = false;  // below N = 1 (mc's scale): its least scale too slow
    if (e.candidates.is_array())
        for (const auto& c : e.candidates) {
            if (!c.is_object()) continue;
            const bool slow = c.value("ratio", 0.0) > 1 + e.tolerance;
            if (c.contains("scale")) {
                scaled = true;
                leastTooSlow = leastTooSlow || (slow && c.value("scale", 1.0) <= methods::kMinScale + 1e-9);
            } else if (c.value("n", 0L) == 1 && !c.contains("extra") && slow) {
                oneTooSlow = true;
            }
        }
    if (scaled) oneTooSlow = leastTooSlow;
    if (e.ratio > 1 && oneTooSlow) return "floor";
    if (scaled) return "unmatched";  // below N = 1 the scale is continuous: no step
    if (e.ratio < 1 && n >= double(equaltime::kMaxN)) return "ceiling";
    if (e.bracketed) return "step";
    return "unmatched";
}

std::string offTimeReason(const Record& partner)
{
    const std::string c = offTimeClass(partner);
    if (c.empty()) return "";
    const EqualTime& e = *partner.equalTime;
    const std::string ratio = fmt::format("t MC / t method = {:.3g}", e.ratio);
    if (c == "floor")
        return fmt::format("MC's {} floor exceeds the method's time ({})",
                           e.scale < 1 ? fmt::format("scale = {:g}", methods::kMinScale) : std::string("N = 1"), ratio);
    if (c == "ceiling") return fmt::format("MC's largest N is still faster than the method ({})", ratio);
    if (c == "step")
        return fmt::format("no integer N closer: N = {:g} and its neighbour bracket the method's time ({})", e.n,
                           ratio);
    return fmt::format("the search found no {} within +-{:g} % ({})", e.scale < 1 ? "scale" : "N", 100 * e.tolerance,
                       ratio);
}

size_t dedupe(std::vector<Record>& records)
{
    std::unordered_map<std::string, size_t> first;  // cell key -> position in out
    std::vector<Record> out;
    for (auto& r : records) {
        auto [it, fresh] = first.emplace(r.key(), out.size());
        if (fresh)
            out.push_back(std::move(r));
        else
            out[it->second] = std::move(r);  // the later record wins
    }
    size_t dropped = records.size() - out.size();
    records = std::move(out);
    return dropped;
}

void to_json(json& j, const Record& r)
{
    j = r.extra.is_object() ? r.extra : json::object();
    j["method"] = r.method;
    j["params"] = r.params;
    j["luminaire"] = r.luminaire;
    j["height"] = num(r.height);
    j["rotation"] = num(r.rotation);
    j["res"] = r.res;
    j["precision"] = r.precision;
    j["device"] = r.device;
    j["driver"] = r.driver;
    j["time_ms"] = {{"median", num(r.time_ms.median)}, {"min", num(r.time_ms.min)}, {"max", num(r.time_ms.max)},
                    {"cv", num(r.time_ms.cv)},         {"reps", r.time_ms.reps},    {"res", r.time_ms.res}};
    j.update(json(r.error));  // nmse, ..., mean_test, grad_nmse, grad_pairs, flip (metrics.h)
    if (r.equal_time_to) j["equal_time_to"] = *r.equal_time_to;
    if (r.n) j["n"] = *r.n;
    if (r.equalTime) j["equal_time"] = *r.equalTime;
    if (r.baseline) j["baseline"] = {{"label", r.baseline->label}, {"spec", r.baseline->spec}};
    if (r.seeds > 1) {
        j["seeds"] = r.seeds;
        json ci = json::object();
        for (const auto& [k, v] : r.ci95) ci[k] = {num(v[0]), num(v[1])};
        j["ci95"] = ci;
    }
    if (r.inputs.is_object() && !r.inputs.empty()) j["inputs"] = r.inputs;
    if (r.sceneKeys.is_object()) j.update(r.sceneKeys);
}

void from_json(const json& j, Record& r)
{
    if (!j.is_object()) throw InputError(fmt::format("a record must be a JSON object, found {}", typeName(j)));
    r = Record{};
    r.method = field<std::string>(j, "method");
    r.params = j.value("params", json::object());
    if (!r.params.is_object()) throw InputError("key \"params\": expected an object");
    r.luminaire = field<std::string>(j, "luminaire");
    r.height = numField(j, "height");
    r.rotation = numField(j, "rotation");
    r.res = field<int>(j, "res");
    r.precision = field<std::string>(j, "precision");
    if (r.precision != "float" && r.precision != "double")
        throw InputError(fmt::format("key \"precision\": expected \"float\" or \"double\", found \"{}\"", r.precision));
    r.device = field<std::string>(j, "device");
    r.driver = field<std::string>(j, "driver");
    const json t = field<json>(j, "time_ms");
    r.time_ms.median = numField(t, "median");
    r.time_ms.min = numField(t, "min");
    r.time_ms.reps = field<int>(t, "reps");
    // max and res came later: older files read as 0
    r.time_ms.max = t.contains("max") ? numField(t, "max") : 0;
    r.time_ms.res = t.contains("res") ? field<int>(t, "res") : 0;
    r.time_ms.cv = t.contains("cv") ? numField(t, "cv") : 0;
    r.error.nmse = numField(j, "nmse");
    r.error.nrmse = numField(j, "nrmse");
    r.error.relmse = numField(j, "relmse");
    r.error.ueb = numField(j, "ueb");
    r.error.leb = numField(j, "leb");
    r.error.nonfinite = field<int64_t>(j, "nonfinite");
    // Not in every record (e.g. written by a hand or an older runner): optional.
    r.error.pixels = j.contains("pixels") ? field<int64_t>(j, "pixels") : 0;
    r.error.mean_ref = j.contains("mean_ref") ? numField(j, "mean_ref") : kNaN;
    r.error.mean_test = j.contains("mean_test") ? numField(j, "mean_test") : kNaN;
    // Records written before grad_nmse and flip existed read as NaN (written back as null).
    r.error.grad_nmse = j.contains("grad_nmse") ? numField(j, "grad_nmse") : kNaN;
    r.error.grad_pairs = j.contains("grad_pairs") ? field<int64_t>(j, "grad_pairs") : 0;
    r.error.flip = j.contains("flip") ? numField(j, "flip") : kNaN;
    if (j.contains("equal_time_to")) r.equal_time_to = field<std::string>(j, "equal_time_to");
    if (j.contains("n")) r.n = field<int64_t>(j, "n");
    if (j.contains("equal_time")) r.equalTime = field<EqualTime>(j, "equal_time");
    if (j.contains("seeds")) {  // as the widest integer: a large count must not wrap into the range
        const int64_t seeds = field<int64_t>(j, "seeds");
        if (!(seeds >= 1 && seeds <= experiments::kMaxSeeds))
            throw InputError(
                fmt::format("key \"seeds\": expected an integer in [1, {}], found {}", experiments::kMaxSeeds, seeds));
        r.seeds = static_cast<int>(seeds);
    }
    if (j.contains("ci95")) {
        const json ci = field<json>(j, "ci95");
        if (!ci.is_object()) throw InputError("key \"ci95\": expected an object of [lo, hi] by metric");
        for (auto it = ci.begin(); it != ci.end(); ++it) {
            if (!it->is_array() || it->size() != 2)
                throw InputError(fmt::format("key \"ci95\".{}: expected [lo, hi], found {}", it.key(), it->dump()));
            r.ci95[it.key()] = {it->at(0).is_number() ? it->at(0).get<double>() : kNaN,
                                it->at(1).is_number() ? it->at(1).get<double>() : kNaN};
        }
    }
    if (j.contains("inputs")) {
        r.inputs = j["inputs"];
        if (!r.inputs.is_object())
            throw InputError(fmt::format("key \"inputs\": expected an object, found {}", r.inputs.dump()));
    }
    for (auto it = j.begin(); it != j.end(); ++it) {
        if (kSceneKeys.count(it.key()))
            r.sceneKeys[it.key()] = it.value();
        else if (!kKnownKeys.count(it.key()))
            r.extra[it.key()] = it.value();
    }
    if (r.equal_time_to && !r.equalTime && r.extra.contains("equal_time_ratio")) {
        r.equalTime = legacyEqualTime(r.extra, r);
        for (const char* k : kLegacyEqualTime) r.extra.erase(k);
    }
    checkRanges(r);
    r.baseline = readBaseline(j, r);
}

void to_json(json& j, const Results& d)
{
    j = json{{"schema_version", kResultsSchemaVersion}, {"context", d.context}, {"records", d.records}};
}

void from_json(const json& j, Results& d)
{
    if (!j.is_object() || !j.contains("context") || !j.contains("records"))
        throw InputError("expected a JSON object with \"context\" and \"records\"");
    if (!j["context"].is_object()) throw InputError("\"context\" must be an object");
    if (!j["records"].is_array()) throw InputError("\"records\" must be an array");
    const json version = j.value("schema_version", json(1));
    // read as the widest integer: 4294967297 must not wrap to 1
    if (!version.is_number_integer() || version.get<long long>() < 1 ||
        version.get<long long>() > kResultsSchemaVersion)
        throw InputError(fmt::format("\"schema_version\" {}: this lumibench reads versions 1 to {} (a newer "
                                     "lumibench wrote it?)",
                                     version.dump(), kResultsSchemaVersion));
    d.context = j["context"];
    d.records.clear();
    size_t i = 0;
    for (const auto& rj : j["records"]) {
        try {
            d.records.push_back(rj.get<Record>());
        } catch (const InputError& e) {
            throw InputError(fmt::format("record {}: {}", i, e.what()));
        }
        ++i;
    }
}

json makeContext(const std::string& device, const std::string& driver, const json& extra)
{
    json c;
    c["device"] = device;
    c["driver"] = driver;
    const std::string dir = LB_SOURCE_DIR;
    std::string commit = gitOutput({"-C", dir, "rev-parse", "HEAD"});
    c["commit"] = commit.empty() ? "unknown" : commit;
    if (!commit.empty())
        c["commit_dirty"] = !gitOutput({"-C", dir, "status", "--porcelain", "--untracked-files=no"}).empty();

    std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm tm{};
    gmtime_r(&now, &tm);
    std::array<char, 32> date{};
    std::strftime(date.data(), date.size(), "%Y-%m-%dT%H:%M:%SZ", &tm);
    c["date"] = date.data();

    std::array<char, 256> host{};
    c["host"] = gethostname(host.data(), host.size() - 1) == 0 ? host.data() : "unknown";
    c["lumibench_version"] = LB_VERSION;
#ifdef __VERSION__
    c["compiler"] = __VERSION__;
#endif
    utsname u{};
    if (uname(&u) == 0) c["os"] = fmt::format("{} {} {}", u.sysname, u.release, u.machine);
    if (extra.is_object()) c.update(extra);
    return c;
}

std::string journalPath(const std::string& path) { return path + ".journal"; }

bool exists(const std::string& path)
{
    return std::filesystem::exists(path) || std::filesystem::exists(journalPath(path));
}

namespace {

// A record carries its experiment file inside its context: twice an input's depth.
constexpr int kResultsDepth = 2 * util::kMaxJsonDepth;

Results loadDocument(const std::string& path)
{
    // 1 GiB: a results file of a million records is ~1 GB; anything larger is not one.
    const json j = util::readJson(path, "a results file (JSON)", size_t(1) << 30, kResultsDepth);
    try {
        return j.get<Results>();
    } catch (const InputError& e) {
        throw InputError(fmt::format("{}: {}", path, e.what()));
    }
}

// Adds the journal's context (where the document has none) and records to doc.
void foldJournal(const std::string& jpath, Results& doc)
{
    const std::string text = util::readFile(jpath, "a results journal (JSON lines)", size_t(1) << 30);
    size_t begin = 0, line = 0;
    for (size_t end; (end = text.find('\n', begin)) != std::string::npos; begin = end + 1) {
        ++line;
        try {
            json j = util::parseJson(text.substr(begin, end - begin), fmt::format("{}:{}", jpath, line), kResultsDepth);
            if (j.contains("record"))
                doc.records.push_back(j.at("record").get<Record>());
            else if (j.contains("context") && doc.context.empty())
                doc.context = j.at("context");
            else if (!j.contains("context"))
                throw InputError("neither a record nor a context");
        } catch (const json::exception& e) {
            throw InputError(fmt::format("{}:{}: not a journal line: {}", jpath, line, e.what()));
        } catch (const InputError& e) {
            throw InputError(fmt::format("{}:{}: {}", jpath, line, e.what()));
        }
    }
    // text after the last newline: an append that was cut off, no record
    dedupe(doc.records);
}

// The error of a failed open(O_NOFOLLOW) of an output folder's file: a link
// there is an input error naming it (a planted link would carry the appends
// out of the folder), anything else the system's reason.
[[noreturn]] void failOpen(const std::string& path, const char* what)
{
    const int e = errno;
    if (e == ELOOP)
        throw InputError(fmt::format("{}: the results {} is a symbolic link; expected a regular file (lumibench "
                                     "writes no output through a link: remove it)",
                                     path, what));
    throw Error(fmt::format("{}: cannot open the results {}: {}", path, what, std::strerror(e)));
}

// Held while a process appends to or compacts a results file: the document
// is replaced by every save, so a lock on it would not serialise anything.
struct FileLock {
    int fd;
    explicit FileLock(const std::string& path)
    {
        const std::string lockPath = path + ".lock";
        fd = ::open(lockPath.c_str(), O_CREAT | O_RDWR | O_CLOEXEC | O_NOFOLLOW, 0644);
        if (fd < 0) failOpen(lockPath, "lock file");
        if (::flock(fd, LOCK_EX) != 0) {
            int e = errno;
            ::close(fd);
            throw Error(fmt::format("{}: cannot lock: {}", lockPath, std::strerror(e)));
        }
    }
    ~FileLock() { ::close(fd); }  // closing releases the flock
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;
};

uintmax_t sizeOr0(const std::string& path)
{
    std::error_code ec;
    uintmax_t n = std::filesystem::file_size(path, ec);
    return ec ? 0 : n;
}

Results loadUnlocked(const std::string& path)
{
    const std::string jpath = journalPath(path);
    const bool journal = std::filesystem::exists(jpath);
    Results doc;
    if (!journal || std::filesystem::exists(path)) doc = loadDocument(path);
    if (journal) foldJournal(jpath, doc);
    return doc;
}

void compactLocked(const std::string& path, const json& context)
{
    Results doc;
    if (exists(path))
        doc = loadUnlocked(path);
    else
        doc.context = context;
    save(path, doc);  // then removes the journal: after a crash between the two, load folds it again (dedupe)
}

}  // namespace

Results load(const std::string& path)
{
    // The document and its journal as one state: a shared lock keeps an
    // appender from folding the journal in between the two reads. No lock
    // file: no appender has ever written here (e.g. a read-only copy).
    int fd = ::open((path + ".lock").c_str(), O_RDONLY | O_CLOEXEC);
    struct Unlock {
        int fd;
        ~Unlock()
        {
            if (fd >= 0) ::close(fd);
        }
    } unlock{fd};
    if (fd >= 0 && ::flock(fd, LOCK_SH) != 0)
        throw Error(fmt::format("{}.lock: cannot lock: {}", path, std::strerror(errno)));
    return loadUnlocked(path);
}

void save(const std::string& path, const Results& doc)
{
    util::writeFileAtomic(path, json(doc).dump(1) + '\n');
    std::error_code ec;
    std::filesystem::remove(journalPath(path), ec);
    if (ec) throw Error(fmt::format("{}: cannot remove: {}", journalPath(path), ec.message()));
}

void appendRecord(const std::string& path, const json& context, const Record& r)
{
    FileLock lock(path);
    const std::string jpath = journalPath(path);
    int fd = ::open(jpath.c_str(), O_CREAT | O_RDWR | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) failOpen(jpath, "journal");
    struct Close {
        int fd;
        ~Close() { ::close(fd); }
    } closer{fd};
    auto fail = [&](const char* what) {
        return Error(fmt::format("{}: cannot {}: {}", jpath, what, std::strerror(errno)));
    };
    off_t size = ::lseek(fd, 0, SEEK_END);
    if (size < 0) throw fail("seek");
    char last = '\n';
    if (size > 0 && ::pread(fd, &last, 1, size - 1) != 1) throw fail("read");
    if (last != '\n') {  // a cut-off append: keep the journal up to its last newline
        const std::string text = util::readFile(jpath, "a results journal (JSON lines)", size_t(1) << 30);
        size_t keep = text.rfind('\n');
        size = keep == std::string::npos ? 0 : off_t(keep + 1);
        if (::ftruncate(fd, size) != 0) throw fail("truncate");
    }
    std::string text;
    if (size == 0 && !std::filesystem::exists(path)) text = json{{"context", context}}.dump() + '\n';
    text += json{{"record", json(r)}}.dump() + '\n';
    for (size_t done = 0; done < text.size();) {
        ssize_t n = ::pwrite(fd, text.data() + done, text.size() - done, size + off_t(done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw fail("write");  // a full disk: the part written is cut off by the next append
        done += size_t(n);
    }
    if (::fsync(fd) != 0) throw fail("flush");
    // Amortised O(1): fold the journal in once it outgrows the document.
    const uintmax_t journalBytes = uintmax_t(size) + text.size();
    if (journalBytes > std::max<uintmax_t>(uintmax_t(64) << 10, sizeOr0(path))) compactLocked(path, context);
}

void compact(const std::string& path, const json& context)
{
    FileLock lock(path);
    compactLocked(path, context);
}

size_t retain(const std::string& path, const std::function<bool(const Record&)>& keep, const std::string& sidePath)
{
    if (!exists(path)) return 0;
    FileLock lock(path);
    Results doc = loadUnlocked(path);
    Results side;
    side.context = doc.context;
    std::vector<Record> kept;
    for (auto& r : doc.records) (keep(r) ? kept : side.records).push_back(std::move(r));
    if (side.records.empty()) return 0;
    if (exists(sidePath)) {  // earlier moves stay: the new ones replace those of the same cell
        Results old = load(sidePath);
        old.records.insert(old.records.end(), side.records.begin(), side.records.end());
        dedupe(old.records);
        side.records = std::move(old.records);
    }
    const size_t moved = doc.records.size() - kept.size();
    save(sidePath, side);  // first: a crash between the two saves keeps both copies, loses none
    doc.records = std::move(kept);
    save(path, doc);
    return moved;
}

size_t update(const std::string& path, const std::function<bool(Record&)>& edit)
{
    if (!exists(path)) return 0;
    FileLock lock(path);
    Results doc = loadUnlocked(path);
    size_t changed = 0;
    for (auto& r : doc.records) changed += edit(r);
    if (changed) save(path, doc);
    return changed;
}

}  // namespace lb::results
