// Host tests of the scattered-sampling cubature (kernels/common/cubature.h),
// in float and in double: the code the kernels run, through host/math/kmath.h.
#include "math/kmath.h"
#include "photometry/table.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <type_traits>
#include <string>
#include <vector>

namespace cub32 {
using namespace lb::f32;
constexpr bool kDouble = false;
// Triangle areas in q are differences of float coordinates of size ~1: the
// sum over <= 19 triangles is exact to a few 1e-7; 1e-5 of the hull area
// leaves margin and also covers the merge tolerance (1e-5 relative) times the
// perimeter when near-duplicate clip vertices are dropped.
constexpr double kAreaTol = 4e-5;
// Van Oosterom-Strackee in float: ~1e-7 relative per triangle, and the
// eps-snaps change the covered area by <= 1e-5 of the light's size.
constexpr double kOmegaTol = 1e-4;
constexpr double kOmegaAbs = 1e-6;
// The bound for float: 1e-4 relative (the ratio of two float sums of
// the same weights; the tabulated cos is exact to 3.8e-7).
constexpr double kLambertTol = 1e-4;
#define LB_SUITE Cubature32
#include "cubature_cases.inc"
#undef LB_SUITE
}  // namespace cub32

namespace cub64 {
using namespace lb::f64;
constexpr bool kDouble = true;
// Double: the same budgets scaled by the merge tolerance 1e-9.
constexpr double kAreaTol = 1e-8;
constexpr double kOmegaTol = 1e-8;
constexpr double kOmegaAbs = 1e-12;
// The bound for double: 1e-6 relative; the table's cos is exact to
// 3.8e-7 relative, the rest is rounding.
constexpr double kLambertTol = 1e-6;
#define LB_SUITE Cubature64
#include "cubature_cases.inc"
#undef LB_SUITE
}  // namespace cub64
