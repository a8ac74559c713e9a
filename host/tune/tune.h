// tune.h -- nlopt tuning of a method's continuous parameters against NMSE:
// `lumibench tune EXP --out DIR`.
//
// A tune experiment (experiments/tune-*.json):
//
//   {"name": "tune-smoke",
//    "method": "cubature:triangulation=fan",   // the SPEC whose tunables are searched
//    "params": ["plane_eps", "horizon_eps"],   // default: every tunable Real/Int of the method
//    "bounds": {"plane_eps": [1e-6, 1e-4]},    // optional: a narrower range than the tunables table's
//    "reference": "reference:tol=1e-4",
//    "luminaire_dir": "luminaires", "res": 24, "precision": "float", "size": [1, 1], "extent": 5,
//    "train":      {"luminaires": ["lambert.ldt"], "heights": [0.1], "rotations": ["pi/2", "3pi/4"]},
//    "validation": {"luminaires": ["spot.ldt"],    "heights": [1.1], "rotations": ["pi/2", "3pi/4"]},
//    "metric": "nmse",                           // what is minimised: any metric a record carries
//                                                // (nmse, nrmse, relmse, grad_nmse, flip, ueb, leb as |leb|)
//    "objective": "mean",                        // mean | worst | geomean | relative of the metric
//                                                // over the training scenes, or equal_time (below)
//    "scale": "point",                           // relative: the SPEC whose metric divides each scene's
//    "equal_time": {"time_res": 128, "reps": 5, "rounds": 5, "mc": "mc", "fit": [1, 2, 4, 8, 16, 32, 64],
//                   "mode": "aim"},            // the equal-time protocol (equaltime/protocol.h)
//    "algorithm": "LN_SBPLX",                    // any nlopt name (LN_NELDERMEAD, LN_BOBYQA, ...)
//    "global": "GN_DIRECT_L", "global_maxeval": 40,   // optional global search before the local one
//    "maxeval": 30, "maxtime": 60, "seed": 1,
//    "cross_validation": "leave-one-luminaire-out",   // optional, below
//    "presets": true,                                  // optional, below
//    "scene": "specular", "alpha": [0.1, 0.5], "eye": [0, 4, 2]}   // scene/scene_keys.h; alphas
//                                                // multiply the train and validation scenes
//
// Balanced objectives: "geomean" is exp(mean log metric) over the scenes
// (minimising it minimises the mean of log metric: a scene 100x worse than
// the rest weighs as much as any other, where the arithmetic "mean" follows
// the worst few); "relative" is the mean of metric / scale, scale the
// metric of the "scale" SPEC on the same scene (default the point light),
// rendered once before the search.
//
// The equal-time objective: before the search, MCI ("mc" at each N of
// "fit") is rendered on every scene and timed at time_res^2 pixels (one
// warm-up, median of reps launches), giving the scene's curve of MCI's metric
// against its time. Each evaluation times the candidate against MCI by the
// protocol's search (pairedMs): in mode aim, once in `rounds` alternating
// rounds against MCI at the N that equaltime::solveN aims at on the curve; in
// mode search, until the ratio is within the tolerance. Its time is read on
// the curve's clock, t = t_curve(N) / ratio, a load that changed since the
// curve was measured hitting both sides of the ratio alike. Each scene scores
// log(metric / MCI's metric at that time), interpolated log-log on the curve
// (equaltime::metricAt); the objective is the mean
// over the scenes. So a candidate that gains accuracy only by becoming slower
// gains nothing against MCI. Noise: each evaluation's time is one median of
// `rounds` ratios on whatever else the machine runs; at 1.5x timing noise the
// score moves by ~log 1.5 = 0.4 (MCI's metric ~ 1/t), so compare
// equal-time objectives that differ by more than that, or rerun.
//
// Cross-validation ("cross_validation": "leave-one-luminaire-out"): after the
// main search, one more search per luminaire of the training set, on the
// training scenes of every other luminaire (the same heights, rotations and
// budget); each fold's tuned spec and the defaults are then scored on the
// held-out luminaire's training scenes (and on the validation set).
// tune.json's "cross_validation": per fold the held-out luminaire, default and
// tuned held-out scores, train and validation scores, the tuned spec; their
// means; "folds_improved" (and its fraction) counts the folds whose tuned
// spec beats the defaults on the held-out luminaire; per fold also the
// metric's arithmetic and geometric means over the held-out scenes
// ("default_<metric>", "tuned_<metric>", whatever the objective);
// "param_spread": parameterSpread over the folds. Needs two training
// luminaires or more.
//
// Presets ("presets": true): one more search per training luminaire on its
// own training scenes; DIR/presets.json maps each luminaire file's name to its
// tuned SPEC (`render --method cubature:preset=DIR/presets.json`), and
// tune.json's "presets" compares, per luminaire, the defaults, the one global
// tuned spec and the preset on that luminaire's training scenes (and its
// validation scenes where the validation set has the same luminaire).
//
// Each parameter is searched in the unit interval mapped onto its bounds from
// the tunables table, linearly or logarithmically (Scale::Log). Continuous
// parameters are kernel arguments, so every evaluation reuses the cached
// program; references come from the render cache.
#pragma once

#include "equaltime/protocol.h"

#include "methods/registry.h"
#include "scene/scene_keys.h"

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace lb::tune {

struct SceneSet {
    std::vector<std::string> luminaires;  // resolved paths
    std::vector<double> heights, rotations;
    std::vector<std::string> rotationText;
};

// The "equal_time" key's defaults: time_res 128, reps 5, rounds = reps,
// tolerance 0.10, mc "mc", fit 1, 2, 4, ..., 64, mode aim.
equaltime::Protocol tuneProtocol();

struct TuneExperiment {
    std::string path, name;
    std::string method;  // base SPEC
    std::vector<std::string> params;  // names searched
    // Narrower search ranges than the tunables table's, by name ("bounds").
    std::map<std::string, std::pair<double, double>> bounds;
    std::string reference = "reference";
    int res = 24;
    std::string precision = "float";
    double width = 1, length = 1, extent = 5;
    SceneSet train, validation;
    std::string metric = "nmse";  // metrics::minimisableMetrics()
    std::string objective = "mean";  // mean | worst | geomean | relative | equal_time
    std::string scale = "point";  // relative: the SPEC whose metric divides each scene's
    equaltime::Protocol equalTime = tuneProtocol();  // how the candidate and MCI are timed
    std::string algorithm = "LN_SBPLX";
    std::string global;  // "" = none
    int globalMaxeval = 0;  // 0: half of maxeval
    int maxeval = 30;
    double maxtime = 0;  // seconds, 0 = none
    unsigned seed = 1;
    bool crossValidation = false;  // leave-one-luminaire-out over the training luminaires
    bool presets = false;  // a tuned spec per training luminaire, DIR/presets.json
    SceneKindKeys sceneKeys;  // scene, alpha, eye, albedo
    nlohmann::json raw;
};

// Reads and checks the file; lb::InputError naming the file and key otherwise.
TuneExperiment loadTuneExperiment(const std::string& path);

// One searched parameter: its row of the tunables table.
struct Dim {
    methods::Param param;
    double toValue(double u) const;  // unit interval -> value (clamped to the bounds)
    double toUnit(double v) const;  // value -> unit interval
};

struct TuneOptions {
    std::string outDir;
    int device = -1;
    bool quiet = false;
    bool plot = true;  // run plots/tune.py when /usr/bin/python3 has matplotlib
};

// Runs the search and writes outDir/tune.json (and tune.png, and with
// "presets" presets.json); returns the document.
// Its "near_bound" lists every searched parameter whose tuned value ended within
// 1 % of the searched unit interval from a bound ({name, value, bound lo | hi,
// limit}); each is also warned about on stderr (the optimum may lie beyond it).
// Its summaries ("default", "tuned") name the metric: train_<metric>,
// validation_<metric>, ..._per_scene, ..._mean, ..._worst. Throws lb::Error
// before searching when the metric is flip and flip-evaluator is not available.
nlohmann::json runTune(const TuneExperiment& e, const TuneOptions& opt);

// The equal-time score of one scene: log(metric / equaltime::metricAt(curve, ms)),
// the curve MCI's (time at the equal-time resolution, metric) in order of N.
double equalTimeScore(double metric, double ms, const std::vector<equaltime::MetricPoint>& curveByN);

// The candidate's time on MCI's curve clock: the protocol's search
// (equaltime::pairUp) of `method` against MCI (mcAt) on `frames`, aimed from
// the measured t(N) `curve` and the candidate's own time aimMs; t = the
// curve's t at the N found (+ extra, linearly) over the paired ratio.
double pairedMs(const equaltime::Protocol& p, const equaltime::Frames& frames, const methods::MethodSpec& method,
                const equaltime::McAt& mcAt, const equaltime::Curve& curve, double aimMs);

// What an objective makes of the per-scene scores (the metric; with relative
// metric / scale; with equal_time the log ratio): mean, relative and
// equal_time their arithmetic mean, worst their maximum, geomean
// exp(mean log max(score, 1e-300)).
double aggregateScores(const std::string& objective, const std::vector<double>& scores);

// One scene's relative score: metric / scale, a scale <= 0 or non-finite
// (an undefined metric of the scale SPEC) counting as 1e-30 so the score is
// large but finite.
double relativeScore(double metric, double scale);

// The spread of each searched parameter over the cross-validation folds:
// per name {values, min, max, mean, std, unit_range}; unit_range is
// max - min in the search's unit interval (0: every fold agrees, 1: the
// parameter swings over its whole range, a sign of over-fitting).
nlohmann::json parameterSpread(const std::vector<Dim>& dims, const std::vector<std::vector<double>>& foldValues);

// tune.json's cross-validation as Markdown: per fold the held-out luminaire's
// default and tuned scores, then each parameter's spread over the folds;
// "" without cross-validation.
std::string crossValidationTable(const nlohmann::json& doc);

// The SPEC with `names` set to `values` (canonical text), the rest from `base`.
std::string specWith(const std::string& base, const std::vector<std::string>& names, const std::vector<double>& values,
                     SceneKind kind = SceneKind::Diffuse);

}  // namespace lb::tune
