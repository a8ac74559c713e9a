// Equal time (docs/design.md section 6): MC's sample count N at which MC
// takes as long as a method on the same device, found by one search that
// `run`, `bench` and `tune` share.
//
// The search starts from measured (N, median ms) points of MC, t(N): N
// solves t(N) = t_M on their piecewise-linear interpolation (solveN). That N
// and its neighbour towards t_M are then launched against the method in
// alternating rounds, so that the drift of a shared machine hits both sides
// of each ratio alike; a candidate's ratio is the median over the rounds of
// t(MC) / t(method), and the candidate closest to 1 (in log) is N_eq. While
// it is off by more than the tolerance, N is aimed again by the secant
// through the paired ratios and timed with its neighbours (three tries at
// most), unless the measured N below and above the method's time are
// adjacent integers already: then no integer N matches more closely on this
// device (`bracketed`). Where MC takes a fractional count (mc's `extra`: that
// share of its tiles takes N + 1 points), the step between N and N + 1 is
// closed by interpolating their paired ratios (two tries). Where MC at N = 1
// is slower than the tolerance allows and it can render below one sample per
// pixel (Sides::scaled: mc's scale, the image rendered at a fraction of its
// side and upsampled), the search goes on in the scale, on the paired ratios
// of scaled launches (time ~ a + b s^2, a the upsampling's): s^2 = 1 /
// ratio(N = 1) and half of it first, then interpolation between the ratios
// nearest 1 from below and above, or the line through the two nearest
// (three more tries).
//
// The module knows launches, not kernels: a caller hands it the method's
// launch and a factory of MC's launches by sample count, so it is tested on
// synthetic time models without a device.
#pragma once

#include "cl/runtime.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace lb::equaltime {

// The largest sample count the search sets (its clamp).
constexpr long kMaxN = 1L << 20;

// Measured (N, median ms) points of MC.
using Curve = std::vector<std::pair<long, double>>;

// N with t(N) = targetMs on the piecewise-linear interpolation of the
// points, sorted by N; below the smallest time 1 (or proportional to N from
// the first point), above the largest extrapolated along the last two
// points; clamped to [1, 2^20]. Measured MC times are not linear in N over
// 1..1024 on every device (PoCL: t(128) / t(8) = 31), so a local
// interpolation beats one global line.
long solveN(Curve points, double targetMs);
// t at N on the same interpolation (proportional beyond its ends).
double interpolateMs(Curve points, long n);

// One launch: its time in ms (an OpenCL profiling event, or a model in tests).
using Launch = std::function<double()>;

// What the search times against each other.
struct Sides {
    Launch method;  // one frame of the method as a renderer runs it
    // One frame of MC at n samples plus a fractional share `extra` in [0, 1)
    // (always 0 unless `fractional`); called once per distinct (n, extra), so
    // the caller may build the kernel there and keep it in the returned launch.
    std::function<Launch(long n, double extra)> mc;
    bool fractional = false;  // MC takes a fractional sample count
    // MC at N = 1 rendered at `scale` (< 1) of the image's side and
    // upsampled; empty: the search stops at N = 1.
    std::function<Launch(double scale)> scaled;
};

// Search: the aimed N and its neighbours until the ratio is within the
// tolerance (above). Aim: MC at the N solveN aims at, paired once (one set of
// rounds, no tolerance loop, no fraction): a cheaper time of the method on
// the curve's clock, as tune's equal-time objective takes at every evaluation.
enum class Mode { Search, Aim };

struct Options {
    double tolerance = 0.10;  // |ratio - 1| that counts as equal time
    int rounds = 11;  // alternating rounds per timing (>= 5)
    int tries = 3;  // aims of the integer search
    Mode mode = Mode::Search;
    double minScale = 0.05;  // the least scale below N = 1 (Sides::scaled)
};

struct Result {
    long n = 0;  // N_eq
    double extra = 0;  // its fractional share (0 unless that is closer)
    double scale = 1;  // below N = 1: the side's share MC renders (n 1, extra 0)
    double ratio = NAN;  // median over the rounds of t(MC) / t(method)
    ocl::Timing method, partner;  // the two sides over the same paired rounds
    bool ok = false;  // |ratio - 1| <= tolerance
    bool bracketed = false;  // no integer N is closer on this device
    nlohmann::json candidates = nlohmann::json::array();  // [{"n", "extra"?, "scale"?, "ratio", "ms"}, ...] as timed
};

// The search above (in options.mode), from the measured points `fit` (>= 1
// point) and the method's time `targetMs` measured apart (its own cell),
// which aims the first candidates only: every verdict of the search is a
// paired ratio.
Result search(const Sides& sides, const Options& options, const Curve& fit, double targetMs);

// The median over the rounds of t(launches[k]) / t(launches[0]) (k >= 1),
// from one set of alternating rounds.
double medianRatio(const std::vector<ocl::Timing>& rounds, size_t k);

// One point of an MC curve for metrics at a time: MC's median time (ms) and
// its metric on the scene.
struct MetricPoint {
    double ms, metric;
};
// MC's metric at `ms`: the curve (in order of N) with its times made
// non-decreasing (a later, larger N measured faster than a smaller one takes
// the smaller one's time; equal times keep the lower metric), interpolated
// linearly in (log t, log metric); beyond its ends along metric ~ 1/t (MC's
// variance at N ~ t). Metrics <= 0 count as 1e-300.
double metricAt(const std::vector<MetricPoint>& curveByN, double ms);

}  // namespace lb::equaltime
