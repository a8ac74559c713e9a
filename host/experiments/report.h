// report.h -- DIR/report.md and DIR/plots/ from DIR/results.json, so results
// can be re-reported and re-plotted without re-running (`lumibench report DIR`).
#pragma once

#include <string>

namespace lb::experiments {

// Runs plots/experiment.py (with $LUMIBENCH_PYTHON, default /usr/bin/python3)
// on DIR, which writes DIR/plots/*.png. Returns "" on success, else why not
// (no python, no matplotlib, script failed): the report says so.
std::string makePlots(const std::string& dir);

// Writes DIR/report.md: device and driver, the main tables (mean NMSE, then
// grad_nmse and FLIP, over the rotations per luminaire, height and method,
// the equal-time MCI beside the method it matches; a metric no record carries
// gets a line saying so), relative run times (paper Table 1: median time over
// the point light's), the equal-time pairs with all three metrics, and the
// plots found in DIR/plots.
// `plotNote` (from makePlots) is printed when the plots are missing.
void writeReport(const std::string& dir, const std::string& plotNote = "");

} // namespace lb::experiments
