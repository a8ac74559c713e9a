// tune.cpp -- see tune.h.
#include "tune/tune.h"

#include "methods/render.h"
#include "methods/spec.h"
#include "metrics/flip.h"
#include "metrics/metrics.h"
#include "photometry/load.h"
#include "util/check.h"
#include "util/error.h"
#include "util/fileio.h"
#include "util/json_file.h"
#include "util/process.h"

#include <fmt/format.h>
#include <nlopt.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <set>
#include <tuple>
#include "lb_build_config.h"

namespace lb::tune {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

using Reader = util::JsonKeys;

// train / validation: {luminaires, heights, rotations}. Heights from
// -kMaxSceneLength (a light through the receiver plane is a case to tune on).
SceneSet sceneSet(const Reader& file, const std::string& key, const std::string& lumDir)
{
    const json& j = file.at(key);
    if (!j.is_object()) file.fail(key, "expected an object with luminaires, heights, rotations");
    Reader r{file.path, j, key + "."};
    r.onlyKnown({"luminaires", "heights", "rotations"});
    SceneSet s;
    for (const auto& n : r.strings("luminaires")) {
        fs::path p = fs::path(n).is_absolute() ? fs::path(n) : fs::path(lumDir) / n;
        if (!fs::exists(p)) r.fail("luminaires", fmt::format("file '{}' not found", p.string()));
        s.luminaires.push_back(p.string());
    }
    s.heights = r.numbers("heights", -kMaxSceneLength, kMaxSceneLength, "m");
    s.rotations = r.angles("rotations", s.rotationText);
    return s;
}

// One scene: its table, its reference image (and with the equal_time
// objective MCI's curve on it).
struct Case {
    std::string label;
    std::string luminaire;  // the file's name, e.g. lambert.ldt
    std::shared_ptr<photometry::Table> table;
    Scene scene;
    Image ref;
    std::vector<equaltime::MetricPoint> mci;
    double scale = 1;  // relative: the scale SPEC's metric on this scene
};

}  // namespace

double Dim::toValue(double u) const
{
    u = std::clamp(u, 0.0, 1.0);
    double v = param.scale == methods::Scale::Log && param.lo > 0
        ? std::exp(std::log(param.lo) + u * (std::log(param.hi) - std::log(param.lo)))
        : param.lo + u * (param.hi - param.lo);
    v = std::clamp(v, param.lo, param.hi);
    if (param.kind == methods::Kind::Int) v = std::round(v);
    return v;
}

double Dim::toUnit(double v) const
{
    if (param.hi <= param.lo) return 0;
    double u = param.scale == methods::Scale::Log && param.lo > 0
        ? (std::log(std::max(v, param.lo)) - std::log(param.lo)) / (std::log(param.hi) - std::log(param.lo))
        : (v - param.lo) / (param.hi - param.lo);
    return std::clamp(u, 0.0, 1.0);
}

equaltime::Protocol tuneProtocol()
{
    equaltime::Protocol p;
    p.timeRes = 128;
    p.reps = 5;
    p.rounds = 5;
    p.fit = {1, 2, 4, 8, 16, 32, 64};
    p.mode = equaltime::Mode::Aim;
    return p;
}

double pairedMs(const equaltime::Protocol& p, const equaltime::Frames& frames, const methods::MethodSpec& method,
                const equaltime::McAt& mcAt, const equaltime::Curve& curve, double aimMs)
{
    const equaltime::Result q = equaltime::pairUp(p, frames, method, mcAt, curve, aimMs);
    const double t =
        equaltime::interpolateMs(curve, q.n) * (1 - q.extra) + equaltime::interpolateMs(curve, q.n + 1) * q.extra;
    return t / q.ratio;
}

double equalTimeScore(double metric, double ms, const std::vector<equaltime::MetricPoint>& curveByN)
{
    return std::log(std::max(metric, 1e-300) / equaltime::metricAt(curveByN, ms));
}

double aggregateScores(const std::string& objective, const std::vector<double>& scores)
{
    if (scores.empty()) throw Error("tune: aggregateScores of no scores");
    if (objective == "worst") return *std::max_element(scores.begin(), scores.end());
    double s = 0;
    for (double x : scores) s += objective == "geomean" ? std::log(std::max(x, 1e-300)) : x;
    s /= double(scores.size());
    return objective == "geomean" ? std::exp(s) : s;
}

double relativeScore(double metric, double scale)
{
    return metric / (std::isfinite(scale) && scale > 0 ? scale : 1e-30);
}

json parameterSpread(const std::vector<Dim>& dims, const std::vector<std::vector<double>>& foldValues)
{
    json out = json::object();
    for (size_t i = 0; i < dims.size(); ++i) {
        std::vector<double> v, u;
        for (const auto& f : foldValues) {
            v.push_back(f.at(i));
            u.push_back(dims[i].toUnit(f.at(i)));
        }
        if (v.empty()) continue;
        const double n = double(v.size());
        const double mean = std::accumulate(v.begin(), v.end(), 0.0) / n;
        double var = 0;
        for (double x : v) var += (x - mean) * (x - mean);
        const auto [ulo, uhi] = std::minmax_element(u.begin(), u.end());
        out[dims[i].param.name] = {{"values", v},
                                   {"min", *std::min_element(v.begin(), v.end())},
                                   {"max", *std::max_element(v.begin(), v.end())},
                                   {"mean", mean},
                                   {"std", std::sqrt(var / n)},
                                   {"default", dims[i].param.def},
                                   {"unit_range", *uhi - *ulo}};
    }
    return out;
}

namespace {

// "method", "params" (the searched parameters: every tunable numeric one the
// method does not set, unless listed) and "reference".
void readSearch(const Reader& r, TuneExperiment& e)
{
    if (!r.has("method")) r.fail("method", "missing (a SPEC, e.g. \"cubature:triangulation=fan\")");
    e.method = r.string("method");
    const SceneKind kind = e.sceneKeys.kind;
    methods::MethodSpec base;
    try {
        base = methods::parseSpec(e.method, kind);
    } catch (const InputError& err) {
        r.fail("method", err.what());
    }
    const auto& fam = base.family();
    auto numeric = [](const methods::Param& p) {
        return p.kind == methods::Kind::Real || p.kind == methods::Kind::Int;
    };
    if (r.has("params")) {
        e.params = r.strings("params");
        for (const auto& n : e.params) {
            auto it = std::find_if(fam.params.begin(), fam.params.end(), [&](auto& p) { return p.name == n; });
            if (it == fam.params.end() || !numeric(*it))
                r.fail("params", fmt::format("'{}' is not a numeric parameter of method {}", n, base.name));
            if (base.given.count(n))
                r.fail("params", fmt::format("'{}' is searched, so \"method\" must not set it", n));
            if (std::count(e.params.begin(), e.params.end(), n) > 1)
                r.fail("params", fmt::format("'{}' named twice; expected each parameter once", n));
            if (fam.unused && fam.unused(base, n))
                r.fail("params",
                       fmt::format("'{}' has no effect with method {} (e.g. a static sample's coordinate "
                                   "beyond \"static\")",
                                   n, e.method));
        }
    } else {
        for (const auto& p : fam.params)
            if (p.tunable && numeric(p) && !base.given.count(p.name) && !(fam.unused && fam.unused(base, p.name)))
                e.params.push_back(p.name);
    }
    if (e.params.empty()) r.fail("params", fmt::format("method {} has no tunable parameter left to search", base.name));
    if (r.has("bounds")) {
        const json& b = r.at("bounds");
        if (!b.is_object()) r.fail("bounds", "expected an object {\"name\": [lo, hi], ...}");
        for (const auto& [n, range] : b.items()) {
            if (std::find(e.params.begin(), e.params.end(), n) == e.params.end())
                r.fail("bounds", fmt::format("'{}' is not searched (searched: {})", n, fmt::join(e.params, ", ")));
            const auto& p = *std::find_if(fam.params.begin(), fam.params.end(), [&](auto& q) { return q.name == n; });
            if (!range.is_array() || range.size() != 2 || !range[0].is_number() || !range[1].is_number())
                r.fail("bounds", fmt::format("'{}': expected [lo, hi], found {}", n, range.dump()));
            const double lo = range[0].get<double>(), hi = range[1].get<double>();
            if (!(lo >= p.lo && hi <= p.hi && lo < hi))
                r.fail("bounds",
                       fmt::format("'{}': expected lo < hi within the tunables table's [{}, {}], found [{}, {}]", n,
                                   p.lo, p.hi, lo, hi));
            e.bounds[n] = {lo, hi};
        }
    }
    if (r.has("reference")) {
        e.reference = r.string("reference");
        try {
            if (methods::parseSpec(e.reference, kind).name != "reference")
                r.fail("reference", "expected a reference SPEC");
        } catch (const InputError& err) {
            r.fail("reference", err.what());
        }
    }
}

// The scenes: res, precision, size, extent and the train and validation sets.
void readScenes(const Reader& r, TuneExperiment& e)
{
    std::string lumDir = util::resolveSourceDir(r.has("luminaire_dir") ? r.string("luminaire_dir") : "luminaires");
    if (r.has("res")) e.res = static_cast<int>(r.integer("res", 1, 4096));
    if (r.has("precision")) {
        e.precision = r.string("precision");
        try {
            methods::parsePrecision(e.precision);
        } catch (const InputError& err) {
            r.fail("precision", err.what());
        }
    }
    if (r.has("size")) {
        auto s = r.numbers("size", 0, kMaxSceneLength, "m");
        if (s.size() != 2 || !(s[0] > 0) || !(s[1] > 0)) r.fail("size", "expected [W, L] in metres, both > 0");
        e.width = s[0];
        e.length = s[1];
    }
    if (r.has("extent")) e.extent = r.number("extent", 1e-6, kMaxSceneLength);
    for (const char* k : {"train", "validation"})
        if (!r.has(k)) r.fail(k, "missing (an object with luminaires, heights, rotations)");
    e.train = sceneSet(r, "train", lumDir);
    e.validation = sceneSet(r, "validation", lumDir);
}

// "equal_time": the equal-time protocol (equaltime::readProtocol); rounds
// default to reps.
void readEqualTime(const Reader& r, TuneExperiment& e)
{
    if (e.objective != "equal_time")
        r.fail("equal_time", fmt::format("set, but \"objective\" is '{}' (equal_time uses it)", e.objective));
    const json& j = r.at("equal_time");
    const std::vector<std::string>& keys = equaltime::protocolKeys();
    if (!j.is_object()) r.fail("equal_time", fmt::format("expected an object with {}", fmt::join(keys, ", ")));
    Reader q{r.path, j, "equal_time."};
    if (q.has("mci_n")) q.fail("mci_n", "the curve's sample counts are the key \"fit\"");
    q.onlyKnown(std::set<std::string>(keys.begin(), keys.end()));
    equaltime::ReadRules rules;
    rules.minTimeRes = 8;
    rules.maxTimeRes = 4096;
    rules.kind = e.sceneKeys.kind;
    equaltime::readProtocol(q, e.equalTime, rules);
    if (e.equalTime.subpixel)
        q.fail("subpixel", "tune pairs MC at N >= 1 (its time model is t(N)); subpixel is for run and bench");
    if (!q.has("rounds")) e.equalTime.rounds = e.equalTime.reps;
}

// The optimiser: metric, objective, the nlopt algorithms and their budgets.
void readOptimiser(const Reader& r, TuneExperiment& e)
{
    if (r.has("metric")) {
        e.metric = r.string("metric");
        const auto& ok = metrics::minimisableMetrics();
        if (std::find(ok.begin(), ok.end(), e.metric) == ok.end())
            r.fail("metric", fmt::format("expected one of {}, found '{}'", fmt::join(ok, ", "), e.metric));
    }
    if (r.has("objective")) {
        e.objective = r.string("objective");
        const std::set<std::string> ok = {"mean", "worst", "geomean", "relative", "equal_time"};
        if (!ok.count(e.objective))
            r.fail("objective",
                   fmt::format("expected mean, worst, geomean, relative or equal_time, found '{}'", e.objective));
    }
    if (r.has("scale")) {
        if (e.objective != "relative")
            r.fail("scale", fmt::format("set, but \"objective\" is '{}' (relative uses it)", e.objective));
        e.scale = r.string("scale");
        try {
            methods::parseSpec(e.scale, e.sceneKeys.kind);
        } catch (const InputError& err) {
            r.fail("scale", err.what());
        }
    }
    if (r.has("equal_time")) readEqualTime(r, e);
    auto checkAlgo = [&](const std::string& k, const std::string& name) {
        if (nlopt_algorithm_from_string(name.c_str()) < 0)
            r.fail(k, fmt::format("unknown nlopt algorithm '{}' (e.g. LN_SBPLX, LN_NELDERMEAD, GN_DIRECT_L)", name));
    };
    if (r.has("algorithm")) e.algorithm = r.string("algorithm");
    checkAlgo("algorithm", e.algorithm);
    if (e.algorithm.rfind("LN_", 0) != 0 && e.algorithm.rfind("GN_", 0) != 0)
        r.fail("algorithm",
               fmt::format("'{}' needs gradients; use a derivative-free LN_ or GN_ algorithm", e.algorithm));
    if (r.has("global")) {
        e.global = r.string("global");
        checkAlgo("global", e.global);
        if (e.global.rfind("GN_", 0) != 0)
            r.fail("global", fmt::format("expected a GN_ algorithm, found '{}'", e.global));
    }
    if (r.has("global_maxeval")) e.globalMaxeval = static_cast<int>(r.integer("global_maxeval", 1, 1000000));
    if (r.has("maxeval")) e.maxeval = static_cast<int>(r.integer("maxeval", 1, 1000000));
    if (r.has("maxtime")) e.maxtime = r.number("maxtime", 0, 1e7);
    if (r.has("seed")) e.seed = static_cast<unsigned>(r.integer("seed", 0, 0xffffffffL));
    if (r.has("cross_validation")) {
        const std::string cv = r.string("cross_validation");
        if (cv != "leave-one-luminaire-out" && cv != "none")
            r.fail("cross_validation", fmt::format("expected leave-one-luminaire-out or none, found '{}'", cv));
        e.crossValidation = cv != "none";
        if (e.crossValidation && e.train.luminaires.size() < 2)
            r.fail("cross_validation", "leave-one-luminaire-out needs two training luminaires or more");
    }
    if (r.has("presets")) e.presets = r.boolean("presets");
}

}  // namespace

TuneExperiment loadTuneExperiment(const std::string& path)
{
    // A tune file is a few kB; 16 MiB leaves room for generated ones.
    const json j = util::readJsonObject(path, "a tune experiment file (JSON)", 16u << 20);
    Reader r{path, j};
    r.onlyKnown(
        {"name",      "description",    "method",  "params",  "bounds",     "reference",  "luminaire_dir",    "res",
         "precision", "size",           "extent",  "train",   "validation", "objective",  "algorithm",        "metric",
         "global",    "global_maxeval", "maxeval", "maxtime", "seed",       "equal_time", "cross_validation", "presets",
         "scene",     "alpha",          "eye",     "albedo",  "scale"});
    TuneExperiment e;
    e.path = path;
    e.raw = j;
    e.name = r.has("name") ? r.string("name") : fs::path(path).stem().string();
    e.sceneKeys = SceneKindKeys::read(j, path);
    readSearch(r, e);
    readScenes(r, e);
    readOptimiser(r, e);
    return e;
}

std::string specWith(const std::string& base, const std::vector<std::string>& names, const std::vector<double>& values,
                     SceneKind kind)
{
    methods::MethodSpec s = methods::parseSpec(base, kind);
    std::map<std::string, std::string> kv;
    for (const auto& k : s.given) kv[k] = s.values.at(k);
    for (size_t i = 0; i < names.size(); ++i) kv[names[i]] = fmt::format("{}", values[i]);
    std::string out = s.name;
    char sep = ':';
    for (const auto& [k, v] : kv) {
        out += fmt::format("{}{}={}", sep, k, v);
        sep = ',';
    }
    return out;
}

namespace {

// One evaluation of a spec on one scene.
struct Eval {
    double metric = 0;  // the experiment's metric (1e6 when undefined or non-finite pixels)
    double ms = 0;  // equal_time: the median time at the equal-time resolution
    double score = 0;  // what the objective aggregates: metric, or the equal-time score
    long nonfinite = 0;
};

class Tuner {
public:
    Tuner(const TuneExperiment& e, const TuneOptions& o) : e_(e), opt_(o), rt_(o.device)
    {
        prec_ = methods::parsePrecision(e.precision);
        base_ = methods::parseSpec(e.method, e.sceneKeys.kind);
        const auto& fam = base_.family();
        for (const auto& n : e.params)
            for (const auto& p : fam.params)
                if (p.name == n) {
                    Dim d{p};
                    if (auto b = e.bounds.find(n); b != e.bounds.end()) std::tie(d.param.lo, d.param.hi) = b->second;
                    dims_.push_back(d);
                }
        for (const auto& d : dims_) names_.push_back(d.param.name);
        train_ = cases(e.train, "train");
        validation_ = cases(e.validation, "validation");
        if (train_.empty() || validation_.empty())
            throw Error(fmt::format("{}: the metric {} is undefined on every {} scene (black references)", e.path,
                                    e.metric, train_.empty() ? "training" : "validation"));
    }

    json run();

private:
    bool equalTime() const { return e_.objective == "equal_time"; }

    double metricOf(const Image& ref, const Image& img, long* nonfinite) const
    {
        auto m = metrics::compare(ref, img);
        if (e_.metric == "flip") m.flip = metrics::flip(ref, img);  // only when minimised: it costs most
        if (nonfinite) *nonfinite += m.nonfinite;
        const double v = metrics::minimisable(m, e_.metric);
        return m.nonfinite > 0 || !std::isfinite(v) ? 1e6 : v;
    }

    // The equal-time timing: one warm-up and the median of reps launches at time_res.
    methods::RenderOptions timedOptions() const
    {
        methods::RenderOptions ro;
        ro.reps = e_.equalTime.reps;
        ro.timeRes = e_.equalTime.timeRes;
        return ro;
    }

    // The SPEC of MCI at n samples (+ extra).
    methods::MethodSpec mciAt(long n, double extra = 0) const
    {
        return methods::parseSpec(equaltime::specAt(e_.equalTime.mc, n, extra), e_.sceneKeys.kind);
    }

    // The method's time on case c's MCI curve clock (pairedMs): the
    // protocol's pairing on the scene at time_res.
    double pairedMs(const Case& c, const methods::MethodSpec& s, double aimMs)
    {
        Scene ts = c.scene;
        if (e_.equalTime.timeRes > 0) ts.res = e_.equalTime.timeRes;
        return tune::pairedMs(
            e_.equalTime, equaltime::preparedFrames(rt_, *c.table, ts, prec_), s,
            [&](long n, double extra) { return mciAt(n, extra); }, curveOf(c), aimMs);
    }

    // Case c's measured t(N) at the protocol's fit.
    equaltime::Curve curveOf(const Case& c) const
    {
        equaltime::Curve curve;
        for (size_t i = 0; i < e_.equalTime.fit.size(); ++i) curve.emplace_back(e_.equalTime.fit[i], c.mci[i].ms);
        return curve;
    }

    // MCI's curve on one scene: metric and time at each of the protocol's fit.
    std::vector<equaltime::MetricPoint> mciCurve(const Case& c, const std::string& what)
    {
        std::vector<equaltime::MetricPoint> out;
        const auto& k = e_.equalTime;
        for (long n : k.fit) {
            auto r = methods::render(rt_, *c.table, c.scene, mciAt(n), prec_, timedOptions());
            out.push_back({r.timing.median_ms, metricOf(c.ref, r.image, nullptr)});
        }
        if (!opt_.quiet) {
            std::string line;
            for (size_t i = 0; i < out.size(); ++i)
                line += fmt::format("  N={} {:.3g} ms {:.3g}", k.fit[i], out[i].ms, out[i].metric);
            fmt::print(stderr, "tune: {} MCI curve {}:{}\n", what, c.label, line);
        }
        return out;
    }

    // Whether the metric is defined against this reference (NMSE is not on
    // a black one: a beam that misses the receiver); scenes where it is not
    // would score every candidate alike (1e6) and are left out.
    bool metricDefined(const Image& ref) const
    {
        auto m = metrics::compare(ref, ref);
        return m.nonfinite == 0 && std::isfinite(metrics::minimisable(m, e_.metric));
    }

    // The scale SPEC's metric on case c (the relative objective's divisor).
    double scaleOf(const Case& c)
    {
        methods::RenderOptions ro;
        ro.reps = 1;
        auto r = methods::render(rt_, *c.table, c.scene, methods::parseSpec(e_.scale, e_.sceneKeys.kind), prec_, ro);
        return metricOf(c.ref, r.image, nullptr);
    }

    std::vector<Case> cases(const SceneSet& s, const std::string& what)
    {
        std::vector<Case> out;
        methods::MethodSpec ref = methods::parseSpec(e_.reference, e_.sceneKeys.kind);
        methods::RenderOptions ro;
        ro.progress = !opt_.quiet;
        for (const auto& lum : s.luminaires) {
            auto table = std::make_shared<photometry::Table>(photometry::load(lum));
            for (double h : s.heights)
                for (size_t r = 0; r < s.rotations.size(); ++r)
                    for (double alpha : e_.sceneKeys.alphas) {
                        Case c;
                        c.luminaire = fs::path(lum).filename().string();
                        c.table = table;
                        c.scene.height = h;
                        c.scene.rotation = s.rotations[r];
                        c.scene.res = e_.res;
                        c.scene.width = e_.width;
                        c.scene.length = e_.length;
                        c.scene.extent = e_.extent;
                        c.scene = e_.sceneKeys.applied(c.scene, alpha);
                        c.label = fmt::format("{} h={} R={}", fs::path(lum).stem().string(), h, s.rotationText[r]);
                        if (c.scene.kind == SceneKind::Specular) c.label += fmt::format(" alpha={}", alpha);
                        if (!opt_.quiet) fmt::print(stderr, "tune: {} reference {}\n", what, c.label);
                        c.ref = methods::render(rt_, *table, c.scene, ref, prec_, ro).image;
                        if (!metricDefined(c.ref)) {
                            skipped_.push_back(c.label);
                            fmt::print(stderr, "tune: {} {} left out: the metric is undefined on its reference\n", what,
                                       c.label);
                            continue;
                        }
                        if (equalTime()) c.mci = mciCurve(c, what);
                        if (e_.objective == "relative") c.scale = scaleOf(c);
                        out.push_back(std::move(c));
                    }
        }
        return out;
    }

    // The metric (and with equal_time the time and score) of the method with
    // `values` on every case (non-finite pixels or an undefined value: a large
    // penalty so the search moves away; non-finite pixels are counted).
    std::vector<Eval> evaluate(const std::vector<Case>& cs, const std::vector<double>& values)
    {
        methods::MethodSpec s =
            methods::parseSpec(specWith(e_.method, names_, values, e_.sceneKeys.kind), e_.sceneKeys.kind);
        const auto& fam = s.family();
        // Where only the image counts (no equal-time score, no cache, no
        // frames to settle): one launch, no warm-up, timing or statistics.
        const bool imageOnly = !equalTime() && !fam.expensive && fam.settleFrames(s) == 0;
        methods::RenderOptions ro = equalTime() ? timedOptions() : methods::RenderOptions{};
        ro.reps = 1;  // equal_time: the aim of the paired timing below
        std::vector<Eval> out;
        for (const auto& c : cs) {
            Eval ev;
            if (imageOnly) {
                methods::Prepared pm(rt_, *c.table, c.scene, s, prec_);
                pm.launch(0, c.scene.res).wait();
                ev.metric = metricOf(c.ref, pm.image(), &ev.nonfinite);
            } else {
                auto r = methods::render(rt_, *c.table, c.scene, s, prec_, ro);
                ev.metric = metricOf(c.ref, r.image, &ev.nonfinite);
                ev.ms = equalTime() ? pairedMs(c, s, r.timing.median_ms) : r.timing.median_ms;
            }
            ev.score = equalTime()           ? equalTimeScore(ev.metric, ev.ms, c.mci)
                : e_.objective == "relative" ? relativeScore(ev.metric, c.scale)
                                             : ev.metric;
            out.push_back(ev);
        }
        return out;
    }

    double aggregate(const std::vector<Eval>& v) const
    {
        std::vector<double> scores;
        for (const auto& x : v) scores.push_back(x.score);
        return aggregateScores(e_.objective, scores);
    }

    std::vector<double> values(const std::vector<double>& u) const
    {
        std::vector<double> v;
        for (size_t i = 0; i < dims_.size(); ++i) v.push_back(dims_[i].toValue(u[i]));
        return v;
    }

    json paramsJson(const std::vector<double>& v) const
    {
        json p = json::object();
        for (size_t i = 0; i < dims_.size(); ++i) p[dims_[i].param.name] = v[i];
        return p;
    }

    // The parameters of v within 1 % of the search range (in the search's own
    // scale, as nlopt sees it) from a bound: [{param, value, bound lo|hi, limit}].
    json atBound(const std::vector<double>& v) const
    {
        json out = json::array();
        for (size_t i = 0; i < dims_.size(); ++i) {
            const double u = dims_[i].toUnit(v[i]);
            const auto& p = dims_[i].param;
            if (u <= 0.01 || u >= 0.99)
                out.push_back({{"param", p.name},
                               {"value", v[i]},
                               {"bound", u <= 0.01 ? "lo" : "hi"},
                               {"limit", u <= 0.01 ? p.lo : p.hi}});
        }
        return out;
    }

    // One named set's values in a summary: <set>_objective, <set>_<metric>
    // (by the objective; the mean with equal_time) with its per-scene list,
    // mean and worst; with equal_time also the scores, times and MCI's metric
    // at those times per scene.
    void setJson(json& s, const std::string& set, const std::vector<Case>& cs, const std::vector<Eval>& x) const;

    // The defaults, then the search on `train`; the best values.
    struct Search {
        std::vector<double> best;
        std::string algo;
        int evals = 0;
        json trace;
    };
    Search searchOn(const std::vector<Case>& train, const std::string& label);

    // The training luminaires' file names, in order of first appearance.
    std::vector<std::string> trainLuminaires() const
    {
        std::vector<std::string> out;
        for (const auto& c : train_)
            if (std::find(out.begin(), out.end(), c.luminaire) == out.end()) out.push_back(c.luminaire);
        return out;
    }
    // The cases of `cs` whose luminaire is (or with `keep` false: is not) `lum`.
    static std::vector<Case> only(const std::vector<Case>& cs, const std::string& lum, bool keep = true)
    {
        std::vector<Case> out;
        for (const auto& c : cs)
            if ((c.luminaire == lum) == keep) out.push_back(c);
        return out;
    }
    json crossValidation(const std::vector<double>& defaults);
    json presets(const std::vector<double>& defaults, const std::vector<double>& global);

    json header() const;
    json summary(const std::vector<double>& v, const std::string& algo, int evals);
    std::string search(std::vector<double>& u, std::chrono::steady_clock::time_point t0);
    // One nlopt stage from u0; updates best_ and the trace.
    void stage(const std::string& algo, int maxeval, double maxtime, std::vector<double>& u);

    const TuneExperiment& e_;
    TuneOptions opt_;
    ocl::Runtime rt_;
    methods::Precision prec_;
    methods::MethodSpec base_;
    std::vector<Dim> dims_;
    std::vector<std::string> names_;
    std::vector<Case> train_, validation_;
    std::vector<std::string> skipped_;  // scenes left out: the metric is undefined on their reference
    const std::vector<Case>* active_ = &train_;  // what the running search minimises over
    std::string label_;  // "" for the main search, else the fold or preset it runs for
    json trace_ = json::array();
    int evals_ = 0;
    double best_ = std::numeric_limits<double>::infinity();
    std::vector<double> bestU_;
    std::string stageName_;
};

void Tuner::setJson(json& s, const std::string& set, const std::vector<Case>& cs, const std::vector<Eval>& x) const
{
    std::vector<double> m;
    for (const auto& v : x) m.push_back(v.metric);
    const std::string k = set + "_" + e_.metric;
    const double mean = std::accumulate(m.begin(), m.end(), 0.0) / double(m.size());
    const double worst = *std::max_element(m.begin(), m.end());
    s[set + "_objective"] = aggregate(x);
    const double geomean = aggregateScores("geomean", m);
    s[k] = e_.objective == "worst" ? worst : e_.objective == "geomean" ? geomean : mean;
    s[k + "_per_scene"] = m;
    s[k + "_mean"] = mean;
    s[k + "_worst"] = worst;
    s[k + "_geomean"] = geomean;
    if (e_.objective == "relative") {
        json rel = json::array(), scale = json::array();
        for (size_t i = 0; i < x.size(); ++i) {
            rel.push_back(x[i].score);
            scale.push_back(cs[i].scale);
        }
        s[set + "_relative_per_scene"] = rel;
        s[set + "_scale_" + e_.metric + "_per_scene"] = scale;
    }
    if (equalTime()) {
        json score = json::array(), ms = json::array(), mci = json::array();
        for (size_t i = 0; i < x.size(); ++i) {
            score.push_back(x[i].score);
            ms.push_back(x[i].ms);
            mci.push_back(equaltime::metricAt(cs[i].mci, x[i].ms));
        }
        s[set + "_equal_time"] = aggregate(x);
        s[set + "_equal_time_per_scene"] = score;
        s[set + "_ms_per_scene"] = ms;
        s[set + "_mci_" + e_.metric + "_per_scene"] = mci;
    }
}

void Tuner::stage(const std::string& algo, int maxeval, double maxtime, std::vector<double>& u)
{
    size_t n = dims_.size();
    nlopt::opt o(static_cast<nlopt::algorithm>(nlopt_algorithm_from_string(algo.c_str())), static_cast<unsigned>(n));
    o.set_lower_bounds(std::vector<double>(n, 0.0));
    o.set_upper_bounds(std::vector<double>(n, 1.0));
    o.set_maxeval(maxeval);
    if (maxtime > 0) o.set_maxtime(maxtime);
    o.set_initial_step(std::vector<double>(n, 0.15));  // 15% of each (scaled) range
    o.set_xtol_abs(1e-4);
    o.set_ftol_rel(1e-6);
    stageName_ = algo;
    int total = maxeval;
    int k0 = evals_;
    auto f = [](const std::vector<double>& x, std::vector<double>&, void* data) -> double {
        auto* t = static_cast<std::pair<Tuner*, std::pair<int, int>>*>(data);
        Tuner& self = *t->first;
        auto v = self.values(x);
        double obj = self.aggregate(self.evaluate(*self.active_, v));
        ++self.evals_;
        if (obj < self.best_) {
            self.best_ = obj;
            self.bestU_ = x;
        }
        self.trace_.push_back({{"evaluation", self.evals_},
                               {"stage", self.stageName_},
                               {"objective", obj},
                               {"best", self.best_},
                               {"params", self.paramsJson(v)}});
        if (!self.opt_.quiet)
            fmt::print(stderr, "tune: {}{} evaluation {}/{}  objective {:.6g}  best {:.6g}  {}\n", self.label_,
                       self.stageName_, self.evals_ - t->second.first, t->second.second, obj, self.best_,
                       self.paramsJson(v).dump());
        return obj;
    };
    // Progress counts k/maxeval within the stage.
    std::pair<Tuner*, std::pair<int, int>> data{this, {k0, total}};
    o.set_min_objective(f, &data);
    double fval = 0;
    try {
        o.optimize(u, fval);
    } catch (const nlopt::roundoff_limited&) {
        // best point so far stands
    } catch (const nlopt::forced_stop&) {
    }
    if (!bestU_.empty()) u = bestU_;
}

// What is tuned, on which scenes: the head of tune.json.
json Tuner::header() const
{
    json doc;
    doc["experiment"] = e_.path;
    doc["name"] = e_.name;
    doc["method"] = e_.method;
    doc["objective"] = e_.objective;
    doc["metric"] = e_.metric;
    if (e_.objective == "relative") doc["scale"] = e_.scale;
    doc["seed"] = e_.seed;
    doc["device"] = rt_.info().name;
    json dims = json::array();
    for (const auto& d : dims_)
        dims.push_back({{"name", d.param.name},
                        {"default", d.param.def},
                        {"lo", d.param.lo},
                        {"hi", d.param.hi},
                        {"scale", d.param.scale == methods::Scale::Log ? "log" : "linear"},
                        {"meaning", d.param.meaning}});
    doc["search"] = dims;
    json scenes;
    for (auto* set : {&train_, &validation_}) {
        json a = json::array();
        for (const auto& c : *set) a.push_back(c.label);
        scenes[set == &train_ ? "train" : "validation"] = a;
    }
    doc["scenes"] = scenes;
    doc["skipped_scenes"] = skipped_;
    if (equalTime()) {
        const auto& k = e_.equalTime;
        json curves = json::object();
        for (auto* set : {&train_, &validation_})
            for (const auto& c : *set) {
                json pts = json::array();
                for (size_t i = 0; i < c.mci.size(); ++i)
                    pts.push_back({{"n", k.fit[i]}, {"ms", c.mci[i].ms}, {e_.metric, c.mci[i].metric}});
                curves[c.label] = pts;
            }
        doc["equal_time"] = k.json();
        doc["equal_time"]["mci_curves"] = curves;
    }
    return doc;
}

// The errors of the parameter values v on both sets: per scene, aggregated,
// mean and worst; the spec that renders them, the bounds they ended at.
json Tuner::summary(const std::vector<double>& v, const std::string& algo, int evals)
{
    auto tr = evaluate(train_, v);
    auto va = evaluate(validation_, v);
    json s;
    s["params"] = paramsJson(v);
    s["spec"] = specWith(e_.method, names_, v, e_.sceneKeys.kind);
    setJson(s, "train", train_, tr);
    setJson(s, "validation", validation_, va);
    long nf = 0;
    for (auto* x : {&tr, &va})
        for (const auto& ev : *x) nf += ev.nonfinite;
    s["nonfinite"] = nf;
    s["evaluations"] = evals;
    s["algorithm"] = algo;
    s["at_bound"] = atBound(v);
    return s;
}

// The global stage (if any), then the local one from the best point so far;
// returns the algorithms' name ("GLOBAL+LOCAL" or "LOCAL") and leaves the
// best point in bestU_ (u where no evaluation improved on it).
std::string Tuner::search(std::vector<double>& u, std::chrono::steady_clock::time_point t0)
{
    std::string algo = e_.algorithm;
    double remaining = e_.maxtime;
    if (!e_.global.empty()) {
        int g = e_.globalMaxeval > 0 ? e_.globalMaxeval : std::max(1, e_.maxeval / 2);
        stage(e_.global, g, e_.maxtime, u);
        algo = e_.global + "+" + e_.algorithm;
        if (e_.maxtime > 0)
            remaining = std::max(
                1.0, e_.maxtime - std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    int left = std::max(1, e_.maxeval - evals_);
    // The local search starts from the best point so far (the defaults are its first evaluation).
    stage(e_.algorithm, left, remaining, u);
    return algo;
}

Tuner::Search Tuner::searchOn(const std::vector<Case>& train, const std::string& label)
{
    active_ = &train;
    label_ = label;
    trace_ = json::array();
    evals_ = 0;
    best_ = std::numeric_limits<double>::infinity();
    bestU_.clear();
    nlopt::srand(e_.seed);
    std::vector<double> u;
    for (const auto& d : dims_) u.push_back(d.toUnit(std::stod(base_.values.at(d.param.name))));
    Search out;
    out.algo = search(u, std::chrono::steady_clock::now());
    out.best = values(bestU_.empty() ? u : bestU_);
    out.evals = evals_;
    out.trace = trace_;
    active_ = &train_;
    label_.clear();
    return out;
}

// The metric's arithmetic and geometric means over one evaluation's scenes,
// whatever the objective: the two views the cross-validation reports.
json metricMeans(const std::vector<Eval>& x)
{
    std::vector<double> m;
    for (const auto& v : x) m.push_back(v.metric);
    return {{"mean", aggregateScores("mean", m)}, {"geomean", aggregateScores("geomean", m)}, {"per_scene", m}};
}

// Leave-one-luminaire-out: per training luminaire a search on the others'
// training scenes, scored on its own (held out) and on the validation set.
json Tuner::crossValidation(const std::vector<double>& defaults)
{
    json folds = json::array();
    double sumDefault = 0, sumTuned = 0, sumTrain = 0, sumValidation = 0;
    int improved = 0;
    std::vector<std::vector<double>> foldValues;
    const auto lums = trainLuminaires();
    for (const auto& lum : lums) {
        const auto fold = only(train_, lum, false), held = only(train_, lum);
        Search s = searchOn(fold, fmt::format("fold {}: ", lum));
        const auto hd = evaluate(held, defaults), ht = evaluate(held, s.best);
        json f;
        f["held_out"] = lum;
        f["default"] = aggregate(hd);
        f["tuned"] = aggregate(ht);
        f["improved"] = f["tuned"].get<double>() < f["default"].get<double>();
        f["default_" + e_.metric] = metricMeans(hd);
        f["tuned_" + e_.metric] = metricMeans(ht);
        f["train_default"] = aggregate(evaluate(fold, defaults));
        f["train"] = aggregate(evaluate(fold, s.best));
        f["validation"] = aggregate(evaluate(validation_, s.best));
        f["tuned_spec"] = specWith(e_.method, names_, s.best, e_.sceneKeys.kind);
        f["params"] = paramsJson(s.best);
        f["evaluations"] = s.evals;
        f["near_bound"] = atBound(s.best);
        sumDefault += f["default"].get<double>();
        sumTuned += f["tuned"].get<double>();
        sumTrain += f["train"].get<double>();
        sumValidation += f["validation"].get<double>();
        improved += f["improved"].get<bool>();
        foldValues.push_back(s.best);
        if (!opt_.quiet)
            fmt::print(stderr,
                       "tune: fold {}: held out default {:.6g} tuned {:.6g}  train {:.6g}  validation {:.6g}  {}\n",
                       lum, f["default"].get<double>(), f["tuned"].get<double>(), f["train"].get<double>(),
                       f["validation"].get<double>(), f["params"].dump());
        folds.push_back(f);
    }
    const double n = double(lums.size());
    return {{"scheme", "leave-one-luminaire-out"},
            {"score", e_.objective + " " + e_.metric},
            {"folds", folds},
            {"held_out_default_mean", sumDefault / n},
            {"held_out_tuned_mean", sumTuned / n},
            {"train_mean", sumTrain / n},
            {"validation_mean", sumValidation / n},
            {"folds_improved", improved},
            {"folds_count", lums.size()},
            {"folds_improved_fraction", improved / n},
            {"param_spread", parameterSpread(dims_, foldValues)}};
}

// A tuned spec per training luminaire (on its own training scenes) against
// the defaults and the global tuned spec.
json Tuner::presets(const std::vector<double>& defaults, const std::vector<double>& global)
{
    json entries = json::object(), rows = json::array();
    for (const auto& lum : trainLuminaires()) {
        const auto own = only(train_, lum), val = only(validation_, lum);
        Search s = searchOn(own, fmt::format("preset {}: ", lum));
        const std::string spec = specWith(e_.method, names_, s.best, e_.sceneKeys.kind);
        entries[lum] = spec;
        json row = {{"luminaire", lum},
                    {"spec", spec},
                    {"params", paramsJson(s.best)},
                    {"evaluations", s.evals},
                    {"near_bound", atBound(s.best)},
                    {"train_default", aggregate(evaluate(own, defaults))},
                    {"train_global", aggregate(evaluate(own, global))},
                    {"train_preset", aggregate(evaluate(own, s.best))}};
        if (!val.empty()) {
            row["validation_default"] = aggregate(evaluate(val, defaults));
            row["validation_global"] = aggregate(evaluate(val, global));
            row["validation_preset"] = aggregate(evaluate(val, s.best));
        }
        if (!opt_.quiet)
            fmt::print(stderr, "tune: preset {}: train default {:.6g} global {:.6g} preset {:.6g}\n", lum,
                       row["train_default"].get<double>(), row["train_global"].get<double>(),
                       row["train_preset"].get<double>());
        rows.push_back(row);
    }
    return {{"file", "presets.json"},
            {"score", e_.objective + " " + e_.metric},
            {"entries", entries},
            {"luminaires", rows}};
}

json Tuner::run()
{
    auto t0 = std::chrono::steady_clock::now();
    std::vector<double> defaults;
    for (const auto& d : dims_) defaults.push_back(std::stod(base_.values.at(d.param.name)));

    json doc = header();
    doc["default"] = summary(defaults, "none", 0);
    if (!opt_.quiet)
        fmt::print(stderr, "tune: default  train {:.6g}  validation {:.6g} ({} of {})\n",
                   doc["default"]["train_objective"].get<double>(),
                   doc["default"]["validation_objective"].get<double>(), e_.objective, e_.metric);

    Search s = searchOn(train_, "");
    doc["tuned"] = summary(s.best, s.algo, s.evals);
    doc["trace"] = s.trace;
    doc["improved_validation"] =
        doc["tuned"]["validation_objective"].get<double>() < doc["default"]["validation_objective"].get<double>();
    if (e_.crossValidation) doc["cross_validation"] = crossValidation(defaults);
    if (e_.presets) doc["presets"] = presets(defaults, s.best);
    doc["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    doc["near_bound"] = json::array();
    for (const auto& b : doc["tuned"]["at_bound"]) {
        doc["near_bound"].push_back(
            {{"name", b["param"]}, {"value", b["value"]}, {"bound", b["bound"]}, {"limit", b["limit"]}});
        // Always said, --quiet or not: the result is suspect.
        fmt::print(stderr,
                   "tune: warning: {} = {:.6g} ended within 1 % of the search range from its {} bound {:.6g}: "
                   "the optimum may lie beyond it (the ranges: tune.json, \"search\")\n",
                   b["param"].get<std::string>(), b["value"].get<double>(), b["bound"].get<std::string>(),
                   b["limit"].get<double>());
    }
    if (!opt_.quiet)
        fmt::print(stderr, "tune: tuned {}  train {:.6g}  validation {:.6g} ({} of {}; {} evaluations, {:.1f} s)\n",
                   doc["tuned"]["params"].dump(), doc["tuned"]["train_objective"].get<double>(),
                   doc["tuned"]["validation_objective"].get<double>(), e_.objective, e_.metric, s.evals,
                   doc["seconds"].get<double>());
    return doc;
}

}  // namespace

std::string crossValidationTable(const json& doc)
{
    if (!doc.contains("cross_validation")) return "";
    const json& cv = doc["cross_validation"];
    std::string out = fmt::format("| held out | default ({0}) | tuned ({0}) | tuned / default |\n|---|---|---|---|\n",
                                  cv["score"].get<std::string>());
    for (const auto& f : cv["folds"]) {
        const double d = f["default"].get<double>(), t = f["tuned"].get<double>();
        out += fmt::format("| {} | {:.4g} | {:.4g} | {:.3g}{} |\n", f["held_out"].get<std::string>(), d, t,
                           d != 0 ? t / d : 0.0,
                           t < d        ? ""
                               : t == d ? " (equal)"
                                        : " (worse)");
    }
    out += fmt::format("| mean | {:.4g} | {:.4g} | improved in {} of {} folds |\n",
                       cv["held_out_default_mean"].get<double>(), cv["held_out_tuned_mean"].get<double>(),
                       cv["folds_improved"].get<int>(), cv["folds"].size());
    out +=
        "\n| parameter | default | min | max | mean | range swept (of the search range) |\n|---|---|---|---|---|---|\n";
    for (const auto& [name, p] : cv["param_spread"].items())
        out += fmt::format("| {} | {} | {:.4g} | {:.4g} | {:.4g} | {:.0f} % |\n", name, p["default"].get<std::string>(),
                           p["min"].get<double>(), p["max"].get<double>(), p["mean"].get<double>(),
                           100 * p["unit_range"].get<double>());
    return out;
}

json runTune(const TuneExperiment& e, const TuneOptions& opt)
{
    std::string why;
    if (e.metric == "flip" && !metrics::flipAvailable(&why))
        throw Error(fmt::format("{}: \"metric\": flip cannot be minimised here: {}", e.path, why));
    Tuner t(e, opt);
    json doc = t.run();
    fs::create_directories(opt.outDir);
    fs::path out = fs::path(opt.outDir) / "tune.json";
    if (doc.contains("presets"))
        util::writeFileAtomic((fs::path(opt.outDir) / "presets.json").string(),
                              doc["presets"]["entries"].dump(2) + "\n");
    util::writeFileAtomic(out.string(), doc.dump(2) + "\n");
    if (opt.plot) {
        fs::path script = fs::path(LB_SOURCE_DIR) / "plots" / "tune.py";
        fs::path png = fs::path(opt.outDir) / "tune.png";
        util::refuseLinksBelow(opt.outDir, "tune.png");  // the script's write would follow a link
        if (fs::exists("/usr/bin/python3") && fs::exists(script)) {
            if (util::runProcess({"/usr/bin/python3", script.string(), out.string(), png.string()}) != 0)
                fmt::print(stderr, "tune: warning: the convergence plot failed ({} {} {})\n", script.string(),
                           out.string(), png.string());
        }
    }
    return doc;
}

}  // namespace lb::tune
