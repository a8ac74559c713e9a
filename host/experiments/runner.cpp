#include "experiments/runner.h"

#include "equaltime/equaltime.h"
#include "experiments/results.h"
#include "methods/analytic.h"
#include "methods/mc_denoise.h"
#include "methods/render.h"
#include "metrics/flip.h"
#include "metrics/metrics.h"
#include "metrics/png.h"
#include "metrics/tonemap.h"
#include "photometry/names.h"
#include "photometry/text.h"
#include "experiments/run_lock.h"
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
#include <optional>
#include <set>

namespace lb::experiments {

namespace fs = std::filesystem;
using nlohmann::json;

std::string cellImageName(const std::string& role, const std::string& spec, const std::string& baseline)
{
    auto safe = [](const std::string& s) {
        std::string out;
        for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-') ? c : '_';
        return out;
    };
    // a long SPEC (a preset's path) still names a file
    if (role != "equal_time") return util::shortName(safe(spec));
    return util::shortName("mci_eq_" + safe(spec) +
                           (baseline.empty() || baseline == "MCI" ? "" : "_vs_" + safe(baseline)));
}

namespace {

using Clock = std::chrono::steady_clock;

// The error metrics a record carries (an input: records of a runner that
// computed fewer are recomputed on resume, so that every record has them all).
const char* const kMetricSet = "nmse nrmse relmse ueb leb grad_nmse flip";
// The smallest image side that is pictured and given a FLIP (whyNoPictures).
constexpr int kMinPicturedRes = 2;

// One cell of a scene: a method (as written), an MCI-curve point, or the
// equal-time partner of a method.
struct Cell {
    std::string role;  // "method" | "mci_curve" | "equal_time"
    std::string spec;  // the SPEC rendered ("method", "mci_curve") or matched ("equal_time")
    methods::MethodSpec parsed;
    const Baseline* baseline = nullptr;  // "mci_curve" and "equal_time": whose
};

results::BaselineRef refOf(const Baseline& b) { return {b.label, results::baselineSpec(b.canonical)}; }

std::vector<Cell> cellsOf(const Experiment& e)
{
    std::vector<Cell> cells;
    std::set<std::string> seen;  // canonical SPECs: "mc:n=8" and the curve's N = 8 are one cell
    auto add = [&](const std::string& role, const std::string& spec, const Baseline* b) {
        methods::MethodSpec p = methods::parseSpec(spec, e.kind());
        if (!seen.insert(p.canonical()).second) return;
        cells.push_back({role, spec, p, b});
    };
    for (const auto& m : e.methods) add("method", m, nullptr);
    for (const auto& b : e.baselines)
        for (long n : e.mciCurve) add("mci_curve", b.at(n), &b);
    for (const auto& b : e.baselines)
        for (const auto& m : e.equalTime) cells.push_back({"equal_time", m, methods::parseSpec(m, e.kind()), &b});
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
    r.luminaire = sid.luminaireName;
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
    bool pictured = true;  // false: no pictures, no FLIP for this scene (canBePictured)

    // The scene's part of a record, with the name the luminaire file gives it.
    results::Record base() const
    {
        results::Record r = baseRecord(sid, rt);
        r.extra["luminaire_name"] = photometry::displayName(sid.luminaire);
        return r;
    }

    methods::RenderResult render(const methods::MethodSpec& spec) const
    {
        methods::RenderOptions ro;
        ro.reps = e.protocol.reps;
        ro.timeRes = e.protocol.timeRes;
        return methods::render(rt, table, scene, spec, prec, ro);
    }

    results::Record record(const methods::MethodSpec& spec, const methods::RenderResult& rr, const Cell& cell,
                           const std::string& cellName) const
    {
        results::Record r = base();
        r.method = spec.name;
        r.params = spec.paramsJson();
        r.time_ms = {rr.timing.median_ms, rr.timing.min_ms, rr.timing.max_ms, rr.timing.reps, rr.timeRes, rr.timing.cv};
        r.error = metrics::compare(ref, rr.image);
        // null, with one warning per run, without flip-evaluator
        if (pictured) r.error.flip = metrics::flip(ref, rr.image);
        if (seeded(spec)) {
            std::vector<metrics::Metrics> draws = {r.error};
            for (int k = 1; k < e.seeds; ++k) draws.push_back(drawError(spec, k));
            metrics::SeedSummary s = metrics::overSeeds(draws);
            r.error = s.mean;
            r.seeds = s.seeds;
            r.ci95 = s.ci95;
        }
        // a partner: its baseline's SPEC at N as written ("mc:domain=solid,sequence=sobol,n=4")
        r.extra["spec"] = cell.role == "equal_time"
            ? cell.baseline->at(spec.integer("n"), spec.has("extra") ? spec.num("extra") : 0)
            : cell.spec;
        if (cell.baseline) r.baseline = refOf(*cell.baseline);
        r.extra["role"] = cell.role;
        r.extra["build_s"] = rr.buildSeconds;
        if (!rr.stats.empty()) r.extra["stats"] = rr.stats;
        if (!imageDir.empty()) saveImages(cellName, rr.image, r.error);
        return r;
    }

    // Whether the method's output depends on a seed (its family has one) and
    // the experiment asks for more than one draw.
    bool seeded(const methods::MethodSpec& spec) const { return e.seeds > 1 && spec.has("seed"); }

    // The error of draw k: the image of `spec` at seed s + k (s its own,
    // wrapped below 2^31, the smallest of the families' bounds), untimed.
    metrics::Metrics drawError(const methods::MethodSpec& spec, int k) const
    {
        const long seed = (spec.integer("seed") + k) % 2147483648L;
        methods::RenderOptions imageOnly;
        imageOnly.reps = 1;
        Image img = methods::render(rt, table, scene, spec.with("seed", std::to_string(seed)), prec, imageOnly).image;
        metrics::Metrics m = metrics::compare(ref, img);
        if (pictured) m.flip = metrics::flip(ref, img);
        return m;
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

// Why a reference cannot be pictured ("" when it can): a black one (the
// tone-mapping scale is 1/mean, and FLIP's exposure range comes from it) or
// one too small for FLIP's filters.
std::string whyNoPictures(const Image& ref)
{
    if (ref.width < kMinPicturedRes || ref.height < kMinPicturedRes)
        return fmt::format("the image is {}x{} pixels, below the {}x{} that FLIP and the pictures need", ref.width,
                           ref.height, kMinPicturedRes, kMinPicturedRes);
    double sum = 0;
    for (double v : ref.px) sum += v;
    const double mean = sum / double(ref.px.size());
    if (!(mean > 0) || !std::isfinite(mean)) return fmt::format("the reference's mean is {} lx (black)", mean);
    return "";
}

// A baseline's SPEC at N samples (N + extra: mc's fractional count).
methods::MethodSpec mcAt(const Experiment& e, const Baseline& b, long n, double extra = 0)
{
    return methods::parseSpec(b.at(n, extra), e.kind());
}

// The equal-time MCI partner of cell c, whose method took tM ms in its own
// cell: findPartner from the measured t(N) (pts: the scene's MC curve, else
// the protocol's fit points timed here), every kernel at the experiment's
// time_res; its error image is one more, untimed render at the experiment's res.
results::Record equalTimePartner(const SceneRun& sr, const Cell& c, double tM, equaltime::Curve pts)
{
    const Experiment& e = sr.e;
    const Baseline& b = *c.baseline;
    Scene ts = sr.scene;  // the scene at the experiment's time_res
    if (e.protocol.timeRes > 0) ts.res = e.protocol.timeRes;
    const equaltime::Result q = findPartner(
        e, b, equaltime::preparedFrames(sr.rt, sr.table, ts, sr.prec),
        [&](const methods::MethodSpec& s) { return sr.render(s).timing.median_ms; }, c.parsed, pts, tM);
    auto s1 = mcAt(e, b, q.n, q.extra);
    if (q.scale < 1) s1 = s1.with("scale", fmt::format("{:.3f}", q.scale));
    methods::RenderOptions imageOnly;
    imageOnly.reps = 1;
    auto r1 = methods::render(sr.rt, sr.table, sr.scene, s1, sr.prec, imageOnly);
    r1.timing = q.partner;
    r1.timeRes = ts.res;
    results::Record r = sr.record(s1, r1, c, cellImageName(c.role, c.spec, b.label));
    r.equal_time_to = c.parsed.canonical();
    r.n = q.n;
    results::EqualTime et;
    et.label = c.spec;
    // N + extra: MC's mean sample count; below N = 1 per image pixel, as rendered at the time_res
    const double px = double(methods::mcRenderRes(q.scale, ts.res)) / ts.res;
    et.n = (double(q.n) + q.extra) * (q.scale < 1 ? px * px : 1.0);
    et.scale = q.scale;
    et.method_ms = q.method.median_ms;  // the method and MC in the same paired rounds
    et.partner_ms = q.partner.median_ms;
    et.method_cv = q.method.cv;
    et.partner_cv = q.partner.cv;
    et.ratio = q.ratio;
    et.cell_ms = tM;  // the method's own cell, timed apart
    et.tolerance = e.protocol.tolerance;
    et.ok = q.ok;
    et.bracketed = q.bracketed;
    et.candidates = q.candidates;
    et.fit = json::array();
    for (auto [n, t] : pts) et.fit.push_back({n, t});
    r.equalTime = et;
    return r;
}

// The cells a resumed run finds in results.json, by cell key (an equal-time
// partner, whose N was chosen at run time, by scene, device and the SPEC it
// matches): the inputs they were computed from and their median times.
struct DoneCells {
    std::map<std::string, json> inputs;
    std::map<std::string, double> times;  // median ms (equal-time targets)

    static DoneCells load(const std::string& resultsPath)
    {
        DoneCells d;
        if (!results::exists(resultsPath)) return d;
        for (const auto& r : results::load(resultsPath).records) {
            d.inputs[r.key()] = r.inputs;
            d.times[r.key()] = r.time_ms.median;
        }
        return d;
    }
};

// What every record depends on besides its cell key (results.h, runner.h):
// the digests of the kernels and luminaires, each computed once per run.
class CellInputs {
public:
    CellInputs(const Experiment& e, const methods::MethodSpec& refSpec) : e_(e), refSpec_(refSpec) {}

    json of(const SceneId& sid, const Cell& c)
    {
        json in = {{"size", {sid.width, sid.length}},
                   {"extent", sid.extent},
                   {"luminaire_digest", luminaire(sid.luminaire)},
                   {"reference", refSpec_.canonical()},
                   {"reference_kernel", kernel(refSpec_)},
                   {"reps", e_.protocol.reps},
                   {"time_res", e_.protocol.timeRes},
                   {"metrics", kMetricSet}};
        if (c.role == "equal_time") {
            in["kernel"] = kernel(mcAt(e_, *c.baseline, 1));
            in["target_kernel"] = kernel(c.parsed);
            in["mc"] = c.baseline->canonical;
            in["equal_time_tolerance"] = e_.protocol.tolerance;
            in["equal_time_rounds"] = e_.protocol.rounds;  // the pairing's rounds decide its N
            in["equal_time_fit"] = e_.protocol.fit;
            if (e_.protocol.mode != equaltime::Mode::Search) in["equal_time_mode"] = modeName(e_.protocol.mode);
            if (e_.protocol.subpixel) in["equal_time_subpixel"] = true;  // may pair below N = 1
            in["mci_curve"] = e_.mciCurve;  // the measured t(N) the search starts from
        } else {
            in["kernel"] = kernel(c.parsed);
        }
        // The draws over seeds (Experiment::seeds) of a seed-dependent cell:
        // MC's for a partner. Absent at one draw, as before the key existed.
        const bool seeded = c.role == "equal_time" ? mcAt(e_, *c.baseline, 1).has("seed") : c.parsed.has("seed");
        if (seeded && e_.seeds > 1) in["seeds"] = e_.seeds;
        // A presets file is an input too: the SPEC its entry for this
        // luminaire resolves to (an edited entry is a different input; the
        // other luminaires' entries are not this cell's).
        if (c.parsed.has("preset") && c.parsed.str("preset") != "none")
            in["preset_spec"] = methods::resolvePreset(c.parsed, sid.luminaire).canonical();
        return in;
    }

private:
    const std::string& kernel(const methods::MethodSpec& method)
    {
        const std::string& file = method.family().file;
        auto it = kernels_.find(file);
        if (it == kernels_.end()) it = kernels_.emplace(file, ocl::kernelSourceDigest(file)).first;
        return it->second;
    }
    const std::string& luminaire(const std::string& path)
    {
        auto it = luminaires_.find(path);
        if (it == luminaires_.end()) it = luminaires_.emplace(path, luminaireDigest(path)).first;
        return it->second;
    }

    const Experiment& e_;
    const methods::MethodSpec& refSpec_;
    std::map<std::string, std::string> kernels_;  // kernel file -> digest of it and its headers
    std::map<std::string, std::string> luminaires_;  // luminaire path -> digest of its bytes
};

// The key of a cell's record (results.h Record::key).
std::string cellKey(const SceneId& sid, ocl::Runtime& rt, const Cell& c)
{
    results::Record r = baseRecord(sid, rt);
    if (c.role == "equal_time") {
        r.method = "mc";
        r.equal_time_to = c.parsed.canonical();
        r.baseline = refOf(*c.baseline);
    } else {
        r.method = c.parsed.name;
        r.params = c.parsed.paramsJson();
    }
    return r.key();
}

// Which of a scene's cells are to be computed: those not done, and those
// done with other inputs (stale; `changed` names the inputs that differ).
struct ScenePlan {
    std::vector<bool> todo;
    std::vector<json> inputs;
    std::set<std::string> changed;
    size_t ntodo = 0, nstale = 0;
};

ScenePlan planScene(const SceneId& sid, const std::vector<Cell>& cells, const DoneCells& done, CellInputs& inputs,
                    ocl::Runtime& rt)
{
    ScenePlan p;
    p.todo.resize(cells.size());
    p.inputs.resize(cells.size());
    for (size_t i = 0; i < cells.size(); ++i) {
        p.inputs[i] = inputs.of(sid, cells[i]);
        auto it = done.inputs.find(cellKey(sid, rt, cells[i]));
        p.todo[i] = it == done.inputs.end() || it->second != p.inputs[i];
        if (it != done.inputs.end() && p.todo[i]) {
            ++p.nstale;
            p.changed.insert(changedInputs(it->second, p.inputs[i]));
        }
        p.ntodo += p.todo[i];
    }
    return p;
}

// The medians of a scene's cells (this run or an earlier one), by canonical
// SPEC, and the points of each baseline among them: the t(N) curve its
// equal-time partners aim on.
struct SceneTimes {
    const Experiment& e;
    std::map<std::string, double> times;
    std::map<const Baseline*, equaltime::Curve> curves;

    void remember(const methods::MethodSpec& s, double ms)
    {
        times[s.canonical()] = ms;
        if (s.name != "mc" || !s.given.count("n") || (s.has("extra") && s.num("extra") > 0)) return;
        json pa = s.paramsJson();
        pa.erase("n");
        pa.erase("extra");
        for (const auto& b : e.baselines) {  // a baseline's points only enter its own fit
            json pb = mcAt(e, b, 1).paramsJson();
            pb.erase("n");
            pb.erase("extra");
            if (pa == pb) curves[&b].emplace_back(s.integer("n"), ms);
        }
    }
};

// The run of an experiment's shard, scene by scene (runner.h).
class Runner {
public:
    Runner(const Experiment& e, const RunOptions& opt)
        : e_(e), opt_(opt), resultsPath_(createdResultsPath(opt.outDir)), rt_(opt.device),
          refSpec_(methods::parseSpec(e.reference, e.kind())), inputs_(e, refSpec_)
    {
    }

    RunSummary run()
    {
        context_ = runContext();
        // one experiment at a time in this folder (its shards together)
        const RunLock lock(
            resultsPath_,
            util::digestHex(
                json{e_.name, e_.raw, e_.res, e_.protocol.reps, e_.protocol.timeRes, e_.luminaireDir}.dump()),
            e_.name, e_.path);
        util::removeStaleTemporaries(opt_.outDir);  // left by a killed run
        cells_ = cellsOf(e_);
        dropCellsNotInTheExperiment();
        relabelScenes();
        done_ = DoneCells::load(resultsPath_);
        for (const auto& s : scenes(e_))
            if (inShard(s, opt_.shardK, opt_.shardN)) mine_.push_back(s);
        sum_.scenes = mine_.size();
        sum_.cells = mine_.size() * cells_.size();
        for (size_t si = 0; si < mine_.size(); ++si) runScene(si);
        sum_.seconds = std::chrono::duration<double>(Clock::now() - t0_).count();
        results::compact(resultsPath_, context_);  // the journal folded in: results.json holds every record
        results::saveCsv(resultsPath_, results::load(resultsPath_));  // DIR/results.csv, the same records as a table
        return sum_;
    }

private:
    // DIR/results.json, DIR created first (before the device is opened).
    static std::string createdResultsPath(const std::string& outDir)
    {
        fs::create_directories(outDir);
        return (fs::path(outDir) / "results.json").string();
    }

    json runContext()
    {
        return results::makeContext(rt_.info().name, rt_.info().driver,
                                    {{"platform", rt_.info().platform},
                                     {"experiment", e_.name},
                                     {"experiment_file", e_.path},
                                     {"experiment_spec", e_.raw},
                                     {"luminaire_dir", e_.luminaireDir},
                                     {"res", e_.res},
                                     {"reps", e_.protocol.reps},
                                     {"time_res", e_.protocol.timeRes},
                                     {"equal_time_tolerance", e_.protocol.tolerance},
                                     {"baselines", baselinesJson()},
                                     {"shard", fmt::format("{}/{}", opt_.shardK, opt_.shardN)}});
    }

    json baselinesJson() const
    {
        json out = json::array();
        for (const auto& b : e_.baselines)
            out.push_back({{"label", b.label}, {"spec", results::baselineSpec(b.canonical)}});
        return out;
    }

    // Every shard's cells count: shards may share one directory.
    void dropCellsNotInTheExperiment()
    {
        std::set<std::string> wanted;
        for (const auto& s : scenes(e_))
            for (const auto& c : cells_) wanted.insert(cellKey(s, rt_, c));
        const std::string side = (fs::path(opt_.outDir) / "results.dropped.json").string();
        sum_.dropped = results::retain(
            resultsPath_, [&](const results::Record& r) { return wanted.count(r.key()) > 0; }, side);
        if (sum_.dropped && opt_.progress)
            std::cerr << fmt::format("[{}] moved {} records of cells no longer in the experiment to {}\n", e_.name,
                                     sum_.dropped, side);
    }

    // Records whose scene label differs from the one the scene has now (a
    // file of a version that wrote the rotation as given: 3*pi/4 and 3pi/4
    // two labels) get today's label, and their pictures move with them.
    void relabelScenes()
    {
        std::map<std::string, std::string> labelOf;  // cell key -> its scene's label
        for (const auto& s : scenes(e_))
            for (const auto& c : cells_) labelOf[cellKey(s, rt_, c)] = s.label();
        std::map<std::string, std::string> renamed;  // old label -> new
        const size_t n = results::update(resultsPath_, [&](results::Record& r) {
            auto it = labelOf.find(r.key());
            const std::string old = r.extra.is_object() ? r.extra.value("scene", std::string()) : std::string();
            if (it == labelOf.end() || old.empty() || old == it->second) return false;
            renamed[old] = it->second;
            r.extra["scene"] = it->second;
            return true;
        });
        for (const auto& [from, to] : renamed) {
            const fs::path src = fs::path(opt_.outDir) / "images" / from, dst = fs::path(opt_.outDir) / "images" / to;
            if (!fs::is_directory(src)) continue;
            util::createDirsBelow(opt_.outDir, fs::path("images") / to);
            for (const auto& f : fs::directory_iterator(src))  // a picture already under the new label is newer
                if (!fs::exists(dst / f.path().filename())) fs::rename(f.path(), dst / f.path().filename());
            fs::remove_all(src);
        }
        if (n && opt_.progress)
            std::cerr << fmt::format("[{}] {} records of {} scenes relabelled (angles in one form: {} -> {}, ...)\n",
                                     e_.name, n, renamed.size(), renamed.begin()->first, renamed.begin()->second);
    }

    // A scene's cells still to do: its reference, then each cell in order.
    void runScene(size_t si)
    {
        const SceneId& sid = mine_[si];
        const ScenePlan plan = planScene(sid, cells_, done_, inputs_, rt_);
        sum_.skipped += cells_.size() - plan.ntodo;
        sum_.stale += plan.nstale;
        cellsSeen_ += cells_.size() - plan.ntodo;
        if (plan.ntodo == 0) return;  // no reference render for a scene that is done

        if (!tables_.count(sid.luminaire)) tables_.emplace(sid.luminaire, methods::loadLuminaire(sid.luminaire));
        SceneRun sr{e_,
                    sid,
                    rt_,
                    tables_.at(sid.luminaire),
                    opt_,
                    resultsPath_,
                    context_,
                    sid.scene(),
                    methods::parsePrecision(sid.precision),
                    {},
                    {}};
        renderReference(sr);

        SceneTimes st{e_, {}, {}};
        for (size_t i = 0; i < cells_.size(); ++i)
            if (cells_[i].role != "equal_time" && !plan.todo[i])
                st.remember(cells_[i].parsed, done_.times[cellKey(sid, rt_, cells_[i])]);

        for (size_t i = 0; i < cells_.size(); ++i) {
            if (!plan.todo[i]) continue;
            results::Record r = runCell(sr, cells_[i], st);
            r.inputs = plan.inputs[i];
            results::appendRecord(resultsPath_, context_, r);
            ++sum_.computed;
            ++cellsSeen_;
        }
        if (opt_.progress) progress(si, plan);
    }

    void renderReference(SceneRun& sr)
    {
        methods::RenderOptions ro;
        ro.reps = 1;
        sr.ref = methods::render(rt_, sr.table, sr.scene, refSpec_, sr.prec, ro).image;
        const std::string why = whyNoPictures(sr.ref);
        sr.pictured = why.empty();
        if (!sr.pictured)
            std::cerr << fmt::format("lumibench: warning: {}: {}: no pictures and no FLIP for this scene; its records "
                                     "are kept\n",
                                     sr.sid.label(), why);
        if (e_.saveImages && sr.pictured) {
            sr.imageDir = (fs::path(opt_.outDir) / "images" / sr.sid.label()).string();
            util::createDirsBelow(opt_.outDir, fs::path("images") / sr.sid.label());
        }
        if (!sr.imageDir.empty()) writeExr((fs::path(sr.imageDir) / "reference.exr").string(), sr.ref);
    }

    // One cell's record: the method (or curve point) rendered and compared,
    // or the equal-time MCI partner of c.spec (docs/design.md section 6).
    results::Record runCell(const SceneRun& sr, const Cell& c, SceneTimes& st)
    {
        if (c.role != "equal_time") {
            auto rr = sr.render(c.parsed);
            st.remember(c.parsed, rr.timing.median_ms);
            return sr.record(c.parsed, rr, c, cellImageName(c.role, c.spec, ""));
        }
        const std::string target = c.parsed.canonical();
        if (!st.times.count(target))
            throw Error(fmt::format("equal time: no time of '{}' at scene {}", c.spec, sr.sid.label()));
        results::Record r = equalTimePartner(sr, c, st.times[target], st.curves[c.baseline]);
        if (!r.equalTime->ok) {
            ++sum_.equalTimeOff;
            if (opt_.progress)
                std::cerr << fmt::format("[{}] {}: {} at the time of {} is off-time (no verdict): {}\n", e_.name,
                                         sr.sid.label(), c.baseline->label, c.spec, results::offTimeReason(r));
        }
        return r;
    }

    // One line on stderr after each scene: cells done, elapsed, ETA.
    void progress(size_t si, const ScenePlan& plan) const
    {
        double elapsed = std::chrono::duration<double>(Clock::now() - t0_).count();
        size_t left = sum_.cells - cellsSeen_;
        double eta = sum_.computed ? elapsed / double(sum_.computed) * double(left) : NAN;
        std::cerr << fmt::format("[{}] cells {}/{} ({:.0f}%), scene {}/{} {}, elapsed {}, ETA {}{}\n", e_.name,
                                 cellsSeen_, sum_.cells, 100.0 * cellsSeen_ / std::max<size_t>(1, sum_.cells), si + 1,
                                 mine_.size(), mine_[si].label(), hms(elapsed), hms(eta),
                                 plan.nstale
                                     ? fmt::format("; recomputed {} cells whose inputs changed ({})", plan.nstale,
                                                   fmt::format("{}", fmt::join(plan.changed, "; ")))
                                     : std::string());
    }

    const Experiment& e_;
    const RunOptions& opt_;
    const Clock::time_point t0_ = Clock::now();
    const std::string resultsPath_;
    ocl::Runtime rt_;
    const methods::MethodSpec refSpec_;
    CellInputs inputs_;
    json context_;
    DoneCells done_;
    std::vector<Cell> cells_;
    std::vector<SceneId> mine_;
    std::map<std::string, photometry::Table> tables_;
    RunSummary sum_;
    size_t cellsSeen_ = 0;
};

}  // namespace

RunSummary run(const Experiment& e, const RunOptions& opt) { return Runner(e, opt).run(); }

equaltime::Result findPartner(const Experiment& e, const Baseline& b, const equaltime::Frames& frames,
                              const std::function<double(const methods::MethodSpec&)>& timeOf,
                              const methods::MethodSpec& method, equaltime::Curve& fit, double targetMs)
{
    if (fit.size() < 2) {
        fit.clear();
        for (long n : e.protocol.fit) fit.emplace_back(n, timeOf(mcAt(e, b, n)));
    }
    return equaltime::pairUp(
        e.protocol, frames, method, [&](long n, double extra) { return mcAt(e, b, n, extra); }, fit, targetMs);
}

}  // namespace lb::experiments
