#include "experiments/experiment.h"

#include "cl/runtime.h"
#include "experiments/results.h"
#include "methods/analytic.h"
#include "methods/spec.h"
#include "util/check.h"
#include "util/digest.h"
#include "util/error.h"
#include "util/fileio.h"
#include "util/json_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

namespace lb::experiments {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const std::vector<std::string> kKeys = {"name",
                                        "description",
                                        "luminaire_dir",
                                        "luminaires",
                                        "heights",
                                        "rotations",
                                        "methods",
                                        "equal_time",
                                        "mci_curve",
                                        "mc",
                                        "equal_time_fit",
                                        "reference",
                                        "res",
                                        "precision",
                                        "size",
                                        "shape",
                                        "extent",
                                        "reps",
                                        "equal_time_tolerance",
                                        "equal_time_rounds",
                                        "equal_time_subpixel",
                                        "save_images",
                                        "seeds",
                                        "time_res",
                                        "scene",
                                        "alpha",
                                        "eye",
                                        "albedo"};

// Every .ldt / .ies file of a directory, sorted; of a .ldt and a .ies with the
// same stem only the .ldt (the suite ships both forms of each luminaire).
std::vector<std::string> luminaireFiles(const std::string& dir, const std::string& what)
{
    if (!fs::is_directory(dir)) throw InputError(fmt::format("{}: luminaire directory '{}' not found", what, dir));
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir)) {
        std::string ext = e.path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
        if (e.is_regular_file() && (ext == ".ldt" || ext == ".ies"))
            files.push_back(util::requireUtf8(e.path().string(), "a luminaire file"));
    }
    std::sort(files.begin(), files.end());
    std::vector<std::string> out;
    std::set<std::string> stems;
    for (const auto& p : files) {  // ".LDT"/".ldt" sort before ".ies"
        std::string ext = p.extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
        if (ext == ".ldt") stems.insert(p.stem().string());
    }
    for (const auto& p : files) {
        std::string ext = p.extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
        if (ext == ".ies" && stems.count(p.stem().string())) continue;
        out.push_back(p.string());
    }
    if (out.empty()) throw InputError(fmt::format("{}: no .ldt or .ies file in '{}'", what, dir));
    return out;
}

using Reader = util::JsonKeys;

std::string nameOf(const Overrides& ov, const std::string& key) { return ov.name ? ov.name(key) : overrideName(key); }

// Luminaires: an override directory gives every file there; otherwise the list
// (or "*") relative to luminaire_dir.
void readLuminaires(const Reader& r, const Overrides& ov, Experiment& e)
{
    e.luminaireDir = util::resolveSourceDir(r.has("luminaire_dir") ? r.string("luminaire_dir") : "luminaires");
    if (!ov.luminaireDir.empty()) {
        e.luminaireDir = ov.luminaireDir;
        e.luminaires = luminaireFiles(ov.luminaireDir, nameOf(ov, "luminaires"));
        return;
    }
    auto names =
        r.has("luminaires") && r.j["luminaires"] == "*" ? std::vector<std::string>{"*"} : r.strings("luminaires");
    if (names.size() == 1 && names[0] == "*") {
        e.luminaires = luminaireFiles(e.luminaireDir, r.name("luminaires"));
        return;
    }
    for (const auto& n : names) {
        fs::path p = fs::path(n).is_absolute() ? fs::path(n) : fs::path(e.luminaireDir) / n;
        if (!fs::exists(p)) r.fail("luminaires", fmt::format("file '{}' not found", p.string()));
        e.luminaires.push_back(p.string());
    }
}

// Longest label of a baseline: a table's column head.
constexpr size_t kMaxBaselineLabel = 64;

// "mc": one SPEC or a list of SPECs and {"label", "spec"} objects, each an
// mc SPEC without n or extra; labels and canonical SPECs distinct.
template <class Check>
void readBaselines(const Reader& r, Experiment& e, const Check& checkSpec)
{
    const json given = r.has("mc") ? r.at("mc") : json("mc");
    const json list = given.is_array() ? given : json::array({given});
    if (list.empty()) r.fail("mc", "expected a SPEC or a non-empty list of baselines, found []");
    std::set<std::string> labels, specs;
    for (size_t i = 0; i < list.size(); ++i) {
        const json& b = list[i];
        const std::string where = list.size() > 1 || given.is_array() ? fmt::format("entry {}: ", i) : "";
        Baseline out;
        if (b.is_string()) {
            out.spec = b.get<std::string>();
        } else if (b.is_object() && b.size() == 2 && b.contains("label") && b.contains("spec") &&
                   b["label"].is_string() && b["spec"].is_string()) {
            out.label = b["label"].get<std::string>();
            out.spec = b["spec"].get<std::string>();
        } else {
            r.fail(
                "mc",
                fmt::format("{}expected an mc SPEC or {{\"label\": ..., \"spec\": ...}}, found {}", where, b.dump()));
        }
        const methods::MethodSpec s = checkSpec("mc", out.spec);
        if (s.name != "mc") r.fail("mc", fmt::format("{}expected an mc SPEC, found '{}'", where, out.spec));
        for (const char* k : {"n", "extra"})
            if (s.given.count(k))
                r.fail("mc", fmt::format("{}'{}' must not set {} (the runner chooses it)", where, out.spec, k));
        out.canonical = s.canonical();
        if (out.label.empty()) out.label = results::defaultBaselineLabel(out.spec);
        if (out.label.size() > kMaxBaselineLabel || out.label.find_first_of("\n\r\t") != std::string::npos)
            r.fail("mc",
                   fmt::format("{}label '{}': expected at most {} characters, no tab or line break", where, out.label,
                               kMaxBaselineLabel));
        if (!specs.insert(out.canonical).second)
            r.fail("mc", fmt::format("{}'{}' is the same MC as an earlier baseline", where, out.spec));
        if (!labels.insert(out.label).second) r.fail("mc", fmt::format("{}label '{}' given twice", where, out.label));
        e.baselines.push_back(out);
    }
}

// The methods, equal_time, mc, reference and the MCI curve, each checked
// against the registry now, not after an hour of references.
void readMethods(const Reader& r, Experiment& e)
{
    auto checkSpec = [&](const std::string& key, const std::string& s) {
        try {
            return methods::parseSpec(s, e.kind());
        } catch (const InputError& err) {
            r.fail(key, err.what());
        }
    };
    e.methods = r.strings("methods");
    std::set<std::string> canon;
    for (const auto& m : e.methods) canon.insert(checkSpec("methods", m).canonical());
    if (r.has("equal_time")) {
        const bool object = r.at("equal_time").is_object();
        const Reader q{r.path, r.at("equal_time"), "equal_time."};
        e.equalTime = object ? q.strings("methods", false) : r.strings("equal_time", false);
        for (const auto& m : e.equalTime)
            if (!canon.count(checkSpec("equal_time", m).canonical()))
                r.fail("equal_time", fmt::format("'{}' is not one of \"methods\"", m));
    }
    readBaselines(r, e, checkSpec);
    if (r.has("reference")) e.reference = r.string("reference");
    checkSpec("reference", e.reference);
    if (r.has("mci_curve")) e.mciCurve = r.integers("mci_curve", 1, 1 << 20);
}

// The equal-time protocol (equaltime::readProtocol): "reps" and "time_res"
// at the top level (they time every cell), the pairing's keys in the
// "equal_time" object or as top-level equal_time_<key>, not both.
void readProtocol(const Reader& r, const Overrides& ov, Experiment& e)
{
    equaltime::ReadRules rules;
    rules.minReps = kMinExperimentReps;  // docs/design.md section 6: the median of at least 5 timed runs
    rules.maxTimeRes = kMaxRes;
    json top = json::object();
    for (const char* k : {"reps", "time_res"})
        if (r.has(k)) top[k] = r.at(k);
    equaltime::readProtocol(Reader{r.path, top}, e.protocol, rules);
    if (ov.reps) e.protocol.reps = util::checkRange(nameOf(ov, "reps"), *ov.reps, kMinExperimentReps, ocl::kMaxReps);
    if (ov.timeRes) e.protocol.timeRes = util::checkRange(nameOf(ov, "time_res"), *ov.timeRes, 0, kMaxRes);
    json flat = json::object();
    for (const char* k : {"tolerance", "rounds", "fit", "subpixel"})
        if (r.has(std::string("equal_time_") + k)) flat[k] = r.at(std::string("equal_time_") + k);
    equaltime::readProtocol(Reader{r.path, flat, "equal_time_"}, e.protocol, rules);
    if (!r.has("equal_time") || !r.at("equal_time").is_object()) return;
    const Reader q{r.path, r.at("equal_time"), "equal_time."};
    std::set<std::string> known = {"methods",  "tolerance", "rounds", "fit",     "mode",
                                   "time_res", "reps",      "mc",     "subpixel"};
    q.onlyKnown(known);
    rules.elsewhere = {{"time_res", "the top-level \"time_res\" (it times every cell)"},
                       {"reps", "the top-level \"reps\" (it times every cell)"},
                       {"mc", "the top-level \"mc\" (the baselines)"}};
    for (const auto& [k, v] : flat.items())
        if (q.has(k)) q.fail(k, fmt::format("also set by the top-level \"equal_time_{}\"", k));
    equaltime::readProtocol(q, e.protocol, rules);
}

// res, precision, size, extent, save_images, seeds; the command line's
// overrides last.
void readSettings(const Reader& r, const Overrides& ov, Experiment& e)
{
    if (r.has("res")) e.res = static_cast<int>(r.integer("res", 1, kMaxRes));
    if (ov.res) e.res = util::checkRange(nameOf(ov, "res"), *ov.res, 1, kMaxRes);
    if (r.has("precision")) {
        e.precisions = r.strings("precision");
        for (const auto& p : e.precisions) try {
                methods::parsePrecision(p);
            } catch (const InputError& err) {
                r.fail("precision", err.what());
            }
    }
    if (r.has("size") && r.at("size") == "file") {
        e.sizeFromFile = true;
    } else if (r.has("size")) {
        const json& s = r.at("size");
        if (!s.is_array() || s.size() != 2 || !s[0].is_number() || !s[1].is_number())
            r.fail("size", fmt::format("expected [W, L] in metres or \"file\", found {}", s.dump()));
        e.width = util::checkRange(r.name("size") + " W", s[0].get<double>(), 0, kMaxSceneLength, "m");
        e.length = util::checkRange(r.name("size") + " L", s[1].get<double>(), 0, kMaxSceneLength, "m");
        if (!(e.width > 0 && e.length > 0)) r.fail("size", fmt::format("expected W, L > 0, found {}", s.dump()));
    }
    if (r.has("shape")) try {
            e.shape = parseLightShape(r.string("shape"));
        } catch (const InputError& err) {
            r.fail("shape", err.what());
        }
    if (r.has("extent")) e.extent = r.number("extent", 1e-6, kMaxSceneLength);  // 1 um: anything smaller is a typo
    if (r.has("save_images")) e.saveImages = r.boolean("save_images");
    if (r.has("seeds")) e.seeds = static_cast<int>(r.integer("seeds", 1, kMaxSeeds));
    if (ov.seeds) e.seeds = util::checkRange(nameOf(ov, "seeds"), *ov.seeds, 1, kMaxSeeds);
}

}  // namespace

const std::vector<std::string>& experimentKeys() { return kKeys; }

Experiment loadExperiment(const std::string& path, const Overrides& ov)
{
    // An experiment file is a few kB; 16 MiB leaves room for generated ones.
    const json j = util::readJsonObject(path, "an experiment file (JSON)", 16u << 20);
    Reader r{path, j};
    r.onlyKnown(std::set<std::string>(kKeys.begin(), kKeys.end()));

    Experiment e;
    e.path = path;
    e.raw = j;
    e.name = r.has("name") ? r.string("name") : fs::path(path).stem().string();
    readLuminaires(r, ov, e);
    e.heights = r.numbers("heights", 0, kMaxSceneLength, "m");
    e.rotations = r.angles("rotations", e.rotationText);
    e.sceneKeys = SceneKindKeys::read(j, path);
    readMethods(r, e);
    readSettings(r, ov, e);
    readProtocol(r, ov, e);
    return e;
}

std::string Baseline::at(long n, double extra) const { return equaltime::specAt(spec, n, extra); }

Scene SceneId::scene() const
{
    Scene s;
    s.height = height;
    s.rotation = rotation;
    s.res = res;
    s.width = width;
    s.length = length;
    s.shape = shape;
    s.extent = extent;
    return kindKeys.applied(s, alpha);
}

std::string angleText(double radians)
{
    constexpr double kPi = 3.14159265358979323846;
    if (radians == 0) return "0";
    for (long d = 1; d <= 64; ++d) {
        const double c = radians * double(d) / kPi;
        if (std::fabs(c - std::round(c)) > 1e-9 * std::max(1.0, std::fabs(c)) || std::round(c) <= 0) continue;
        const long ci = std::lround(c);
        const std::string num = ci == 1 ? "pi" : fmt::format("{}pi", ci);
        return d == 1 ? num : fmt::format("{}/{}", num, d);
    }
    return fmt::format("{}", radians);
}

std::string SceneId::label() const
{
    std::string rot;
    for (char c : angleText(rotation)) rot += (std::isalnum(static_cast<unsigned char>(c)) || c == '.') ? c : '-';
    const std::string a = kindKeys.kind == SceneKind::Specular ? fmt::format("_a{}", alpha) : "";
    return util::shortName(fmt::format("{}-{}_h{}_r{}{}_{}", fs::path(luminaire).stem().string(),
                                       util::digestHex(luminaireName).substr(0, 6), height, rot, a, precision));
}

namespace {

std::string luminaireName(const Experiment& e, const std::string& path)
{
    fs::path rel = fs::path(path).lexically_relative(e.luminaireDir);
    if (rel.empty() || *rel.begin() == "..") return path;
    return rel.generic_string();
}

}  // namespace

std::vector<SceneId> scenes(const Experiment& e)
{
    std::vector<SceneId> out;
    for (const auto& lum : e.luminaires) {
        Scene light;  // W, L and the shape of this luminaire's scenes
        light.width = e.width;
        light.length = e.length;
        if (e.sizeFromFile)
            methods::sizeFromFile(methods::loadLuminaire(lum), light, fmt::format("{}: key \"size\"", e.path));
        if (e.shape) light.shape = *e.shape;
        for (double h : e.heights)
            for (size_t ri = 0; ri < e.rotations.size(); ++ri)
                for (double a : e.sceneKeys.alphas)
                    for (const auto& p : e.precisions) {
                        SceneId s;
                        s.luminaire = lum;
                        s.luminaireName = luminaireName(e, lum);
                        s.height = h;
                        s.rotation = e.rotations[ri];
                        s.rotationText = e.rotationText[ri];
                        s.precision = p;
                        s.res = e.res;
                        s.width = light.width;
                        s.length = light.length;
                        s.shape = light.shape;
                        s.extent = e.extent;
                        s.kindKeys = e.sceneKeys;
                        s.alpha = a;
                        s.index = out.size();
                        out.push_back(s);
                    }
    }
    return out;
}

bool inShard(const SceneId& s, int k, int n) { return static_cast<int>(s.index % n) == k - 1; }

std::string overrideName(const std::string& key) { return fmt::format("override of key \"{}\"", key); }

void parseShard(const std::string& name, const std::string& text, int& k, int& n)
{
    auto sl = text.find('/');
    try {
        if (sl == std::string::npos) throw std::invalid_argument("");
        size_t a = 0, b = 0;
        k = std::stoi(text.substr(0, sl), &a);
        n = std::stoi(text.substr(sl + 1), &b);
        if (a != sl || b != text.size() - sl - 1) throw std::invalid_argument("");
    } catch (const std::exception&) {
        throw InputError(fmt::format("{}: expected K/N (e.g. 2/4), got '{}'", name, text));
    }
    if (n < 1 || k < 1 || k > n) throw InputError(fmt::format("{}: expected 1 <= K <= N, got '{}'", name, text));
}

}  // namespace lb::experiments
