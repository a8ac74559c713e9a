// results.h -- the results JSON document of an experiment run:
//
//   {"context": {"device": ..., "driver": ..., "commit": ..., "date": ...,
//                "host": ..., "lumibench_version": ..., ...},
//    "records": [{"method": "cubature", "params": {...}, "luminaire": "...",
//                 "height": 0.1, "rotation": 1.5707963267948966, "res": 512,
//                 "precision": "float", "device": ..., "driver": ...,
//                 "time_ms": {"median": ..., "min": ..., "max": ..., "reps": 5, "res": 512},
//                 "nmse": ..., "nrmse": ..., "relmse": ..., "ueb": ..., "leb": ...,
//                 "nonfinite": 0, "pixels": ..., "mean_ref": ..., "mean_test": ...,
//                 "grad_nmse": ..., "grad_pairs": ..., "flip": ... (null: FLIP not available),
//                 "seeds": 8, "ci95": {"nmse": [lo, hi], ...} (seed-dependent methods),
//                 "equal_time_to": "cubature:...", "n": 40, "equal_time": {...},
//                 "baseline": {"label": "strong MC", "spec": "mc:domain=solid,..."}}, ...],
//    "schema_version": 2}
//
// One record is one cell of an experiment: a method with its parameters at
// one scene, precision and device. Its cell key (Record::key) is what
// appendRecord replaces and mergeResults deduplicates by. Every record carries
// device, driver, time and error (docs/design.md section 6), so records of several
// files can be plotted together. Keys a record does not know are kept in
// `extra` through load and save, so that later fields survive older code.
// Undefined numbers (NaN, infinity) are written as null and read back as NaN.
#pragma once

#include "metrics/metrics.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <array>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lb::results {

// Kernel time from OpenCL profiling events (docs/design.md section 6), milliseconds.
struct TimeMs {
    double median = 0, min = 0, max = 0;
    int reps = 0;
    int res = 0;  // pixels per side of the timed launches (0: not recorded, older files)
    double cv = 0;  // coefficient of variation of the reps (std / mean; 0: not recorded, older files)
};

// How an equal-time MC partner was found (docs/design.md section 6), on the
// partner's record as "equal_time": {...}. Both times are medians of the
// same alternating rounds (the method, then MC at n, round after round), the
// pair a report shows.
struct EqualTime {
    std::string label;  // the matched method as the experiment writes it
    double n = 0;  // MC's mean samples per image pixel: (N + extra) scale^2 as rendered (the record's n is N)
    double scale = 1;  // below N = 1: the share of the image's side MC rendered (mc's scale)
    double method_ms = 0, partner_ms = 0;  // medians of the paired rounds
    double method_cv = 0, partner_cv = 0;  // their coefficients of variation
    double ratio = 0;  // the median over the rounds of partner / method
    double cell_ms = 0;  // the method's own cell, timed apart
    double tolerance = 0;  // |ratio - 1| allowed
    bool ok = false;  // |ratio - 1| <= tolerance
    bool bracketed = false;  // no integer N is closer on this device
    nlohmann::json candidates = nlohmann::json::array();  // [{"n", "extra"?, "ratio", "ms"}, ...] as timed
    nlohmann::json fit = nlohmann::json::array();  // [[N, ms], ...]: the t(N) the search started from
};
void to_json(nlohmann::json& j, const EqualTime& e);
// Throws lb::InputError naming a missing or mistyped key.
void from_json(const nlohmann::json& j, EqualTime& e);

// The version of the results document this code writes (its top-level
// "schema_version"; files without one are version 1, whose equal-time
// fields lay in the record as equal_time_ratio, equal_time_ok, ...).
constexpr int kResultsSchemaVersion = 2;

// The Monte Carlo baseline an equal-time partner or an MC curve point belongs
// to (an experiment's "mc": one SPEC or a list of labelled ones): its label as
// the report and the CSV name it, and its canonical SPEC (every parameter,
// without n and extra). On a record as "baseline": {"label", "spec"}.
struct BaselineRef {
    std::string label, spec;
    bool operator==(const BaselineRef& o) const { return label == o.label && spec == o.spec; }
};
// A baseline's SPEC as records carry it: a canonical mc SPEC without its n
// and extra ("mc:a=1,extra=0,n=24,z=2" -> "mc:a=1,z=2"), which the runner
// chooses.
std::string baselineSpec(const std::string& canonical);
// The label a baseline given as a bare SPEC gets: "MCI" for the thesis' MC
// (mc's defaults), else the SPEC as written.
std::string defaultBaselineLabel(const std::string& written);

struct Record {
    std::string method;  // docs/design.md section 4 name, e.g. "mc"
    nlohmann::json params = nlohmann::json::object();  // method parameters, e.g. {"n": 24}
    std::string luminaire;  // file name or synthetic name
    double height = 0, rotation = 0;  // metres, radians (docs/design.md section 2)
    int res = 0;  // image is res x res
    std::string precision = "float";  // "float" | "double"
    std::string device, driver;
    TimeMs time_ms;
    metrics::Metrics error;  // serialised flat: nmse, nrmse, ... at the record's top level
    std::optional<std::string> equal_time_to;  // MC at equal time: the method spec it matches
    std::optional<int64_t> n;  // sample count where it is a result (N_eq), not a parameter
    std::optional<EqualTime> equalTime;  // with equal_time_to: how the partner was found
    // Partners and MC curve points: their baseline. Records of files written
    // before baselines had names get it on load (from the partner's
    // inputs.mc, or the curve point's parameters without n).
    std::optional<BaselineRef> baseline;
    // Seed-dependent methods (Experiment::seeds): `error` holds the means over
    // this many draws and ci95 their 95 % intervals by metric key
    // (metrics::overSeeds); 1 and empty for one draw.
    int seeds = 1;
    std::map<std::string, std::array<double, 2>> ci95;
    // Everything else the record was computed from, as the runner writes it
    // (runner.h): light size, extent, reps, time_res, the reference SPEC and
    // digests of the luminaire file and of the kernel sources. Empty in
    // records of older files: resume treats those as stale.
    nlohmann::json inputs = nlohmann::json::object();
    // The scene's kind and its values, flat at the record's top level
    // (SceneKindKeys::recordKeys): empty for the diffuse scene, else
    // scene_kind with alpha and eye (specular) or albedo (indirect). Part of
    // the cell key when not empty.
    nlohmann::json sceneKeys = nlohmann::json::object();
    nlohmann::json extra = nlohmann::json::object();  // any other keys, kept as they are

    // The cell key: method, params, luminaire, height, rotation, res,
    // precision, device and equal_time_to; for an equal-time partner only
    // the scene, device, equal_time_to and its baseline's SPEC (its N is a
    // result, not part of the cell), so that a scene has one partner per
    // method and baseline. Anything else
    // that tells two cells apart must go into params. `inputs` is not part
    // of it: a record whose inputs changed is the same cell, out of date.
    std::string key() const;
};

// The equal-time verdict of a method against its MC partner on one metric
// (metrics::minimisable: lower is better). Each side is its 95 % interval
// where it has one (seeds > 1), else its value: the method wins when its
// upper end lies below the partner's lower end, loses when its lower end
// lies above the partner's upper end, and ties when they overlap. Undefined
// when either value is not finite. A pair whose paired times differ by more
// than the tolerance (equal_time.ok false) is no verdict: OffTime
// (docs/design.md section 6), whatever its errors.
enum class Verdict { Win, Tie, Loss, OffTime, Undefined };
Verdict verdict(const Record& method, const Record& partner, const std::string& metric = "nmse");
const char* verdictName(Verdict v);  // "win", "tie", "loss", "off-time", "n/a"

// Why a partner is off-time, "" where it is at equal time: MC at N = 1
// already slower than the method (its floor: N_eq = 1, or N = 1 among the
// candidates timed, slower than the tolerance allows), MC at the largest N still
// faster, no integer N closer (N and N + 1 bracket the method's time), or
// the search found none within the tolerance; each with the paired ratio.
std::string offTimeReason(const Record& partner);
// Its short class: "floor", "ceiling", "step", "unmatched" ("" at equal time).
std::string offTimeClass(const Record& partner);

// Keeps one record per cell key: the last one (in file order), at the
// position of the first. Returns how many were dropped. The rule of
// appendRecord, mergeResults and the report.
size_t dedupe(std::vector<Record>& records);

void to_json(nlohmann::json& j, const Record& r);
// Throws lb::InputError naming the missing or mistyped key.
void from_json(const nlohmann::json& j, Record& r);

struct Results {
    nlohmann::json context = nlohmann::json::object();
    std::vector<Record> records;
};

void to_json(nlohmann::json& j, const Results& d);
void from_json(const nlohmann::json& j, Results& d);

// The run's context: device and driver as given, the source commit (`git -C
// LB_SOURCE_DIR rev-parse HEAD` at run time, "unknown" when git or the
// repository is absent) and whether the tree had uncommitted changes
// (commit_dirty), the UTC date (ISO 8601), host name, lumibench_version,
// compiler and OS. The keys of `extra` (an object) are added or override.
nlohmann::json makeContext(const std::string& device, const std::string& driver,
                           const nlohmann::json& extra = nlohmann::json::object());

// A results file is the JSON document at `path` and, while records are being
// appended, its journal `path`.journal: JSON lines, {"context": {...}} (only
// when the document did not exist yet) or {"record": {...}}, each ended by a
// newline and flushed to disk before appendRecord returns. A last line without
// its newline (an append cut off by a crash or a full disk) is no record: load
// ignores it and the next append cuts it off.
std::string journalPath(const std::string& path);

// Whether `path` or its journal exists.
bool exists(const std::string& path);

// Reads a results file: the document, then the journal's records (dedupe: a
// journal record replaces the document's of the same cell), both under a
// shared lock on `path`.lock where it exists, so that a concurrent append
// cannot fold the journal in between the two reads. Throws
// lb::InputError naming the file (and the record index or journal line) when
// both are missing, or either is not JSON or not a results document.
Results load(const std::string& path);

// Writes `doc` atomically: to a temporary file beside `path`, flushed to disk,
// then renamed over `path`, so that a reader or an interrupted run sees the
// old or the new document, never half of one; then removes the journal, so
// that `path` holds exactly `doc`. Throws lb::Error.
void save(const std::string& path, const Results& doc);

// Adds `r` to the results file at `path` (created with `context` when it does
// not exist; an existing file keeps its context). A record with the same cell
// key replaces the earlier one on load, so a re-run cell is not counted twice.
// O(1) per record: one line appended to the journal (amortised: the journal is
// folded into the document once it outgrows it, and at least 64 KiB).
// Serialised with other processes appending to the same file by an exclusive
// lock on `path`.lock (left in place).
void appendRecord(const std::string& path, const nlohmann::json& context, const Record& r);

// Folds the journal into the document (save(path, load(path))), under the
// lock; creates the document with `context` and no records when neither
// exists. A run ends with it, so that other tools read results.json alone.
void compact(const std::string& path, const nlohmann::json& context);

// Keeps in the results file at `path` only the records for which `keep`
// is true; the others are appended to the results file `sidePath` (created
// with the same context), so nothing is lost. Under the exclusive lock of
// `path`, as appendRecord. Returns how many were moved; a missing file moves
// none.
size_t retain(const std::string& path, const std::function<bool(const Record&)>& keep, const std::string& sidePath);

// Applies `edit` to every record of the results file at `path` (it returns
// whether it changed the record) and saves the file where one changed, under
// the exclusive lock of `path`, as appendRecord. Returns how many changed; a
// missing file changes none. (Migrations of older files, e.g. scene labels.)
size_t update(const std::string& path, const std::function<bool(Record&)>& edit);

struct MergeStats {
    size_t files = 0, records_in = 0, records_out = 0, replaced = 0;
    // With MergeOptions::force: each difference between the inputs that a
    // merge without it refuses, and each record replaced by one computed
    // from other inputs, commit or experiment, by name.
    std::vector<std::string> forced;
};

struct MergeOptions {
    bool force = false;  // merge despite differing experiments, commits or cell inputs (said in MergeStats::forced)
};

// Merges results files (e.g. the shards of one experiment) into one document.
// Records are deduplicated by cell key (dedupe): of several with the same key
// the one from the later file (in the order given) wins, also for equal-time
// partners (one per scene, device, matched method and baseline). Inputs whose
// contexts name different experiments or commits, and a record replacing
// one of the same cell with other `inputs`, are refused (InputError naming
// both files and what differs) unless options.force. The merged context is
// the first file's, with "merged_from": [{"file": ..., "context": ...}, ...]
// and "commits" (every input's commit, in order) for every input. Throws
// lb::InputError for an unreadable input.
Results mergeResults(const std::vector<std::string>& paths, MergeStats* stats = nullptr,
                     const MergeOptions& options = {});

// An equal-time pair: a partner and the record of the method it was timed
// against (same scene, device and scene kind; the method's `spec` as written
// equal to the partner's equal_time label), null where that record is missing.
struct Pair {
    const Record* method = nullptr;
    const Record* partner = nullptr;
};
std::vector<Pair> pairsOf(const std::vector<Record>& records);

// A record's SPEC with every parameter (methods::MethodSpec::canonical of
// its method and params; for a partner MC's SPEC at its N and extra).
std::string canonicalSpec(const Record& r);

// The records as CSV (RFC 4180 with \n line ends: a header line, then one
// flat row per record; fields with a comma, quote or line break are quoted,
// quotes doubled; text a spreadsheet would run as a formula prefixed with ';
// undefined numbers are empty fields; booleans True / False). At most 45
// columns (kMaxCsvColumns), in this order:
//   role ("method", "mci_curve", "equal_time"), series (what a plot groups
//   by: the SPEC as written for a method, <baseline>=<method> for a partner,
//   "<baseline> curve" for an MC curve point), method, spec (canonicalSpec:
//   every parameter), baseline and baseline_spec (the partner's or curve
//   point's baseline: label and canonical SPEC), equal_time_label (the
//   partner's method as the experiment wrote it), verdict and verdict_flip
//   (a partner's verdict in NMSE and in FLIP: win, tie, loss, off-time, n/a),
//   off_time (offTimeReason), scene, luminaire, luminaire_name, height_m,
//   rotation_rad, res, precision, device, driver, time_ms_median, _min,
//   _max, _reps, _res, _cv, the metrics nmse, nrmse, relmse, ueb, leb,
//   nonfinite, mean_ref, mean_test, grad_nmse, flip (means over the seeds
//   where seeds > 1; ueb, leb, mean_ref and mean_test with the unit of the
//   values as suffix, _lux or _cd_m2, where every record has the one unit,
//   else without suffix and a column `unit`), seeds, n (MC's sample count: N
//   + extra for a partner; empty for other methods), equal_time_ratio (the
//   paired rounds' median of t MC / t method), then the scene-kind keys
//   some record has (scene_kind, alpha, eye as JSON text, albedo, shape,
//   size as JSON text).
// Every other field stays in results.json; the 95 % intervals are in
// toLongCsv. docs/experiments.md ("Results as a table") documents them.
std::string toCsv(const Results& doc);
constexpr size_t kMaxCsvColumns = 45;

// The metrics in long form, one row per record and metric (results_long.csv):
// record (the row of the record in toCsv, from 0), metric (nmse, nrmse,
// relmse, ueb, leb, grad_nmse, flip), mean (the value; the mean over the
// seeds where seeds > 1), lo and hi (its 95 % interval; empty for one draw).
std::string toLongCsv(const Results& doc);

// DIR/results.csv beside DIR/results.json: the path with its extension
// replaced by .csv.
std::string csvPathFor(const std::string& resultsJsonPath);

// Writes toCsv(doc) atomically to csvPathFor(resultsJsonPath), and
// toLongCsv(doc) beside it as results_long.csv.
void saveCsv(const std::string& resultsJsonPath, const Results& doc);

}  // namespace lb::results
