// The cubature's merge tolerance, closest-point snap and Delaunay flips on a
// light of aspect 100 (1 m x 10 mm), in float and in double: the code the
// kernels run, through host/math/kmath.h (linear_cases.inc). The catalogue's
// linear cases (host/stability/stability.cpp) run the same light through
// every method on the device.
#include "math/kmath.h"
#include "photometry/table.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace lin {
// The exact Lambert irradiance (double) of the 1 m x 10 mm light of
// linear_cases.inc above the horizon of ground point (x, y), normal +z, I =
// 1000 cos gamma; in *sinLow the lowest elevation (sine) of a corner above
// the receiver's horizon.
inline double exactLambert(double h, double R, double x, double y, double* sinLow)
{
    using namespace lb::f64;
    lb::Scene s;
    s.width = 1;
    s.length = 0.01;
    s.height = h;
    s.rotation = R;
    auto P = s.params();
    lb_light L = lb_scene_light(P.data());
    real3 X(x, y, 0), nx(0, 0, 1), poly[LB_MAXV];
    lb_light_corners(L, poly);
    *sinLow = 1;
    for (int i = 0; i < 4; ++i) {
        poly[i] -= X;
        *sinLow = std::min(*sinLow, poly[i].z / length(poly[i]));
    }
    int n = lb_clip_polygon(poly, 4, nx, 0.0);
    bool front = dot(L.n, X - L.c) > 0;
    return (n >= 3 && front) ? 1000 / (L.w * L.l) * lb_polygon_irradiance_lambert(poly, n, nx) : 0;
}
}  // namespace lin

namespace lin32 {
using namespace lb::f32;
constexpr bool kDouble = false;
// Against the double closed form. Measured on the receivers of
// linear_cases.inc: formfactor 3.4e-4 worst (h = 3, R = pi/2, 1.5 mm in front
// of the light's plane; the aspect-1 tests of tests/cubature hold 1e-4), bound
// 1e-3; within 1 mm of the plane or where the light stands < 0.05 (sine)
// above the receiver's horizon, the float Lambert edge sum of a light seen
// edge-on cancels: 8.0e-2 worst (h = 0.001, R = pi, receiver 0.6 m aside),
// bound 0.1 (the kernels shift such receivers to plane_eps, 1 mm, by default).
// Solid angles: 8.8e-4 worst, 1.2e-3 within 1 mm of the plane; bounds 3e-3 and 0.1.
constexpr double kLambertTol = 1e-3;
constexpr double kGrazingTol = 0.1;
constexpr double kOmegaTol = 3e-3;
constexpr double kOmegaAbs = 1e-9;
#define LB_SUITE Stability32
#include "linear_cases.inc"
#undef LB_SUITE
}  // namespace lin32

namespace lin64 {
using namespace lb::f64;
constexpr bool kDouble = true;
// Double: 1e-6 as tests/cubature, grazing receivers included (measured 2e-7;
// solid angles 4.8e-12).
constexpr double kLambertTol = 1e-6;
constexpr double kGrazingTol = 1e-6;
constexpr double kOmegaTol = 1e-8;
constexpr double kOmegaAbs = 1e-14;
#define LB_SUITE Stability64
#include "linear_cases.inc"
#undef LB_SUITE
}  // namespace lin64
