// results.csv and results_long.csv (results.h toCsv, toLongCsv): one flat row
// per record in at most kMaxCsvColumns columns, and the metrics with their
// 95 % intervals in long form.
#include "experiments/results.h"

#include "util/fileio.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

namespace lb::results {

namespace {

using json = nlohmann::json;

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// Text a spreadsheet would run as a formula: a cell starting with = + - @
// (or a tab or carriage return) that is not a plain number. Prefixed with
// ' (OWASP's advice), which spreadsheets show and do not evaluate.
bool formulaLike(const std::string& s)
{
    if (s.empty() || std::string("=+-@\t\r").find(s[0]) == std::string::npos) return false;
    double v;
    auto r = std::from_chars(s.data() + (s[0] == '+'), s.data() + s.size(), v);
    return !(r.ec == std::errc() && r.ptr == s.data() + s.size());
}

std::string csvField(const std::string& in)
{
    const std::string s = formulaLike(in) ? "'" + in : in;
    if (s.find_first_of(",\"\r\n'") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + '"';
}

// A JSON value as a CSV field: null and non-finite numbers empty, strings
// as they are, booleans True / False (what pandas.read_csv reads as bool),
// numbers in their shortest round-trip form, lists and objects as JSON text.
std::string csvValue(const json& v)
{
    if (v.is_null()) return "";
    if (v.is_string()) return csvField(v.get<std::string>());
    if (v.is_boolean()) return v.get<bool>() ? "True" : "False";
    if (v.is_number_float()) {
        double d = v.get<double>();
        return std::isfinite(d) ? fmt::format("{}", d) : "";
    }
    return csvField(v.dump());
}

// The unit of a record's image values: luminance in cd/m^2 for the specular
// scene (docs/design.md section 8), irradiance in lux otherwise.
std::string valueUnit(const Record& r)
{
    const bool specular = r.sceneKeys.is_object() && r.sceneKeys.value("scene_kind", json("")) == "specular";
    return specular ? "cd_m2" : "lux";
}

const std::set<std::string> kWithUnit = {"ueb", "leb", "mean_ref", "mean_test"};
const char* const kMetricColumns[] = {"nmse",      "nrmse",    "relmse",    "ueb",       "leb",
                                      "nonfinite", "mean_ref", "mean_test", "grad_nmse", "flip"};
const char* const kSceneKindColumns[] = {"scene_kind", "alpha", "eye", "albedo", "shape", "size"};

std::string extraText(const Record& r, const char* key)
{
    return r.extra.is_object() && r.extra.contains(key) && r.extra[key].is_string() ? r.extra[key].get<std::string>()
                                                                                    : "";
}

std::string roleOf(const Record& r)
{
    if (r.equal_time_to) return "equal_time";
    const std::string role = extraText(r, "role");
    return role.empty() ? "method" : role;
}

// The matched method of an equal-time partner as the experiment wrote it:
// the equal-time label, else (a version 1 record without one) the canonical SPEC.
std::string partnerLabel(const Record& r)
{
    if (r.equalTime && !r.equalTime->label.empty()) return r.equalTime->label;
    return r.equal_time_to.value_or("");
}

std::string baselineLabel(const Record& r) { return r.baseline ? r.baseline->label : "MCI"; }

// What a plot groups by: the SPEC as written for a method, <baseline>=<method>
// for an equal-time partner, "<baseline> curve" for an MC curve point.
std::string seriesOf(const Record& r)
{
    const std::string role = roleOf(r);
    if (role == "equal_time") return baselineLabel(r) + "=" + partnerLabel(r);
    if (role == "mci_curve") return baselineLabel(r) + " curve";
    const std::string spec = extraText(r, "spec");
    return spec.empty() ? r.method : spec;
}

// MC's sample count: N + extra of a partner's equal-time result, else the
// record's N_eq, else the method's n parameter; null for other methods.
json mcSamples(const Record& r)
{
    if (r.method != "mc") return nullptr;
    if (r.equalTime) return num(r.equalTime->n);
    if (r.n) return *r.n;
    return r.params.contains("n") ? r.params["n"] : json(nullptr);
}

// The columns beyond the fixed ones: the unit handling and the scene-kind keys present.
struct CsvLayout {
    std::string unit;  // the one unit of every record ("lux", "cd_m2"), or "" where they mix
    std::vector<std::string> kinds;  // kSceneKindColumns some record has
};

CsvLayout csvLayout(const Results& doc)
{
    CsvLayout l;
    std::set<std::string> units, kinds;
    for (const auto& r : doc.records) {
        units.insert(valueUnit(r));
        if (r.sceneKeys.is_object())
            for (auto it = r.sceneKeys.begin(); it != r.sceneKeys.end(); ++it) kinds.insert(it.key());
    }
    l.unit = units.size() <= 1 ? (units.empty() ? "lux" : *units.begin()) : "";
    for (const char* k : kSceneKindColumns)
        if (kinds.count(k)) l.kinds.push_back(k);
    return l;
}

std::vector<std::string> csvHeader(const CsvLayout& l)
{
    std::vector<std::string> cols = {
        "role",         "series",       "method",      "spec",      "baseline",  "baseline_spec",  "equal_time_label",
        "verdict",      "verdict_flip", "off_time",    "scene",     "luminaire", "luminaire_name", "height_m",
        "rotation_rad", "res",          "precision",   "device",    "driver",    "time_ms_median", "time_ms_min",
        "time_ms_max",  "time_ms_reps", "time_ms_res", "time_ms_cv"};
    for (const char* m : kMetricColumns)
        cols.push_back(kWithUnit.count(m) && !l.unit.empty() ? std::string(m) + "_" + l.unit : std::string(m));
    if (l.unit.empty()) cols.push_back("unit");
    cols.insert(cols.end(), {"seeds", "n", "equal_time_ratio"});
    cols.insert(cols.end(), l.kinds.begin(), l.kinds.end());
    return cols;
}

struct PairVerdicts {
    std::string nmse, flip;
};

// Every partner's verdicts in NMSE and FLIP (results::verdict), by record.
std::map<const Record*, PairVerdicts> verdictsOf(const Results& doc)
{
    std::map<const Record*, PairVerdicts> out;
    for (const Pair& p : pairsOf(doc.records)) {
        if (!p.method) {
            out[p.partner] = {"n/a", "n/a"};
            continue;
        }
        out[p.partner] = {verdictName(verdict(*p.method, *p.partner, "nmse")),
                          verdictName(verdict(*p.method, *p.partner, "flip"))};
    }
    return out;
}

std::vector<std::string> csvRow(const Record& r, const CsvLayout& l, const PairVerdicts* v)
{
    const bool partner = r.equal_time_to.has_value();
    const bool mc = partner || roleOf(r) == "mci_curve";
    std::vector<std::string> f = {csvField(roleOf(r)),
                                  csvField(seriesOf(r)),
                                  csvField(r.method),
                                  csvField(canonicalSpec(r)),
                                  mc ? csvField(baselineLabel(r)) : "",
                                  mc && r.baseline ? csvField(r.baseline->spec) : "",
                                  partner ? csvField(partnerLabel(r)) : "",
                                  v ? v->nmse : "",
                                  v ? v->flip : "",
                                  partner ? csvField(offTimeReason(r)) : "",
                                  csvField(extraText(r, "scene")),
                                  csvField(r.luminaire),
                                  csvField(extraText(r, "luminaire_name")),
                                  csvValue(num(r.height)),
                                  csvValue(num(r.rotation)),
                                  csvValue(r.res),
                                  csvField(r.precision),
                                  csvField(r.device),
                                  csvField(r.driver),
                                  csvValue(num(r.time_ms.median)),
                                  csvValue(num(r.time_ms.min)),
                                  csvValue(num(r.time_ms.max)),
                                  csvValue(r.time_ms.reps),
                                  csvValue(r.time_ms.res),
                                  csvValue(num(r.time_ms.cv))};
    const json m = r.error;
    for (const char* k : kMetricColumns) f.push_back(csvValue(m[k]));
    if (l.unit.empty()) f.push_back(valueUnit(r));
    f.insert(f.end(),
             {csvValue(r.seeds), csvValue(mcSamples(r)), r.equalTime ? csvValue(num(r.equalTime->ratio)) : ""});
    for (const auto& k : l.kinds) f.push_back(r.sceneKeys.contains(k) ? csvValue(r.sceneKeys[k]) : "");
    return f;
}

std::string joinRow(const std::vector<std::string>& f)
{
    std::string out;
    for (size_t i = 0; i < f.size(); ++i) out += (i ? "," : "") + f[i];
    return out + "\n";
}

}  // namespace

std::string toCsv(const Results& doc)
{
    const CsvLayout l = csvLayout(doc);
    std::vector<std::string> head = csvHeader(l);
    for (auto& h : head) h = csvField(h);
    std::string out = joinRow(head);
    const auto verdicts = verdictsOf(doc);
    for (const auto& r : doc.records) {
        auto v = verdicts.find(&r);
        out += joinRow(csvRow(r, l, v == verdicts.end() ? nullptr : &v->second));
    }
    return out;
}

std::string toLongCsv(const Results& doc)
{
    std::string out = "record,metric,mean,lo,hi\n";
    for (size_t i = 0; i < doc.records.size(); ++i) {
        const Record& r = doc.records[i];
        for (const auto& key : metrics::minimisableMetrics()) {
            const json m = r.error;
            auto it = r.ci95.find(key);
            const bool ci = it != r.ci95.end();
            out += joinRow({std::to_string(i), key, csvValue(m.value(key, json(nullptr))),
                            ci ? csvValue(num(it->second[0])) : "", ci ? csvValue(num(it->second[1])) : ""});
        }
    }
    return out;
}

std::string csvPathFor(const std::string& resultsJsonPath)
{
    return std::filesystem::path(resultsJsonPath).replace_extension(".csv").string();
}

void saveCsv(const std::string& resultsJsonPath, const Results& doc)
{
    const std::filesystem::path csv = csvPathFor(resultsJsonPath);
    util::writeFilesAtomic({{csv.string(), toCsv(doc)},
                            {(csv.parent_path() / (csv.stem().string() + "_long.csv")).string(), toLongCsv(doc)}});
}

}  // namespace lb::results
