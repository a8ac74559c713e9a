// lut.h -- the trig-free lookup table of kernels/common/lut.h: one luminaire
// resampled once on a uniform grid over the pseudo-angles (q, a), with a
// derived bound on its interpolation error against the exact bilinear lookup.
#pragma once

#include "photometry/table.h"

#include <vector>

namespace lb::photometry {

struct Lut {
    int ng = 0, na = 0;  // cells along pseudo-gamma q and pseudo-azimuth a
    double q0 = 0, q1 = 2;  // pseudo-gamma range = the measured gamma range
    bool rotational = false;  // every C plane equal: a 1D table suffices (LB_LUT_1D)
    std::vector<float> packed;  // kernels/common/lut.h layout
    // Bound on |LUT - exact| (cd) anywhere on the sphere (see buildLut).
    double errorBound = 0;
};

// Pseudo-angles of lut.h for photometric angles in degrees, and back.
double pseudoGamma(double gammaDeg);
double gammaOfPseudo(double q);
double pseudoAzimuth(double cDeg);
double azimuthOfPseudo(double a);

// Every C plane holds the same values (relative 1e-9 of the largest cd).
bool isRotational(const Table& t);
// The luminaire emits nothing at gamma >= 90 deg (measured range ends below
// 90, or every value there is 0): the back hemisphere can be skipped.
bool emitsNoBack(const Table& t);

// Resamples `t` at the (ng + 1) x (na + 1) nodes with the exact bilinear
// lookup. Rotational tables keep na cells too (all columns equal) so that the
// general 2D kernel and the LB_LUT_1D one read the same buffer.
//
// Error bound. The exact lookup f(C, gamma) is bilinear per table cell, so it
// is Lipschitz: |df/dC| <= Sc, |df/dgamma| <= Sg, the largest node-to-node
// slopes of the table (cd per radian). One LUT cell spans at most
// dC = 2 * 4/na rad and dgamma = 2 * (q1 - q0)/ng rad (the pseudo-angles'
// derivative bounds, lut.h), so every point of the cell is within
// Sc dC + Sg dgamma of each of its four nodes, and the bilinear LUT value, a
// convex combination of the node values, is too:
//   |LUT - exact| <= Sc * 8/na + Sg * 2 (q1 - q0)/ng   (+ float rounding).
// The measured range's ends are LUT nodes, so the cut to 0 outside is exact.
Lut buildLut(const Table& t, int ng = 256, int na = 512);

}  // namespace lb::photometry
