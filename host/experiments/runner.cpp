#include "experiments/runner.h"

#include "experiments/results.h"
#include "methods/analytic.h"
#include "methods/render.h"
#include "metrics/flip.h"
#include "metrics/metrics.h"
#include "metrics/png.h"
#include "metrics/tonemap.h"
#include "photometry/text.h"
#include "util/digest.h"
#include "util/error.h"
#include "util/fileio.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <set>

namespace lb::experiments {

namespace fs = std::filesystem;
using nlohmann::json;

long solveN(std::vector<std::pair<long, double>> pts, double targetMs)
{
    std::sort(pts.begin(), pts.end());
    auto clampN = [](double n) {
        return static_cast<long>(std::clamp(std::isfinite(n) ? std::round(n) : 1.0, 1.0, double(1 << 20)));
    };
    if (pts.empty()) return 1;
    if (pts.size() == 1) return clampN(double(pts[0].first) * targetMs / pts[0].second);  // t proportional to N
    if (targetMs <= pts.front().second)
        return pts.front().first > 1 ? clampN(pts.front().first * targetMs / pts.front().second) : 1;
    // The first segment whose end reaches the target, else the last one (extrapolated).
    size_t i = 1;
    while (i + 1 < pts.size() && pts[i].second < targetMs) ++i;
    auto [n0, t0] = pts[i - 1];
    auto [n1, t1] = pts[i];
    if (!(t1 > t0)) return clampN(targetMs <= t1 ? double(n1) : double(n1) * targetMs / t1);  // flat by noise
    return clampN(double(n0) + (targetMs - t0) * double(n1 - n0) / (t1 - t0));
}

// t at n on the piecewise-linear curve through pts (sorted by N inside),
// extrapolated proportionally beyond its ends.
double interpolateMs(std::vector<std::pair<long, double>> pts, long n)
{
    std::sort(pts.begin(), pts.end());
    if (pts.empty()) return NAN;
    if (n <= pts.front().first) return pts.front().second * double(n) / double(pts.front().first);
    for (size_t i = 1; i < pts.size(); ++i)
        if (n <= pts[i].first) {
            auto [n0, t0] = pts[i - 1];
            auto [n1, t1] = pts[i];
            return t0 + (t1 - t0) * double(n - n0) / double(n1 - n0);
        }
    return pts.back().second * double(n) / double(pts.back().first);
}

std::string cellImageName(const std::string& role, const std::string& spec)
{
    std::string out = role == "equal_time" ? "mci_eq_" : "";
    for (char c : spec) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-') ? c : '_';
    return out;
}

namespace {

using Clock = std::chrono::steady_clock;

// The error metrics a record carries (an input: records of a runner that
// computed fewer are recomputed on resume, so that every record has them all).
const char* const kMetricSet = "nmse nrmse relmse ueb leb grad_nmse flip";

// One cell of a scene: a method (as written), an MCI-curve point, or the
// equal-time partner of a method.
struct Cell {
    std::string role;  // "method" | "mci_curve" | "equal_time"
    std::string spec;  // the SPEC rendered ("method", "mci_curve") or matched ("equal_time")
    methods::MethodSpec parsed;
};

std::vector<Cell> cellsOf(const Experiment& e)
{
    std::vector<Cell> cells;
    std::set<std::string> seen;  // canonical SPECs: "mc:n=8" and the curve's N = 8 are one cell
    auto add = [&](const std::string& role, const std::string& spec) {
        methods::MethodSpec p = methods::parseSpec(spec, e.kind());
        if (!seen.insert(p.canonical()).second) return;
        cells.push_back({role, spec, p});
    };
    for (const auto& m : e.methods) add("method", m);
    std::string mcBase = e.mc.find(':') == std::string::npos ? e.mc + ":" : e.mc + ",";
    for (long n : e.mciCurve) add("mci_curve", mcBase + "n=" + std::to_string(n));
    for (const auto& m : e.equalTime) cells.push_back({"equal_time", m, methods::parseSpec(m, e.kind())});
    return cells;
}

std::string hms(double s)
{
    if (!std::isfinite(s) || s < 0) return "?";
    long t = std::lround(s);
    return t >= 3600 ? fmt::format("{}:{:02d}:{:02d}", t / 3600, (t / 60) % 60, t % 60)
                     : fmt::format("{}:{:02d}", t / 60, t % 60);
}

// Digest of a luminaire file's bytes (of the name for built-in analytic
// luminaires, which have no file): a file edited under the same name is a
// different input.
std::string luminaireDigest(const std::string& path)
{
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return util::digestHex(path);
    return util::digestHex(util::readFile(path, "a luminaire file", photometry::kMaxFileBytes));
}

// The names of the inputs that differ between two records' `inputs`.
std::string changedInputs(const json& was, const json& now)
{
    if (!was.is_object() || was.empty()) return "no input digests (an older file)";
    std::set<std::string> names;
    for (auto it = now.begin(); it != now.end(); ++it)
        if (!was.contains(it.key()) || was[it.key()] != it.value()) names.insert(it.key());
    for (auto it = was.begin(); it != was.end(); ++it)
        if (!now.contains(it.key())) names.insert(it.key());
    return fmt::format("{}", fmt::join(names, ", "));
}

// The scene's part of a record.
results::Record baseRecord(const SceneId& sid, ocl::Runtime& rt)
{
    results::Record r;
    r.luminaire = fs::path(sid.luminaire).filename().string();
    r.height = sid.height;
    r.rotation = sid.rotation;
    r.res = sid.res;
    r.precision = sid.precision;
    r.device = rt.info().name;
    r.driver = rt.info().driver;
    r.extra["scene"] = sid.label();
    r.sceneKeys = SceneKindKeys::recordKeys(sid.scene());
    return r;
}

// "mc:n=N" or "mc:n=N,extra=F" (the equal-time MCI's sample count).
std::string mcLabel(const methods::MethodSpec& s)
{
    std::string label = "mc:n=" + std::to_string(s.integer("n"));
    if (s.has("extra") && s.num("extra") > 0) label += ",extra=" + s.values.at("extra");
    return label;
}

struct SceneRun {
    const Experiment& e;
    const SceneId& sid;
    ocl::Runtime& rt;
    const photometry::Table& table;
    const RunOptions& opt;
    const std::string& resultsPath;
    const json& context;
    Scene scene;
    methods::Precision prec;
    Image ref;
    std::string imageDir;

    results::Record base() const { return baseRecord(sid, rt); }

    methods::RenderResult render(const methods::MethodSpec& spec) const
    {
        methods::RenderOptions ro;
        ro.reps = e.reps;
        ro.timeRes = e.timeRes;
        return methods::render(rt, table, scene, spec, prec, ro);
    }

    results::Record record(const methods::MethodSpec& spec, const methods::RenderResult& rr, const Cell& cell,
                           const std::string& cellName) const
    {
        results::Record r = base();
        r.method = spec.name;
        r.params = spec.paramsJson();
        r.time_ms = {rr.timing.median_ms, rr.timing.min_ms, rr.timing.max_ms, rr.timing.reps, rr.timeRes};
        r.error = metrics::compare(ref, rr.image);
        r.error.flip = metrics::flip(ref, rr.image);  // null, with one warning per run, without flip-evaluator
        r.extra["spec"] = cell.role == "equal_time" ? mcLabel(spec) : cell.spec;
        r.extra["role"] = cell.role;
        r.extra["build_s"] = rr.buildSeconds;
        if (!rr.stats.empty()) r.extra["stats"] = rr.stats;
        if (!imageDir.empty()) saveImages(cellName, rr.image, r.error);
        return r;
    }

    // <cell>.exr and the PNG triple of `lumibench compare --png`, one k per scene.
    void saveImages(const std::string& name, const Image& img, const metrics::Metrics& m) const
    {
        std::string p = (fs::path(imageDir) / name).string();
        double k = tonemap::defaultK(ref);
        double over = std::isfinite(m.ueb) ? m.ueb : 0.0, under = std::isfinite(m.leb) ? -m.leb : 0.0;
        json j = m;
        j["k"] = k;
        util::writeFilesAtomic({{p + ".exr", encodeExr(img)},
                                {p + "_ref.png", encodePng(tonemap::tonemapPicture(ref, k))},
                                {p + "_test.png", encodePng(tonemap::tonemapPicture(img, k))},
                                {p + "_err.png", encodePng(tonemap::errorPicture(ref, img, over, under))},
                                {p + ".json", j.dump() + '\n'}});
    }
};

// The equal-time MCI partner of cell c, whose method took tM ms in its own
// cell (DESIGN section 6): MC's N aimed on the measured t(N) (pts: the
// scene's MC curve, else the experiment's equal_time_fit points timed here),
// then timed against the method in alternating rounds. The record's extra
// keys say how it was found (equal_time_candidates, _ratio, _ok, _bracketed).
results::Record equalTimePartner(const SceneRun& sr, const Cell& c, double tM, std::vector<std::pair<long, double>> pts)
{
    const Experiment& e = sr.e;
    ocl::Runtime& rt = sr.rt;
    const photometry::Table& table = sr.table;
    const std::string target = c.parsed.canonical();
    auto mcAt = [&](long n, double extra = 0) {
        std::string s = e.mc + (e.mc.find(':') == std::string::npos ? ":" : ",") + "n=" + std::to_string(n);
        if (extra > 0) s += fmt::format(",extra={:.3f}", extra);
        return methods::parseSpec(s, e.kind());
    };
    if (pts.size() < 2) {
        pts.clear();
        for (long n : e.equalTimeFit) {
            pts.emplace_back(n, sr.render(mcAt(n)).timing.median_ms);
        }
    }
    // N on the measured t(N), then it and its neighbour on the
    // method's side timed against the method in alternating
    // rounds (DESIGN 6: ratios within one run), the ratio the
    // median of the rounds' ratios. While the closest is off by
    // more than the tolerance and not bracketed by a measured
    // neighbour (three tries at most), aim again by the secant
    // through the paired ratios.
    Scene ts = sr.scene;
    if (e.timeRes > 0) ts.res = e.timeRes;
    methods::Prepared pm(rt, table, ts, c.parsed, sr.prec);
    std::map<long, std::unique_ptr<methods::Prepared>> prepared;  // MC by N, built once
    json candJson = json::array();
    long bestN = 0;
    double ratio = NAN;
    std::vector<ocl::Timing> bestT;  // (method, MC at bestN) of bestN's rounds
    std::map<long, double> measured;  // N -> median round ratio
    long next = solveN(pts, tM);  // first aim: the curve
    for (int attempt = 0; attempt < 3; ++attempt) {
        // the aimed N and its neighbour towards the target on the
        // curve; later tries: the aimed N and both neighbours
        long n1 = std::max(1L, next);
        std::vector<long> tries = {n1};
        if (attempt == 0)
            tries.push_back(interpolateMs(pts, n1) > tM ? n1 - 1 : n1 + 1);
        else
            tries.insert(tries.end(), {n1 - 1, n1 + 1});
        std::vector<long> cand;
        for (long n : tries)
            if (n >= 1 && !measured.count(n) && std::find(cand.begin(), cand.end(), n) == cand.end()) cand.push_back(n);
        if (cand.empty()) break;
        std::vector<std::function<cl::Event()>> launches = {[&] { return pm.launch(0, ts.res); }};
        for (long n : cand) {
            auto& p = prepared[n];
            if (!p) p = std::make_unique<methods::Prepared>(rt, table, ts, mcAt(n), sr.prec);
            methods::Prepared* pp = p.get();
            launches.push_back([pp, &ts] { return pp->launch(0, ts.res); });
        }
        std::vector<ocl::Timing> tt = rt.timeInterleaved(launches, std::max(1, e.reps), 1);
        for (size_t k = 0; k < cand.size(); ++k) {
            std::vector<double> rr;
            for (size_t ri = 0; ri < tt[0].samples_ms.size(); ++ri)
                rr.push_back(tt[k + 1].samples_ms[ri] / tt[0].samples_ms[ri]);
            double q = ocl::summarize(rr).median_ms;  // median of the rounds' ratios
            measured[cand[k]] = q;
            candJson.push_back({{"n", cand[k]}, {"ratio", q}, {"ms", tt[k + 1].median_ms}});
            if (bestN == 0 || std::fabs(std::log(q)) < std::fabs(std::log(ratio))) {
                bestN = cand[k];
                ratio = q;
                bestT = {tt[0], tt[k + 1]};
            }
        }
        if (std::abs(ratio - 1) <= e.equalTimeTolerance) break;
        // aim again on the paired ratios themselves: the secant
        // through the measured points nearest below and above 1
        // (or the two nearest to 1 when all lie on one side)
        std::vector<std::pair<long, double>> m(measured.begin(), measured.end());
        std::sort(m.begin(), m.end(),
                  [](auto x, auto y) { return std::fabs(std::log(x.second)) < std::fabs(std::log(y.second)); });
        auto lo = std::find_if(m.begin(), m.end(), [](auto x) { return x.second < 1; });
        auto hi = std::find_if(m.begin(), m.end(), [](auto x) { return x.second >= 1; });
        std::pair<long, double> p0 = m[0], p1 = m.size() > 1 ? m[1] : m[0];
        if (lo != m.end() && hi != m.end()) p0 = *lo, p1 = *hi;
        if (lo != m.end() && hi != m.end() && std::abs(p0.first - p1.first) == 1) break;  // bracketed
        double slope = p1.first != p0.first ? (p1.second - p0.second) / double(p1.first - p0.first) : 0;
        next = slope > 0 ? std::lround(double(p0.first) + (1 - p0.second) / slope)
                         : std::lround(double(p0.first) / p0.second);  // t proportional to N
        next = std::clamp(next, 1L, 1L << 20);
    }
    // Bracketed: the neighbour of N_eq on the other side of 1 was
    // measured too (or N_eq = 1 is too slow already), so no integer
    // N matches the method more closely on this device.
    bool bracketed = ratio >= 1 ? (bestN == 1 || (measured.count(bestN - 1) && measured[bestN - 1] < 1))
                                : (measured.count(bestN + 1) && measured[bestN + 1] >= 1);
    // No integer N within the tolerance, but N and N + 1 bracket the
    // method: MC's fractional sample count (mc's `extra`, kernels/mc.cl: that
    // share of the tiles takes N + 1 points; time is linear in it) closes the
    // step. Aimed by linear interpolation between the paired ratios of N and
    // N + 1, then by the secant through the nearest measured pair; two tries.
    long n1 = bestN;
    double extra = 0;
    long lo = ratio >= 1 ? bestN - 1 : bestN;
    if (std::abs(ratio - 1) > e.equalTimeTolerance && bracketed && lo >= 1 && measured.count(lo) &&
        measured.count(lo + 1) && mcAt(lo).has("extra")) {
        double f0 = 0, q0 = measured[lo], f1 = 1, q1 = measured[lo + 1];
        for (int attempt = 0; attempt < 2 && q1 > q0; ++attempt) {
            double f = std::round(1000 * std::clamp(f0 + (1 - q0) * (f1 - f0) / (q1 - q0), 0.001, 0.999)) / 1000;
            methods::Prepared pf(rt, table, ts, mcAt(lo, f), sr.prec);
            std::vector<ocl::Timing> tt = rt.timeInterleaved(
                {[&] { return pm.launch(0, ts.res); }, [&] { return pf.launch(0, ts.res); }}, std::max(1, e.reps), 1);
            std::vector<double> rr;
            for (size_t ri = 0; ri < tt[0].samples_ms.size(); ++ri)
                rr.push_back(tt[1].samples_ms[ri] / tt[0].samples_ms[ri]);
            double q = ocl::summarize(rr).median_ms;
            candJson.push_back({{"n", lo}, {"extra", f}, {"ratio", q}, {"ms", tt[1].median_ms}});
            if (std::fabs(std::log(q)) < std::fabs(std::log(ratio))) {
                n1 = lo;
                extra = f;
                ratio = q;
                bestT = tt;
            }
            if (std::abs(q - 1) <= e.equalTimeTolerance) break;
            (q < 1 ? f0 : f1) = f;
            (q < 1 ? q0 : q1) = q;
        }
    }
    auto s1 = mcAt(n1, extra);
    // the error image at the experiment's res (its time is the paired one above)
    methods::RenderOptions imageOnly;
    imageOnly.reps = 1;
    auto r1 = methods::render(rt, table, sr.scene, s1, sr.prec, imageOnly);
    r1.timing = bestT[1];
    r1.timeRes = ts.res;
    json fitJson = json::array();
    for (auto [n, t] : pts) fitJson.push_back({n, t});
    results::Record r = sr.record(s1, r1, c, cellImageName(c.role, c.spec));
    r.equal_time_to = target;
    r.n = n1;
    r.extra["equal_time_n"] = double(n1) + extra;  // N + extra: MC's mean sample count
    r.extra["equal_time_candidates"] = candJson;
    r.extra["equal_time_cell_ms"] = tM;  // the method's own cell, timed apart
    r.extra["equal_time_label"] = c.spec;
    r.extra["equal_time_target_ms"] = bestT[0].median_ms;  // the method, in the paired rounds
    r.extra["equal_time_ratio"] = ratio;
    r.extra["equal_time_ok"] = std::abs(ratio - 1) <= e.equalTimeTolerance;
    r.extra["equal_time_bracketed"] = bracketed;
    r.extra["equal_time_fit"] = fitJson;
    return r;
}

}  // namespace

RunSummary run(const Experiment& e, const RunOptions& opt)
{
    RunSummary sum;
    auto t0 = Clock::now();
    fs::create_directories(opt.outDir);
    const std::string resultsPath = (fs::path(opt.outDir) / "results.json").string();

    ocl::Runtime rt(opt.device);
    json context = results::makeContext(rt.info().name, rt.info().driver,
                                        {{"platform", rt.info().platform},
                                         {"experiment", e.name},
                                         {"experiment_file", e.path},
                                         {"experiment_spec", e.raw},
                                         {"luminaire_dir", e.luminaireDir},
                                         {"res", e.res},
                                         {"reps", e.reps},
                                         {"time_res", e.timeRes},
                                         {"equal_time_tolerance", e.equalTimeTolerance},
                                         {"shard", fmt::format("{}/{}", opt.shardK, opt.shardN)}});

    // Resume: the cells already written, by cell key (an equal-time partner,
    // whose N was chosen at run time, by scene, device and the SPEC it
    // matches), with the inputs they were computed from. A cell is done
    // only when its inputs are this run's; otherwise it is recomputed and
    // its record replaced.
    util::removeStaleTemporaries(opt.outDir);  // left by a killed run
    std::map<std::string, json> doneInputs;  // key -> inputs
    std::map<std::string, double> doneTimes;  // key -> median ms (equal-time targets)
    if (results::exists(resultsPath)) {
        for (const auto& r : results::load(resultsPath).records) {
            doneInputs[r.key()] = r.inputs;
            doneTimes[r.key()] = r.time_ms.median;
        }
    }

    // What every record depends on besides its cell key (results.h).
    std::map<std::string, std::string> kernelDigests;  // kernel file -> digest of it and its headers
    auto kernelDigest = [&](const std::string& method) {
        const std::string& file = methods::family(method, e.kind()).file;
        auto it = kernelDigests.find(file);
        if (it == kernelDigests.end()) it = kernelDigests.emplace(file, ocl::kernelSourceDigest(file)).first;
        return it->second;
    };
    std::map<std::string, std::string> lumDigests;  // luminaire path -> digest of its bytes

    std::vector<Cell> cells = cellsOf(e);
    std::vector<SceneId> mine;
    for (const auto& s : scenes(e))
        if (inShard(s, opt.shardK, opt.shardN)) mine.push_back(s);
    sum.scenes = mine.size();
    sum.cells = mine.size() * cells.size();

    std::map<std::string, photometry::Table> tables;
    const methods::MethodSpec refSpec = methods::parseSpec(e.reference, e.kind());
    size_t cellsSeen = 0;
    double computeSeconds = 0;

    for (size_t si = 0; si < mine.size(); ++si) {
        const SceneId& sid = mine[si];

        // Keys and inputs of this scene's cells, to skip the scene without a reference render.
        auto keyOf = [&](const Cell& c) {
            results::Record r = baseRecord(sid, rt);
            if (c.role == "equal_time") {
                r.method = "mc";
                r.equal_time_to = c.parsed.canonical();
            } else {
                r.method = c.parsed.name;
                r.params = c.parsed.paramsJson();
            }
            return r.key();
        };
        if (!lumDigests.count(sid.luminaire)) lumDigests[sid.luminaire] = luminaireDigest(sid.luminaire);
        auto inputsOf = [&](const Cell& c) {
            json in = {{"size", {sid.width, sid.length}},
                       {"extent", sid.extent},
                       {"luminaire_digest", lumDigests[sid.luminaire]},
                       {"reference", refSpec.canonical()},
                       {"reference_kernel", kernelDigest(refSpec.name)},
                       {"reps", e.reps},
                       {"time_res", e.timeRes},
                       {"metrics", kMetricSet}};
            if (c.role == "equal_time") {
                in["kernel"] = kernelDigest("mc");
                in["target_kernel"] = kernelDigest(c.parsed.name);
                in["mc"] = methods::parseSpec(e.mc, e.kind()).canonical();
                in["equal_time_tolerance"] = e.equalTimeTolerance;
            } else {
                in["kernel"] = kernelDigest(c.parsed.name);
            }
            return in;
        };
        std::vector<bool> todo(cells.size());
        std::vector<json> cellInputs(cells.size());
        std::set<std::string> changed;  // why done cells are recomputed
        size_t ntodo = 0, nstale = 0;
        for (size_t i = 0; i < cells.size(); ++i) {
            cellInputs[i] = inputsOf(cells[i]);
            auto it = doneInputs.find(keyOf(cells[i]));
            todo[i] = it == doneInputs.end() || it->second != cellInputs[i];
            if (it != doneInputs.end() && todo[i]) {
                ++nstale;
                changed.insert(changedInputs(it->second, cellInputs[i]));
            }
            ntodo += todo[i];
        }
        sum.skipped += cells.size() - ntodo;
        sum.stale += nstale;
        cellsSeen += cells.size() - ntodo;
        if (ntodo == 0) continue;

        if (!tables.count(sid.luminaire)) tables.emplace(sid.luminaire, methods::loadLuminaire(sid.luminaire));
        const photometry::Table& table = tables.at(sid.luminaire);
        SceneRun sr{e,  sid, rt, table, opt, resultsPath, context, sid.scene(), methods::parsePrecision(sid.precision),
                    {}, {}};
        if (e.saveImages) {
            sr.imageDir = (fs::path(opt.outDir) / "images" / sid.label()).string();
            fs::create_directories(sr.imageDir);
        }
        {
            methods::RenderOptions ro;
            ro.reps = 1;
            sr.ref = methods::render(rt, table, sr.scene, refSpec, sr.prec, ro).image;
            if (!sr.imageDir.empty()) writeExr((fs::path(sr.imageDir) / "reference.exr").string(), sr.ref);
        }

        // Medians of this scene's cells (this run or an earlier one), by canonical SPEC.
        std::map<std::string, double> times;
        std::vector<std::pair<long, double>> curve;
        auto remember = [&](const methods::MethodSpec& s, double ms) {
            times[s.canonical()] = ms;
            if (s.name == "mc" && s.given.count("n")) {
                // Only curve points of the experiment's MC pattern enter the fit.
                methods::MethodSpec base = methods::parseSpec(e.mc, e.kind());
                json pa = s.paramsJson(), pb = base.paramsJson();
                pa.erase("n");
                pb.erase("n");
                if (pa == pb) curve.emplace_back(s.integer("n"), ms);
            }
        };
        for (size_t i = 0; i < cells.size(); ++i)
            if (cells[i].role != "equal_time" && !todo[i]) remember(cells[i].parsed, doneTimes[keyOf(cells[i])]);

        for (size_t i = 0; i < cells.size(); ++i) {
            if (!todo[i]) continue;
            const Cell& c = cells[i];
            auto tc = Clock::now();
            if (c.role != "equal_time") {
                auto rr = sr.render(c.parsed);
                remember(c.parsed, rr.timing.median_ms);
                results::Record r = sr.record(c.parsed, rr, c, cellImageName(c.role, c.spec));
                r.inputs = cellInputs[i];
                results::appendRecord(resultsPath, context, r);
            } else {
                // Equal-time MCI partner of c.spec (DESIGN section 6).
                const std::string target = c.parsed.canonical();
                if (!times.count(target))
                    throw Error(fmt::format("equal time: no time of '{}' at scene {}", c.spec, sid.label()));
                results::Record r = equalTimePartner(sr, c, times[target], curve);
                r.inputs = cellInputs[i];
                if (!r.extra["equal_time_ok"].get<bool>()) {
                    ++sum.equalTimeOff;
                    std::cerr << fmt::format("lumibench: warning: {}: MCI at equal time to {}: N = {}, {:.4g} ms vs "
                                             "{:.4g} ms (ratio {:.3f}, outside +-{:.0f}%)\n",
                                             sid.label(), c.spec, *r.n, r.time_ms.median,
                                             r.extra["equal_time_target_ms"].get<double>(),
                                             r.extra["equal_time_ratio"].get<double>(), 100 * e.equalTimeTolerance);
                }
                results::appendRecord(resultsPath, context, r);
            }
            ++sum.computed;
            ++cellsSeen;
            computeSeconds += std::chrono::duration<double>(Clock::now() - tc).count();
        }
        if (opt.progress) {
            double elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
            size_t left = sum.cells - cellsSeen;
            double eta = sum.computed ? elapsed / double(sum.computed) * double(left) : NAN;
            std::cerr << fmt::format("[{}] cells {}/{} ({:.0f}%), scene {}/{} {}, elapsed {}, ETA {}{}\n", e.name,
                                     cellsSeen, sum.cells, 100.0 * cellsSeen / std::max<size_t>(1, sum.cells), si + 1,
                                     mine.size(), sid.label(), hms(elapsed), hms(eta),
                                     nstale ? fmt::format("; recomputed {} cells whose inputs changed ({})", nstale,
                                                          fmt::format("{}", fmt::join(changed, "; ")))
                                            : std::string());
        }
    }
    sum.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    results::compact(resultsPath, context);  // the journal folded in: results.json holds every record
    results::saveCsv(resultsPath, results::load(resultsPath));  // DIR/results.csv, the same records as a table
    return sum;
}

}  // namespace lb::experiments
