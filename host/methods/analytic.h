// analytic.h -- luminaires given by a formula, for tests and for trying the
// renderer before a file is at hand: I(gamma) = I0 cos^n(gamma) on the emitting
// side (gamma <= 90), 0 behind (or |cos|^n on both sides), rotationally
// symmetric, tabulated every stepDeg in gamma. The bilinear table differs from
// the formula by about (step in rad)^2 / 8 * |f''/f|, and f''/f of cos^n grows
// like n (n-1) tan^2(gamma) towards 90 degrees: at step 0.1 deg that is
// 4e-7 n^2 (1 + tan^2) relative -- fine head-on, large at grazing angles.
#pragma once

#include "photometry/table.h"
#include "scene/scene.h"

#include <string>

namespace lb::methods {

photometry::Table cosineTable(int n, double i0 = 1000.0, bool twoSided = false, double stepDeg = 0.1);

// "analytic:cos<n>[:two]" (e.g. analytic:cos1 = Lambertian) -> the table; other
// strings -> photometry::load(path), its TILT=INCLUDE table kept (render
// applies it at each scene's rotation: photometry::tiltedFor). The table's
// `opening` is what the file declares (sizeFromFile puts it in a scene).
photometry::Table loadLuminaire(const std::string& pathOrAnalytic);

// The scene's light as the table's file declares it (docs/luminaire-openings.md):
// W the opening's length (along C0-C180, the scene's u), L its width, the
// disk for a circle or an ellipse, the rectangle otherwise; a rectangle with
// luminous sides or a short vertical cylinder by its flat bottom face.
// InputError naming `what` when the file declares no flat opening (a point,
// a sphere, a tall or horizontal cylinder).
void sizeFromFile(const photometry::Table& t, Scene& scene, const std::string& what);

}  // namespace lb::methods
