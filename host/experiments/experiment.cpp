#include "experiments/experiment.h"

#include "cl/runtime.h"
#include "methods/spec.h"
#include "util/check.h"
#include "util/error.h"
#include "util/fileio.h"

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

// Errors name the file and the key.
struct Reader {
    std::string path;
    const json& j;

    std::string name(const std::string& key) const { return fmt::format("{}: key \"{}\"", path, key); }
    [[noreturn]] void fail(const std::string& key, const std::string& what) const
    {
        throw InputError(fmt::format("{}: {}", name(key), what));
    }
    bool has(const std::string& key) const { return j.contains(key); }
    const json& at(const std::string& key) const
    {
        if (!j.contains(key)) fail(key, "missing");
        return j.at(key);
    }
    double number(const std::string& key, double lo, double hi) const
    {
        const json& v = at(key);
        if (!v.is_number()) fail(key, fmt::format("expected a number, found {}", v.dump()));
        return util::checkRange(name(key), v.get<double>(), lo, hi);
    }
    long integer(const std::string& key, long lo, long hi) const
    {
        const json& v = at(key);
        if (!v.is_number_integer()) fail(key, fmt::format("expected an integer, found {}", v.dump()));
        return util::checkRange(name(key), v.get<long>(), lo, hi);
    }
    std::string string(const std::string& key) const
    {
        const json& v = at(key);
        if (!v.is_string()) fail(key, fmt::format("expected a string, found {}", v.dump()));
        return v.get<std::string>();
    }
    // A list of strings. A bare string is an error (a typo for a list of one
    // would otherwise pass silently), except `luminaires: "*"`, read by the caller.
    std::vector<std::string> strings(const std::string& key, bool nonEmpty = true) const
    {
        const json& v = at(key);
        std::vector<std::string> out;
        if (!v.is_array()) fail(key, fmt::format("expected a list of strings like [\"a\", \"b\"], found {}", v.dump()));
        for (const auto& x : v) {
            if (!x.is_string()) fail(key, fmt::format("expected a list of strings, found element {}", x.dump()));
            out.push_back(x.get<std::string>());
        }
        if (nonEmpty && out.empty()) fail(key, "expected a non-empty list");
        return out;
    }
    std::vector<long> integers(const std::string& key, long lo, long hi) const
    {
        const json& v = at(key);
        if (!v.is_array()) fail(key, fmt::format("expected a list of integers, found {}", v.dump()));
        std::vector<long> out;
        for (const auto& x : v) {
            if (!x.is_number_integer() || x.get<long>() < lo || x.get<long>() > hi)
                fail(key, fmt::format("expected integers in [{}, {}], found element {}", lo, hi, x.dump()));
            out.push_back(x.get<long>());
        }
        return out;
    }
};

const std::set<std::string> kKeys = {"name",
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
                                     "extent",
                                     "reps",
                                     "equal_time_tolerance",
                                     "save_images",
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
        if (e.is_regular_file() && (ext == ".ldt" || ext == ".ies")) files.push_back(e.path());
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

std::string resolveDir(const std::string& dir)
{
    fs::path p(dir);
    if (p.is_absolute() || fs::exists(p)) return p.string();
    return (fs::path(LB_SOURCE_DIR) / p).string();  // relative to the source tree
}

}  // namespace

Experiment loadExperiment(const std::string& path, const Overrides& ov)
{
    // An experiment file is a few kB; 16 MiB leaves room for generated ones.
    const std::string fileText = util::readFile(path, "an experiment file (JSON)", 16u << 20);
    json j;
    try {
        j = json::parse(fileText);
    } catch (const json::parse_error& e) {
        throw InputError(fmt::format("{}: not valid JSON: {}", path, e.what()));
    }
    if (!j.is_object()) throw InputError(fmt::format("{}: expected a JSON object", path));
    Reader r{path, j};
    for (auto it = j.begin(); it != j.end(); ++it)
        if (!kKeys.count(it.key()))
            r.fail(it.key(),
                   "unknown key (known: name, description, luminaire_dir, luminaires, heights, rotations, "
                   "methods, equal_time, mci_curve, mc, equal_time_fit, reference, res, precision, size, "
                   "extent, reps, equal_time_tolerance, save_images, time_res, scene, alpha, eye, albedo)");

    Experiment e;
    e.path = path;
    e.raw = j;
    e.name = r.has("name") ? r.string("name") : fs::path(path).stem().string();

    // Luminaires: --luminaires DIR takes every file there; otherwise the list
    // (or "*") relative to luminaire_dir.
    e.luminaireDir = resolveDir(r.has("luminaire_dir") ? r.string("luminaire_dir") : "luminaires");
    if (!ov.luminaireDir.empty()) {
        e.luminaireDir = ov.luminaireDir;
        e.luminaires = luminaireFiles(ov.luminaireDir, "--luminaires");
    } else {
        auto names = j.contains("luminaires") && j["luminaires"] == "*" ? std::vector<std::string>{"*"}
                                                                        : r.strings("luminaires");
        if (names.size() == 1 && names[0] == "*") {
            e.luminaires = luminaireFiles(e.luminaireDir, path + ": key \"luminaires\"");
        } else {
            for (const auto& n : names) {
                fs::path p = fs::path(n).is_absolute() ? fs::path(n) : fs::path(e.luminaireDir) / n;
                if (!fs::exists(p)) r.fail("luminaires", fmt::format("file '{}' not found", p.string()));
                e.luminaires.push_back(p.string());
            }
        }
    }

    const json& hs = r.at("heights");
    if (!hs.is_array() || hs.empty()) r.fail("heights", "expected a non-empty list of numbers");
    for (const auto& h : hs) {
        if (!h.is_number()) r.fail("heights", fmt::format("expected numbers, found element {}", h.dump()));
        e.heights.push_back(util::checkRange(r.name("heights"), h.get<double>(), 0, kMaxSceneLength, "m"));
    }
    const json& rs = r.at("rotations");
    if (!rs.is_array() || rs.empty()) r.fail("rotations", "expected a non-empty list");
    for (const auto& x : rs) {
        std::string text = x.is_string() ? x.get<std::string>() : x.dump();
        if (!x.is_string() && !x.is_number())
            r.fail("rotations", fmt::format("expected radians or an expression like 3pi/4, found {}", x.dump()));
        e.rotations.push_back(util::parseAngle(r.name("rotations"), text));
        e.rotationText.push_back(text);
    }

    e.sceneKeys = SceneKindKeys::read(j, path);
    // Methods are checked against the registry now, not after an hour of references.
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
        e.equalTime = r.strings("equal_time", false);
        for (const auto& m : e.equalTime)
            if (!canon.count(checkSpec("equal_time", m).canonical()))
                r.fail("equal_time", fmt::format("'{}' is not one of \"methods\"", m));
    }
    if (r.has("mc")) e.mc = r.string("mc");
    if (checkSpec("mc", e.mc).name != "mc") r.fail("mc", fmt::format("expected an mc SPEC, found '{}'", e.mc));
    for (const char* k : {"n", "extra"})
        if (checkSpec("mc", e.mc).given.count(k))
            r.fail("mc", fmt::format("must not set {} (the runner chooses it)", k));
    if (r.has("reference")) e.reference = r.string("reference");
    checkSpec("reference", e.reference);
    if (r.has("mci_curve")) e.mciCurve = r.integers("mci_curve", 1, 1 << 20);
    e.equalTimeFit = r.has("equal_time_fit") ? r.integers("equal_time_fit", 1, 1 << 20) : std::vector<long>{8, 32, 128};
    if (!e.equalTime.empty() && e.mciCurve.empty() && e.equalTimeFit.size() < 2)
        r.fail("equal_time_fit", "expected at least two sample counts to fit t(N)");

    if (r.has("res")) e.res = static_cast<int>(r.integer("res", 1, kMaxRes));
    if (ov.res) e.res = util::checkRange("--res", *ov.res, 1, kMaxRes);
    if (r.has("precision")) {
        e.precisions = r.strings("precision");
        for (const auto& p : e.precisions) try {
                methods::parsePrecision(p);
            } catch (const InputError& err) {
                r.fail("precision", err.what());
            }
    }
    if (r.has("size")) {
        const json& s = r.at("size");
        if (!s.is_array() || s.size() != 2 || !s[0].is_number() || !s[1].is_number())
            r.fail("size", fmt::format("expected [W, L] in metres, found {}", s.dump()));
        e.width = util::checkRange(r.name("size") + " W", s[0].get<double>(), 0, kMaxSceneLength, "m");
        e.length = util::checkRange(r.name("size") + " L", s[1].get<double>(), 0, kMaxSceneLength, "m");
        if (!(e.width > 0 && e.length > 0)) r.fail("size", fmt::format("expected W, L > 0, found {}", s.dump()));
    }
    if (r.has("extent")) e.extent = r.number("extent", 1e-6, kMaxSceneLength);  // 1 um: anything smaller is a typo
    // DESIGN 6: the median of at least 5 timed runs.
    if (r.has("reps")) e.reps = static_cast<int>(r.integer("reps", kMinExperimentReps, ocl::kMaxReps));
    if (ov.reps) e.reps = util::checkRange("--reps", *ov.reps, kMinExperimentReps, ocl::kMaxReps);
    if (r.has("time_res")) e.timeRes = static_cast<int>(r.integer("time_res", 0, kMaxRes));
    if (ov.timeRes) e.timeRes = util::checkRange("--time-res", *ov.timeRes, 0, kMaxRes);
    if (r.has("equal_time_tolerance")) e.equalTimeTolerance = r.number("equal_time_tolerance", 0.001, 10);
    if (r.has("save_images")) {
        if (!j["save_images"].is_boolean()) r.fail("save_images", "expected true or false");
        e.saveImages = j["save_images"];
    }
    return e;
}

Scene SceneId::scene() const
{
    Scene s;
    s.height = height;
    s.rotation = rotation;
    s.res = res;
    s.width = width;
    s.length = length;
    s.extent = extent;
    return kindKeys.applied(s, alpha);
}

std::string SceneId::label() const
{
    std::string rot;
    for (char c : rotationText) rot += (std::isalnum(static_cast<unsigned char>(c)) || c == '.') ? c : '-';
    const std::string a = kindKeys.kind == SceneKind::Specular ? fmt::format("_a{}", alpha) : "";
    return fmt::format("{}_h{}_r{}{}_{}", fs::path(luminaire).stem().string(), height, rot, a, precision);
}

std::vector<SceneId> scenes(const Experiment& e)
{
    std::vector<SceneId> out;
    for (const auto& lum : e.luminaires)
        for (double h : e.heights)
            for (size_t ri = 0; ri < e.rotations.size(); ++ri)
                for (double a : e.sceneKeys.alphas)
                    for (const auto& p : e.precisions) {
                        SceneId s;
                        s.luminaire = lum;
                        s.height = h;
                        s.rotation = e.rotations[ri];
                        s.rotationText = e.rotationText[ri];
                        s.precision = p;
                        s.res = e.res;
                        s.width = e.width;
                        s.length = e.length;
                        s.extent = e.extent;
                        s.kindKeys = e.sceneKeys;
                        s.alpha = a;
                        s.index = out.size();
                        out.push_back(s);
                    }
    return out;
}

bool inShard(const SceneId& s, int k, int n) { return static_cast<int>(s.index % n) == k - 1; }

void parseShard(const std::string& text, int& k, int& n)
{
    auto sl = text.find('/');
    try {
        if (sl == std::string::npos) throw std::invalid_argument("");
        size_t a = 0, b = 0;
        k = std::stoi(text.substr(0, sl), &a);
        n = std::stoi(text.substr(sl + 1), &b);
        if (a != sl || b != text.size() - sl - 1) throw std::invalid_argument("");
    } catch (const std::exception&) {
        throw InputError(fmt::format("--shard: expected K/N (e.g. 2/4), got '{}'", text));
    }
    if (n < 1 || k < 1 || k > n) throw InputError(fmt::format("--shard: expected 1 <= K <= N, got '{}'", text));
}

}  // namespace lb::experiments
