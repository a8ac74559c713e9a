// colour_bar.h -- one error scale for pictures that are compared (tonemap.h
// errorColour at one symmetric bound) and its labelled colour bar: the bound,
// the bar's colours and tick values in lux and relative to the reference
// mean, and an SVG figure of a picture with its bar.
#pragma once

#include "metrics/image.h"

#include <string>
#include <vector>

namespace lb::tonemap {

// The quantile of |error| a shared bound is taken at (sharedBound): at most
// 0.1 % of any picture's pixels saturate, so one outlier pixel does not pale
// the rest of the picture.
inline constexpr double kBoundQuantile = 0.999;

// |test - reference| at quantile q in [0, 1] over the pixels where both are
// finite (the sorted values' index ceil(q (n - 1)), so that at most a share
// 1 - q of them lies above it); 0 when there are none. Throws lb::InputError
// when the sizes differ.
double errorQuantile(const Image& reference, const Image& test, double q);

// One symmetric bound (lux) for error pictures that are to be compared with
// each other (a scene's methods and MCI at equal time): the largest of their
// kBoundQuantile quantiles of |error|; where that is 0 (every picture exact
// but for fewer than 0.1 % of its pixels), the largest |error|, so that those
// pixels still show. 0 when every picture is exact.
double sharedBound(const Image& reference, const std::vector<const Image*>& tests);

// The colour bar: errorColour(t B, B, B) at t = -1 .. +1 in n >= 2 equal
// steps, as "#rrggbb" (the viewer's and the figures' scale, one map).
std::vector<std::string> colourBar(int n);

struct Tick {
    double t;  // position on the bar, -1 (left, -bound) .. +1 (right, +bound)
    std::string lux;  // "-4 lx", "0", "+2 lx"
    std::string relative;  // "-40 %" of the reference mean ("" when the mean is not positive)
};

// Ticks at -bound, -bound/2, 0, +bound/2, +bound (three significant digits,
// whole numbers from 1000 on: "+8420 %", never an exponent).
std::vector<Tick> barTicks(double bound, double meanRef);

// An SVG figure: the error picture (its PNG bytes, width x height pixels)
// above its colour bar with the ticks of barTicks in lux and in % of the
// reference mean, and a line saying what saturates. Self-contained (the PNG
// inline as data).
std::string errorFigureSvg(const std::string& png, int width, int height, double bound, double meanRef);

}  // namespace lb::tonemap
