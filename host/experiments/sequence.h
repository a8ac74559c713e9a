// sequence.h -- animated sequences of the indirect scene (docs/design.md section 9):
// a named path of the light over F frames, every method rendered frame after
// frame through one Prepared (stateful methods such as acrsm keep their
// clusters from frame to frame; the others start afresh each frame, as they
// would in a renderer), the reference per frame, per-frame metrics and the
// flicker of each method.
//
// flicker = mean over the frames f >= 1 of
//   mean_i ((A_f - A_{f-1})_i - (R_f - R_{f-1})_i)^2 / (mean(R_f) mean(A_f)),
// the NMSE between the method's frame-to-frame difference and the
// reference's, normalised by the frame's means as NMSE is (a difference image
// has a mean near 0, so its own means cannot normalise): 0 when the method
// changes from frame to frame exactly as the converged light does. Frames
// where the walls are nearly dark (a narrow downlight pointing at the floor)
// have tiny means and dominate it; flicker_seq normalises every frame by the
// sequence's mean reference level instead: mean_f mean_i (dA - dR)^2 /
// (mean_f mean(R_f))^2.
#pragma once

#include "cl/runtime.h"
#include "methods/render.h"
#include "photometry/table.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace lb::experiments {

// The light's path: "rotate" sweeps R from `from` to `to` (default pi/2 ->
// pi) at the scene's height; "lift" moves the light's height from `from` to
// `to` (a translation along z) at the scene's rotation.
struct SequencePath {
    std::string kind = "rotate";
    double from = 1.5707963267948966, to = 3.141592653589793;
    int frames = 8;
};

// The scene of frame f (0 .. frames-1), the path's parameter linear in f.
Scene sequenceFrame(const Scene& base, const SequencePath& path, int f);

struct SequenceOptions {
    std::string referenceSpec = "reference";
    methods::RenderOptions render;  // the reference's cache and progress
    int reps = 1;  // timed launches per frame (after the frame's image)
};

// Runs the path for every method SPEC; returns the record: {"path", "frames":
// [{"param", "methods": {spec: {"time_ms", metrics...}}}], "flicker": {spec: v}, "flicker_seq": {spec: v},
// "mean": {spec: {"nmse", "time_ms"}}}.
nlohmann::json runSequence(ocl::Runtime& rt, const photometry::Table& table, const Scene& base,
                           const SequencePath& path, const std::vector<std::string>& specs, methods::Precision p,
                           const SequenceOptions& opt);

}  // namespace lb::experiments
