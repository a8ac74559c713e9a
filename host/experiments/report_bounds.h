// report_bounds.h -- one error scale per scene: the error pictures of a
// results directory (DIR/images/<scene>/<cell>_err.png, written by the runner
// at each picture's own extremes) redrawn at one symmetric bound shared by
// the scene's methods and their equal-time MCI partners (tonemap::sharedBound;
// docs/figures.md says why that bound).
#pragma once

#include "experiments/results.h"

#include <map>
#include <string>

namespace lb::experiments {

// j[key] where it is a string, else `def` (a record's free-form keys).
std::string jsonText(const nlohmann::json& j, const std::string& key, const std::string& def = "");

// A record's role: "equal_time" for a partner, else its `role` ("method",
// "mci_curve"; "method" where it has none).
std::string cellRole(const results::Record& r);

// Gives every record without a `luminaire_name` (those of older runs) the
// name its luminaire file gives it (photometry::displayName of
// luminaire_dir/luminaire, from the results' context), in memory: the report
// and results.csv show it. A file no longer there gives its file name.
void nameLuminaires(results::Results& doc);

struct SceneScale {
    double bound = 0;  // lux: the error pictures saturate at -bound and +bound
    double meanRef = 0;  // lux: the reference's mean (the bar's relative labels)
};

// The picture stem of a record's cell in DIR/images/<scene>/ (no suffix):
// runner.h cellImageName of its role and SPEC (the matched SPEC for a partner).
std::string cellStem(const results::Record& r);

// For every scene of `recs` with DIR/images/<scene>/reference.exr: the bound
// over the EXRs of its method and equal-time cells (the MCI curve's cells do
// not set it, but are redrawn at it), each <cell>_err.png rewritten at it and
// its <cell>.json given `bound`, `mean_ref` and `colour_bar`
// (tonemap::colourBar(33)), for plots/image_grid.py's colour bar. Returns the
// scale per scene label.
std::map<std::string, SceneScale> shareErrorBounds(const std::string& dir, const std::vector<results::Record>& recs);

}  // namespace lb::experiments
