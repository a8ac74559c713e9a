// report.h -- DIR/report.md, DIR/report.html and DIR/plots/ from
// DIR/results.json, so results can be re-reported and re-plotted without
// re-running (`lumibench report DIR`).
#pragma once

#include "experiments/report_bounds.h"

#include <map>
#include <string>

namespace lb::experiments {

// Runs plots/experiment.py (with $LUMIBENCH_PYTHON, default /usr/bin/python3)
// on DIR, which writes DIR/plots/*.png. Returns "" on success, else why not
// (no python, no matplotlib, script failed): the report says so.
std::string makePlots(const std::string& dir);

// Writes DIR/report.md and DIR/report.html, the same tables in both (built
// once, rendered twice): device, driver, commit and date; the main tables
// (NMSE and grad_nmse of the rotations stitched into one image,
// metrics::pooled, and the pixel mean of FLIP, per luminaire, precision,
// height and method, the equal-time MCI beside the method it matches; a
// metric no record carries gets a line saying so), relative run times (paper
// Table 1: median time over the point light's), the equal-time pairs with all
// three metrics, and the plots found in DIR/plots.
//
// report.html is one self-contained file (nothing fetched; the plots and
// pictures inline as data): its tables sort by a click on a column head, and
// for each scene with saved pictures (DIR/images/<scene>/) a viewer switches
// between reference, method, its error picture, MCI at equal time and MCI's
// error (keys 1-5 or a click on the picture; the arrow keys change scene and
// method), zooms on the near field (the image centre, under the light; keys
// + and -) and changes the tone-mapping exposure (keys [ and ]). Its initial
// view comes from the URL fragment, e.g. report.html#scene=0&view=mci&zoom=4;
// keys, clicks and the fragment go through one function. At most
// kMaxInlineBytes of pictures are inlined; later scenes are left out, and the
// page says how many.
//
// Its error pictures are drawn at one symmetric bound per scene, with a
// colour bar in lux and in % of the reference mean: `scales`, or where null
// the bounds of shareErrorBounds (which redraws DIR/images/).
//
// `plotNote` (from makePlots) is printed when the plots are missing.
void writeReport(const std::string& dir, const std::string& plotNote = "",
                 const std::map<std::string, SceneScale>* scales = nullptr);

struct ReportSteps {
    std::string tag;  // the progress lines' prefix, "[tag] report ..." (the experiment's name)
    bool progress = true;  // a line per stage on stderr, with the seconds since the start
    std::string plotNote;  // non-empty: no plots, and this says why (e.g. "--no-plots")
};

// The report step of `run` and `report`: the error pictures on one bound per
// scene (shareErrorBounds), the plots (makePlots; its image grids use those
// pictures) and writeReport, a progress line per stage.
void makeReport(const std::string& dir, const ReportSteps& steps);

inline constexpr size_t kMaxInlineBytes = size_t(48) << 20;

}  // namespace lb::experiments
