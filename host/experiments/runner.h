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
// partners also `target_kernel`, `mc` and `equal_time_tolerance`; a method
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
// experiment wrote it, or "mc:n=<N>" for the curve), `role` ("method",
// "mci_curve" or "equal_time"), `scene` (the scene label) and `build_s`.
// Equal-time records also carry `equal_time_target_ms` (the matched method's
// median in the paired rounds below), `equal_time_cell_ms` (its own cell's
// median), `equal_time_ratio` (the median over the rounds of MC's time over
// the method's), `equal_time_ok` (|ratio - 1| <= tolerance),
// `equal_time_bracketed` (N_eq is the closest integer: see below),
// `equal_time_candidates` ([{n, ratio, ms}]) and `equal_time_fit`
// ([[N, median ms], ...]).
//
// Equal time (docs/design.md section 6): t(N) of MC is measured on the scene's
// MCI-curve points (or, without a curve, on renders at "equal_time_fit"),
// N solves t(N) = t_M on their piecewise-linear interpolation (solveN); that
// N and its neighbour towards t_M are then timed against the method in
// alternating rounds (ocl::Runtime::timeInterleaved, every kernel at the
// experiment's time_res), so that the drift of a shared machine hits both
// sides of each ratio alike; the candidate whose median round ratio is
// closest to 1 is N_eq. While it is off by more than the tolerance, N is
// aimed again by the secant through the paired ratios and timed with its
// neighbours (three tries at most), unless the measured N below and above the
// method's time are adjacent integers already: then no integer N can match
// more closely on this device, and the record says `equal_time_bracketed`.
// Its error image is one more, untimed render.
#pragma once

#include "experiments/experiment.h"

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

// The file name stem of a cell's saved pictures in DIR/images/<scene>/:
// the SPEC as the experiment wrote it with every character but letters,
// digits, '.' and '-' replaced by '_'; "mci_eq_" + that of the matched
// SPEC for an equal-time partner (role "equal_time").
std::string cellImageName(const std::string& role, const std::string& spec);

// The equal-time solve on its own (tests): N with t(N) = targetMs on the
// piecewise-linear interpolation of the measured (N, median ms) points,
// sorted by N; below the smallest time 1, above the largest extrapolated
// along the last two points; clamped to [1, 2^20]. Measured MC times are not
// linear in N over 1..1024 on every device (PoCL: t(128) / t(8) = 31), so a
// local interpolation beats one global line.
long solveN(std::vector<std::pair<long, double>> points, double targetMs);
// t at N on the same interpolation (proportional beyond its ends).
double interpolateMs(std::vector<std::pair<long, double>> points, long n);

}  // namespace lb::experiments
