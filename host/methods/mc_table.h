// mc_table.h -- the table sampler's buffer (kernels/common/mc_table.h): the
// luminaire's cells over (C, 1 - cos gamma), weighted by solid angle times the
// largest corner intensity plus a floor, as an integer summed-area table.
#pragma once

#include "photometry/table.h"

#include <vector>

namespace lb::methods {

// The share of the largest cell intensity every cell's weight gets on top
// (so the sampler's density is positive in every direction: where the
// profile is dark it samples by solid angle).
inline constexpr double kMcTableFloor = 1e-5;
// The largest cell side in degrees (in C and in gamma): the table's steps are
// split to it, so that a window covers the light's directions closely.
inline constexpr double kMcTableStep = 2.5;

// The float buffer `tab` of kernels/mc.cl for table t (layout:
// kernels/common/mc_table.h). Throws Error where the table has more cells than
// the summed-area table can hold exactly in float (2^22).
std::vector<float> mcTableSampler(const photometry::Table& t);

}  // namespace lb::methods
