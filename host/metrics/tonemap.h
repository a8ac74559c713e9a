// tonemap.h -- pictures for people (docs/design.md section 5, thesis 6.2): tone-mapped
// irradiance and signed error pictures, as pure functions from images to 8-bit
// RGB. PNG files are written by metrics/png.h.
#pragma once

#include "metrics/image.h"

#include <cstdint>
#include <vector>

namespace lb::tonemap {

struct Rgb8 {
    uint8_t r = 0, g = 0, b = 0;
    bool operator==(const Rgb8& o) const { return r == o.r && g == o.g && b == o.b; }
};

// An 8-bit RGB picture, row-major, row 0 at the top (same layout as lb::Image).
struct Picture {
    int width = 0, height = 0;
    std::vector<Rgb8> px;
    Picture() = default;
    Picture(int w, int h) : width(w), height(h), px(static_cast<size_t>(w) * h) {}
    Rgb8& at(int row, int col) { return px[static_cast<size_t>(row) * width + col]; }
    const Rgb8& at(int row, int col) const { return px[static_cast<size_t>(row) * width + col]; }
};

// Colours of the pictures. Orange: too bright; blue: too dark; white: no error
// (thesis 6.2, Fig. 6.5). The two ends have the same CIELAB lightness (L* 54.2
// and 54.7), so that errors of equal size look equally strong on either side,
// and stay apart under protan, deutan and tritan colour vision (orange turns
// olive or pink, blue stays blue; tests/metrics/test_tonemap.cpp). Magenta
// marks a non-finite test pixel in every picture, so that it is seen and never
// passes for black or white.
inline constexpr Rgb8 kWhite{255, 255, 255};
inline constexpr Rgb8 kOrange{213, 94, 0};
inline constexpr Rgb8 kBlue{0, 128, 255};
inline constexpr Rgb8 kNonFinite{255, 0, 255};

// Display value in [0, 1] of irradiance E: L / (1 + L) with L = k E (thesis
// Eq. 6.8 with the scale a / L_w replaced by a fixed k, as the thesis does to
// keep pictures comparable). Negative E shows as 0. NaN for non-finite E.
double tonemapValue(double E, double k);

// Rounds a display value in [0, 1] to 0..255 (clamped; no further gamma: the
// tone-mapped value is the display value, as in the thesis' figures).
uint8_t toByte(double v);

// Default k of a figure: 1 / mean(reference), so that the mean irradiance of
// the reference shows as grey 0.5. Throws lb::InputError when the reference
// mean is not positive or not finite (a black reference needs an explicit k).
double defaultK(const Image& reference);

// Grey picture of E tone mapped with k; non-finite pixels in kNonFinite.
Picture tonemapPicture(const Image& E, double k);

// Colour of a signed error d = A - R: white at 0, blending to orange at d =
// +overBound and to blue at d = -underBound (both > 0, magnitudes in lux),
// saturated beyond; the blend is linear in CIELAB (perceptually uniform: equal
// steps of |d| are equal colour differences, lightness falls linearly). A zero bound means nothing to show on that side:
// the colour stays white. kNonFinite for non-finite d.
Rgb8 errorColour(double d, double overBound, double underBound);

// Error picture of test against reference, pixel by pixel errorColour(A - R).
// Throws lb::InputError when the sizes differ.
Picture errorPicture(const Image& reference, const Image& test, double overBound, double underBound);

}  // namespace lb::tonemap
