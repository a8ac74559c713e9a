// test_tables.h -- synthetic luminaires the specialisation and Monte Carlo
// tests share, and their scenes.
#pragma once

#include "photometry/load.h"
#include "scene/scene.h"

#include <cmath>
#include <string>

namespace lb::methods::test_tables {

// A rotational luminaire emitting only forward (cos^3 lobe): every rule fires.
inline photometry::Table frontLobe()
{
    return photometry::tabulate(
        [](double, double g) { return g < 90 ? 500 * std::pow(std::cos(g * M_PI / 180), 3) : 0.0; }, 2, 91);
}
// An asymmetric luminaire emitting into both hemispheres: only noHorizon.
inline photometry::Table asymmetric()
{
    return photometry::tabulate(
        [](double c, double g) { return 100 + 80 * std::cos(c * M_PI / 180) * std::sin(g * M_PI / 180) + g; }, 25, 37);
}

// Emits into both hemispheres, with azimuthal structure and kinks on a
// 10-degree grid (so no sampler is exact on it).
inline photometry::Table lumpy()
{
    const double d = M_PI / 180;
    return photometry::tabulate(
        [&](double c, double g) {
            double cg = std::cos(g * d);
            return 300 * cg * cg * (g < 90 ? 1.0 : 0.2) + 200 * std::sin(g * d) * (1 + 0.5 * std::cos(c * d)) + 20;
        },
        37, 19);
}

// A scene of `kind` with the light at height h and rotation rot, res pixels per side.
inline Scene sceneAt(SceneKind kind, double h, double rot, int res)
{
    Scene s;
    s.kind = kind;
    s.height = h;
    s.rotation = rot;
    s.res = res;
    return s;
}

// Whether an mc spec samples the projected solid angle (projected, mis): the
// azimuth inversion stops within a few ulp of the projected area's terms, and
// two kernels' operation orders may stop it one step apart (next to the
// horizon, where the area is a difference of arcs many times itself: a few
// 1e-5 of a pixel, tests/methods/test_mc_straight.cpp).
inline bool samplesProjected(const std::string& spec)
{
    return spec.find("domain=projected") != std::string::npos || spec.find("domain=mis,") != std::string::npos;
}

}  // namespace lb::methods::test_tables
