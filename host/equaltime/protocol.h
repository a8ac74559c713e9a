// protocol.h -- the equal-time protocol (docs/design.md section 6): how
// `run`, `bench` and `tune` time a method against MC, in one struct with one
// JSON reader, and the set-up that turns it into a search on a device.
//
// The protocol's keys, in an experiment's or a tune file's "equal_time"
// object (docs/experiments.md, docs/tuning.md):
//
//   "time_res": 512,          // pixels per side of every timed launch (0: the image's)
//   "reps": 5,                // timed launches after one warm-up; their median counts
//   "rounds": 11,             // alternating rounds (method, MC) of a pairing
//   "tolerance": 0.10,        // |ratio - 1| that counts as equal time
//   "mc": "mc",               // the partner: an mc SPEC without n (the search sets it)
//   "fit": [8, 32, 128],     // MC's sample counts timed for t(N), which aims the search
//   "mode": "search",         // search | aim (below)
//   "subpixel": false         // search: below N = 1, MC rendered at a share of
//                             // the image's side and upsampled (mc's scale)
//
// Modes of equaltime::search: "search" pairs the aimed N and its neighbours
// until the ratio is within the tolerance (three tries, then the fractional
// step); "aim" pairs MC at the N that solveN aims at on t(N) once, no
// tolerance loop: one set of rounds, the cheap pairing tune's objective
// runs at every evaluation.
#pragma once

#include "equaltime/equaltime.h"
#include "methods/render.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace lb::util {
struct JsonKeys;
}

namespace lb::equaltime {

struct Protocol {
    int timeRes = 512;
    int reps = 5;
    int rounds = 11;
    double tolerance = 0.10;
    std::string mc = "mc";
    std::vector<long> fit = {8, 32, 128};
    Mode mode = Mode::Search;
    bool subpixel = false;

    Options options() const;  // the search's
    nlohmann::json json() const;  // the keys above
};

// The protocol's keys, in the order the docs list them.
const std::vector<std::string>& protocolKeys();
// "search" | "aim"; anything else an InputError naming `where`.
Mode parseMode(const std::string& text, const std::string& where);
const char* modeName(Mode m);

// Reads the protocol's keys present in the object `r` into p (the rest keep
// p's values), each range-checked: time_res 0 .. 16384 (8 .. 4096 where
// minTimeRes says so), reps and rounds 1 .. 1000 (at least minReps),
// tolerance 0.001 .. 10, mc an mc SPEC without n or extra, fit at least two
// counts in 1 .. 2^20. A key of the protocol in `elsewhere` is refused,
// naming the key of the file that sets it instead.
struct ReadRules {
    int minReps = 1;
    int minTimeRes = 0;
    int maxTimeRes = 16384;
    std::map<std::string, std::string> elsewhere;  // protocol key -> where the file sets it
    SceneKind kind = SceneKind::Diffuse;  // the scene kind mc is parsed for
};
void readProtocol(const util::JsonKeys& r, Protocol& p, const ReadRules& rules = {});

// The equal-time set-up, one for run, bench and tune: each side's frame
// launcher by SPEC. preparedFrames builds a methods::Prepared per SPEC on
// the timed scene (local size lx x ly) and keeps it in the launch.
using Frames = std::function<Launch(const methods::MethodSpec&)>;
Frames preparedFrames(ocl::Runtime& rt, const photometry::Table& table, const Scene& timed, methods::Precision prec,
                      size_t lx = 8, size_t ly = 8);

// The SPEC of MC `mc` (a SPEC without n) at n samples, + extra (mc's
// fractional count, 3 decimals) where extra > 0, + scale (3 decimals) where
// below 1: "mc:domain=solid,n=4".
std::string specAt(const std::string& mc, long n, double extra = 0, double scale = 1);

// MC of the partner at n samples (+ extra: mc's fractional count).
using McAt = std::function<methods::MethodSpec(long n, double extra)>;

// The protocol's search for `method` against MC: its sides from `frames`
// (MC fractional where the partner has mc's `extra`), aimed from the
// measured t(N) `fit` and the method's own time targetMs.
Result pairUp(const Protocol& p, const Frames& frames, const methods::MethodSpec& method, const McAt& mcAt,
              const Curve& fit, double targetMs);

}  // namespace lb::equaltime
