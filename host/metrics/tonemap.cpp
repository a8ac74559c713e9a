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
// White blended towards `c` by t in [0, 1].
Rgb8 fromWhite(Rgb8 c, double t)
{
    auto mix = [t](uint8_t x) { return static_cast<uint8_t>(std::lround(255.0 + t * (x - 255.0))); };
    return {mix(c.r), mix(c.g), mix(c.b)};
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
