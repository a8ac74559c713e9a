// runner.h -- runs an experiment (experiment.h) into a results directory:
//
//   DIR/results.json   one record per cell (results.h), appended atomically as
//                      each cell finishes, so an interrupted run resumes: a
//                      rerun skips the cells already in the file whose
//                      `inputs` are this run's, and recomputes (and replaces)
//                      those whose inputs changed, saying which changed
//
// A record's `inputs`: `size` [W, L], `extent`, `luminaire_digest` (of the
// file's bytes), `reference` (canonical SPEC) and `reference_kernel`,
// `kernel` (digest of the method's kernel source with every header it
// includes, ocl::kernelSourceDigest), `reps`, `time_res`; equal-time
// partners also `target_kernel`, `mc`, `equal_time_tolerance`,
// `equal_time_rounds`, `equal_time_fit`, `mci_curve` (and
// `equal_time_mode` when it is not search); a method
// with a presets file (cubature:preset=FILE) `preset_spec`, the SPEC its
// entry for the cell's luminaire resolves to; `metrics`
// names the error metrics computed (metrics.h), so records of a runner
// that computed fewer are recomputed. Records of
// older files have none and are recomputed. Stale temporary files of a
// killed run are removed at the start (util::removeStaleTemporaries).
//   DIR/images/<scene>/  with "save_images": reference.exr, <cell>.exr and the
//                      PNG triple <cell>_ref/_test/_err.png + <cell>.json that
//                      plots/image_grid.py lays out
//
// Per scene the reference is rendered once (cached on disk by render()), then
// every method, the MCI curve and the equal-time partners, compared in memory.
//
// Each record carries, besides the results.h keys, `spec` (the SPEC as the
// experiment wrote it; for the curve and a partner the baseline's SPEC with
// n=<N> added), `baseline` (curve points and partners), `role` ("method",
// "mci_curve" or "equal_time"), `scene` (the scene label) and `build_s`.
// Every equal-time method gets one partner per baseline of the experiment.
// Equal-time partners are found by the experiment's protocol
// (equaltime::pairUp, equaltime/protocol.h; findPartner below) and carry
// its result as results::EqualTime; methods with a seed are rendered with the
// experiment's `seeds` (their metrics the mean, with a 95 % interval).
#pragma once

#include "experiments/experiment.h"

#include <functional>
#include <string>

namespace lb::experiments {

struct RunOptions {
    std::string outDir;
    int shardK = 1, shardN = 1;
    int device = -1;
    bool progress = true;  // progress lines on stderr
};

struct RunSummary {
    size_t scenes = 0;  // scenes of this shard
    size_t cells = 0;  // cells of this shard
    size_t skipped = 0;  // already in results.json with this run's inputs
    size_t stale = 0;  // in results.json but with other inputs: recomputed (counted in computed)
    size_t computed = 0;  // rendered now
    size_t equalTimeOff = 0;  // equal-time partners outside the tolerance
    // Records of cells the experiment no longer has (another res, method,
    // luminaire, ...), moved from results.json to results.dropped.json
    // before the run, so that the report pools only this experiment's cells.
    size_t dropped = 0;
    double seconds = 0;
};

RunSummary run(const Experiment& e, const RunOptions& opt);

// The equal-time search of `method` against baseline b under the
// experiment's protocol, aimed from `curve` (the scene's measured t(N) of b;
// with fewer than two points the protocol's fit N, each timed by timeOf as a
// cell is) and the method's cell time targetMs; the launches from `frames`
// (equaltime::preparedFrames on the scene at time_res, or a model in tests).
// `fit` gets the points the search was aimed from.
equaltime::Result findPartner(const Experiment& e, const Baseline& b, const equaltime::Frames& frames,
                              const std::function<double(const methods::MethodSpec&)>& timeOf,
                              const methods::MethodSpec& method, equaltime::Curve& fit, double targetMs);

// The file name stem of a cell's saved pictures in DIR/images/<scene>/:
// the SPEC as the experiment wrote it with every character but letters,
// digits, '.' and '-' replaced by '_'; for an equal-time partner (role
// "equal_time") "mci_eq_" + that of the matched SPEC, + "_vs_" + that of its
// baseline's label unless the label is "MCI" (or empty).
std::string cellImageName(const std::string& role, const std::string& spec, const std::string& baseline);

}  // namespace lb::experiments
