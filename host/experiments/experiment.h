// experiment.h -- declarative experiments: experiments/*.json.
//
//   {"name": "smoke",
//    "luminaire_dir": "luminaires",          // relative to the source tree (or absolute)
//    "luminaires": ["lambert.ldt", "spot.ldt"],   // or "*" for every .ldt/.ies there
//    "heights": [0.1, 1.1], "rotations": ["pi/2", "3pi/4"],
//    "methods": ["point", "mc:n=8", "cubature"],
//    "equal_time": {"methods": ["cubature"], // methods that get an MC partner at equal time per baseline,
//                   "tolerance": 0.10, "rounds": 11, "fit": [8, 32, 128], "mode": "search"},
//                                            // and the protocol's keys (equaltime/protocol.h; fit: the N
//                                            // t(N) is fitted on when mci_curve is empty); a bare list:
//                                            // the methods. Top-level equal_time_tolerance,
//                                            // equal_time_rounds, equal_time_fit, equal_time_subpixel:
//                                            // the same keys.
//    "mci_curve": [1, 2, 4, ..., 1024],      // each baseline at these N on every scene (error-time curve)
//    "mc": "mc",                             // the MC baseline(s) of the curve and of equal time: a SPEC,
//                                            // or a list of SPECs and {"label": ..., "spec": ...}
//    "reference": "reference",               // the reference SPEC
//    "res": 64, "precision": ["float"], "size": [1, 1], "extent": 5,   // size: [W, L] m or "file"
//    "shape": "disk",                        // rect | disk; default rect, the file's with size "file"
//    "reps": 5, "save_images": true,         // reps: 5 .. 1000, the protocol's (every cell's timing)
//    "seeds": 8,                             // seed-dependent methods (mc) rendered with seeds
//                                            // seed, seed + 1, ...: metrics are means with 95 % intervals
//    "time_res": 512,                        // every method is timed at time_res^2 pixels, whatever
//                                            // res the error image has: the protocol's (design.md section 6)
//    "scene": "specular", "alpha": [0.1, 0.5], "eye": [0, 4, 2]}   // scene/scene_keys.h
//
// A scene is (luminaire, height, rotation, alpha, precision); its cells are the
// methods, the MCI curve points and the equal-time partners, in that order.
// Methods are parsed for the file's scene kind (methods::parseSpec(text, kind)).
// Scenes are enumerated luminaire-major, then height, rotation, alpha, precision, in
// the order of the file (luminaires from a directory sorted by name), so the
// order, and with it the shard assignment, is deterministic.
#pragma once

#include "equaltime/protocol.h"
#include "methods/registry.h"
#include "scene/scene.h"
#include "scene/scene_keys.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lb::experiments {

// One Monte Carlo baseline: every equal-time method gets a partner of it, and
// it has its own MC curve. The label names it in records, the report and the
// CSV; a bare SPEC is labelled results::defaultBaselineLabel ("MCI" for
// mc's defaults, else the SPEC as written).
struct Baseline {
    std::string label;
    std::string spec;  // as written (without n and extra: the runner chooses them)
    std::string canonical;  // methods::MethodSpec::canonical of spec
    // MC of this baseline at n samples (n + extra: mc's fractional count).
    std::string at(long n, double extra = 0) const;
};

struct Experiment {
    std::string path;  // the file it came from
    std::string name;
    std::string luminaireDir;
    std::vector<std::string> luminaires;  // file paths (resolved)
    std::vector<double> heights, rotations;
    std::vector<std::string> rotationText;  // as written (labels)
    std::vector<std::string> methods;  // SPEC strings
    std::vector<std::string> equalTime;  // subset of methods
    std::vector<long> mciCurve;
    std::vector<Baseline> baselines;  // "mc": at least one, labels and SPECs distinct
    std::string reference = "reference";
    int res = 64;
    std::vector<std::string> precisions{"float"};
    double width = 1, length = 1, extent = 5;
    bool sizeFromFile = false;  // "size": "file": each luminaire's declared opening (methods::sizeFromFile)
    std::optional<LightShape> shape;  // "shape": rect | disk; unset: rect, or the file's with sizeFromFile
    // How every cell is timed (reps launches at time_res^2 pixels, 0 = at the
    // image's res; docs/design.md section 6) and how equal-time partners are
    // paired (rounds: more than reps, the pairing decides the verdict and a
    // round is a few launches; tolerance; fit; mode). Its partner is each of
    // `baselines` in turn.
    equaltime::Protocol protocol;
    bool saveImages = false;
    // A method whose family has a "seed" parameter (MC of every sequence,
    // the shared set's draw included) is rendered this many times, seeds
    // s, s + 1, ... from its SPEC's seed s: its record carries the mean of
    // each metric with a 95 % interval (metrics::overSeeds), its time taken
    // once (the seed does not change the kernel). 1: one draw.
    int seeds = 8;
    SceneKindKeys sceneKeys;  // scene, alpha, eye, albedo
    SceneKind kind() const { return sceneKeys.kind; }
    nlohmann::json raw;  // the file as read
};

// docs/design.md section 6: every time is the median of at least 5 timed runs.
constexpr int kMinExperimentReps = 5;
constexpr int kMaxSeeds = 1000;

// Overrides applied after reading the file (range-checked like the keys they
// replace; unset = the file's value).
struct Overrides {
    std::string luminaireDir;  // every .ldt/.ies file in this directory replaces "luminaires"
    std::optional<int> res;  // replaces "res"
    std::optional<int> reps;  // replaces "reps"
    std::optional<int> timeRes;  // replaces "time_res"
    std::optional<int> seeds;  // replaces "seeds"
    // How an error names an override, given the key it replaces ("luminaires",
    // "res", "reps", "time_res", "seeds"); unset: overrideName(key). A caller names its
    // own settings here (the CLI its flags).
    std::function<std::string(const std::string& key)> name;
};
// "override of key \"res\"".
std::string overrideName(const std::string& key);

// Every key an experiment file may have, in the order docs/experiments.md
// documents them (`run --help` lists them).
const std::vector<std::string>& experimentKeys();

// Reads and checks an experiment file. Throws lb::InputError naming the file
// and the key for anything missing, mistyped or out of range; method SPECs are
// parsed against the registry (an unknown method lists the valid ones).
Experiment loadExperiment(const std::string& path, const Overrides& ov = {});

struct SceneId {
    std::string luminaire;  // path as resolved
    // The luminaire as records name it: its path relative to luminaire_dir
    // ("lambert.ldt", "x/l.ldt"; as given when outside it), so that two files
    // of one name in two folders are two luminaires.
    std::string luminaireName;
    double height = 0, rotation = 0;
    std::string rotationText;
    std::string precision;
    int res = 0;
    double width = 1, length = 1, extent = 5;
    LightShape shape = LightShape::Rect;
    SceneKindKeys kindKeys;  // the experiment's scene kind and its values
    double alpha = 0.25;  // specular: this scene's alpha (one of kindKeys.alphas)
    size_t index = 0;  // position in the enumeration (shard assignment)
    Scene scene() const;
    // short, file-name safe: "lambert-1a2b3c_h0.1_r3pi-4_float", specular
    // scenes "lambert-1a2b3c_h0.1_r3pi-4_a0.1_float"; 1a2b3c from a digest
    // of luminaireName, so t.ldt and t.ies (or x/l.ldt and y/l.ldt) differ;
    // the rotation as angleText, so that 3*pi/4, 3pi/4 and 6pi/8 are one label.
    std::string label() const;
};

// The canonical text of an angle (radians) in labels: "0", "pi", "Cpi",
// "pi/D" or "Cpi/D" (C, D coprime, D <= 64) where it is such a multiple of pi
// to 1e-9, else the shortest decimal that reads back as the same double.
std::string angleText(double radians);

// Every scene of the experiment in the deterministic order described above,
// with `size` and `extent` from the experiment.
std::vector<SceneId> scenes(const Experiment& e);

// Shard K of N (1-based): the scenes with index % N == K - 1. A whole scene
// (its reference, methods and equal-time partners) stays on one shard.
bool inShard(const SceneId& s, int k, int n);
// Parses "K/N" (1 <= K <= N); otherwise an InputError naming `name` (the
// setting the text came from).
void parseShard(const std::string& name, const std::string& text, int& k, int& n);

}  // namespace lb::experiments
