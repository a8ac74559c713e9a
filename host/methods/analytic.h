// analytic.h -- luminaires given by a formula, for tests and for trying the
// renderer before a file is at hand: I(gamma) = I0 cos^n(gamma) on the emitting
// side (gamma <= 90), 0 behind (or |cos|^n on both sides), rotationally
// symmetric, tabulated at 0.1 degree in gamma so that the bilinear table is
// within 1.3e-7 n^2 (relative) of the formula.
#pragma once

#include "photometry/table.h"

#include <string>

namespace lb::methods {

photometry::Table cosineTable(int n, double i0 = 1000.0, bool twoSided = false);

// "analytic:cos<n>[:two]" (e.g. analytic:cos1 = Lambertian) -> the table; other
// strings -> photometry::load(path).
photometry::Table loadLuminaire(const std::string& pathOrAnalytic);

} // namespace lb::methods
