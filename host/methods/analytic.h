// analytic.h -- luminaires given by a formula, for tests and for trying the
// renderer before a file is at hand: I(gamma) = I0 cos^n(gamma) on the emitting
// side (gamma <= 90), 0 behind (or |cos|^n on both sides), rotationally
// symmetric, tabulated every stepDeg in gamma. The bilinear table differs from
// the formula by about (step in rad)^2 / 8 * |f''/f|, and f''/f of cos^n grows
// like n (n-1) tan^2(gamma) towards 90 degrees: at step 0.1 deg that is
// 4e-7 n^2 (1 + tan^2) relative -- fine head-on, large at grazing angles.
#pragma once

#include "photometry/table.h"

#include <string>

namespace lb::methods {

photometry::Table cosineTable(int n, double i0 = 1000.0, bool twoSided = false, double stepDeg = 0.1);

// "analytic:cos<n>[:two]" (e.g. analytic:cos1 = Lambertian) -> the table; other
// strings -> photometry::load(path), refused (photometry::requireNoTilt) when
// the file's TILT=INCLUDE table would change the candela values. The table's
// `opening` is what the file declares; the scene does not use it yet.
photometry::Table loadLuminaire(const std::string& pathOrAnalytic);

}  // namespace lb::methods
