// symmetry.h -- unfolding the planes a file stores into the full table over
// C in [0, 360] (docs/design.md section 3). Both readers describe their data with the
// EULUMDAT symmetry indicator:
//   0 none (planes over [0, 360), or [0, 360] when the file repeats 0),
//   1 rotational (one plane), 2 mirror about C0-C180 (planes 0..180),
//   3 mirror about C90-C270 (planes 90..270), 4 both (planes 0..90).
#pragma once

#include "photometry/table.h"

#include <string>
#include <vector>

namespace lb::photometry {

const char* symmetryName(int isym);  // "none", "rotational", "C0-C180", "C90-C270", "quadrant"

// The stored angle that full-table angle c (in [0, 360]) takes its values from.
double foldC(int isym, double c);

// Full table from the stored planes (planes[i] at stored angle c[i], values
// at the gammas). Throws InputError("WHERE: expected ..., got ...") when the
// stored angles do not cover what the symmetry needs (e.g. C90-C270 data
// without the 180 plane). The result has passed Table::validate().
Table unfold(int isym, const std::vector<double>& c, const std::vector<double>& gamma,
             const std::vector<std::vector<double>>& planes, const std::string& where);

}  // namespace lb::photometry
