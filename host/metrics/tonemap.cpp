#include "metrics/tonemap.h"

#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lb::tonemap {

double tonemapValue(double E, double k)
{
    if (!std::isfinite(E)) return std::numeric_limits<double>::quiet_NaN();
    const double L = std::max(0.0, k * E);
    return L / (1.0 + L);
}

uint8_t toByte(double v) { return static_cast<uint8_t>(std::lround(255.0 * std::clamp(v, 0.0, 1.0))); }

double defaultK(const Image& reference)
{
    double sum = 0;
    for (double v : reference.px) sum += v;
    const double mean = sum / static_cast<double>(reference.px.size());
    if (!(mean > 0) || !std::isfinite(mean))
        throw InputError(
            fmt::format("cannot choose the tone-mapping scale k = 1/mean(reference): the mean is {}", mean));
    return 1.0 / mean;
}

Picture tonemapPicture(const Image& E, double k)
{
    Picture p(E.width, E.height);
    for (size_t i = 0; i < E.px.size(); ++i) {
        const double v = tonemapValue(E.px[i], k);
        const uint8_t g = toByte(v);
        p.px[i] = std::isfinite(v) ? Rgb8{g, g, g} : kNonFinite;
    }
    return p;
}

namespace {
// CIELAB (D65) of an 8-bit sRGB colour and back (IEC 61966-2-1, CIE 15).
struct Lab {
    double L, a, b;
};
const double kWhiteXyz[3] = {0.95047, 1.0, 1.08883};
const double kToXyz[3][3] = {{0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};
const double kToRgb[3][3] = {{3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};

Lab labOf(Rgb8 c)
{
    const double rgb[3] = {c.r / 255.0, c.g / 255.0, c.b / 255.0};
    double lin[3], f[3];
    for (int i = 0; i < 3; ++i) lin[i] = rgb[i] <= 0.04045 ? rgb[i] / 12.92 : std::pow((rgb[i] + 0.055) / 1.055, 2.4);
    for (int i = 0; i < 3; ++i) {
        const double t = (kToXyz[i][0] * lin[0] + kToXyz[i][1] * lin[1] + kToXyz[i][2] * lin[2]) / kWhiteXyz[i];
        f[i] = t > 216.0 / 24389.0 ? std::cbrt(t) : t * 841.0 / 108.0 + 4.0 / 29.0;
    }
    return {116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2])};
}

Rgb8 rgbOf(Lab c)
{
    const double fy = (c.L + 16) / 116, f[3] = {fy + c.a / 500, fy, fy - c.b / 200};
    double xyz[3], out[3];
    for (int i = 0; i < 3; ++i)
        xyz[i] = kWhiteXyz[i] * (f[i] > 6.0 / 29.0 ? f[i] * f[i] * f[i] : (f[i] - 4.0 / 29.0) * 108.0 / 841.0);
    for (int i = 0; i < 3; ++i) {
        const double v = std::clamp(kToRgb[i][0] * xyz[0] + kToRgb[i][1] * xyz[1] + kToRgb[i][2] * xyz[2], 0.0, 1.0);
        out[i] = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
    }
    return {toByte(out[0]), toByte(out[1]), toByte(out[2])};
}

// White blended towards `c` by t in [0, 1] along a straight line in CIELAB:
// equal steps of t are equal colour differences (Delta E 1976).
Rgb8 fromWhite(Rgb8 c, double t)
{
    if (t <= 0) return kWhite;
    if (t >= 1) return c;
    const Lab w = labOf(kWhite), e = labOf(c);
    return rgbOf({w.L + t * (e.L - w.L), w.a + t * (e.a - w.a), w.b + t * (e.b - w.b)});
}
}  // namespace

Rgb8 errorColour(double d, double overBound, double underBound)
{
    if (!std::isfinite(d)) return kNonFinite;
    if (d > 0 && overBound > 0) return fromWhite(kOrange, std::min(1.0, d / overBound));
    if (d < 0 && underBound > 0) return fromWhite(kBlue, std::min(1.0, -d / underBound));
    return kWhite;
}

Picture errorPicture(const Image& reference, const Image& test, double overBound, double underBound)
{
    if (reference.width != test.width || reference.height != test.height)
        throw InputError(fmt::format("image sizes differ: reference is {}x{}, test is {}x{}", reference.width,
                                     reference.height, test.width, test.height));
    Picture p(test.width, test.height);
    for (size_t i = 0; i < test.px.size(); ++i)
        p.px[i] = errorColour(test.px[i] - reference.px[i], overBound, underBound);
    return p;
}

}  // namespace lb::tonemap
