#include "metrics/colour_bar.h"

#include "metrics/tonemap.h"
#include "util/base64.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lb::tonemap {

double errorQuantile(const Image& reference, const Image& test, double q)
{
    if (reference.width != test.width || reference.height != test.height)
        throw InputError(fmt::format("image sizes differ: reference is {}x{}, test is {}x{}", reference.width,
                                     reference.height, test.width, test.height));
    std::vector<double> e;
    e.reserve(test.px.size());
    for (size_t i = 0; i < test.px.size(); ++i) {
        const double d = test.px[i] - reference.px[i];
        if (std::isfinite(d)) e.push_back(std::fabs(d));
    }
    if (e.empty()) return 0;
    const size_t k = static_cast<size_t>(std::ceil(std::clamp(q, 0.0, 1.0) * double(e.size() - 1)));
    std::nth_element(e.begin(), e.begin() + static_cast<std::ptrdiff_t>(k), e.end());
    return e[k];
}

double sharedBound(const Image& reference, const std::vector<const Image*>& tests)
{
    double b = 0, largest = 0;
    for (const Image* t : tests) {
        b = std::max(b, errorQuantile(reference, *t, kBoundQuantile));
        largest = std::max(largest, errorQuantile(reference, *t, 1.0));
    }
    return b > 0 ? b : largest;
}

std::vector<std::string> colourBar(int n)
{
    std::vector<std::string> out;
    for (int i = 0; i < std::max(n, 2); ++i) {
        const Rgb8 c = errorColour(-1.0 + 2.0 * i / double(std::max(n, 2) - 1), 1.0, 1.0);
        out.push_back(fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b));
    }
    return out;
}

namespace {
// +4, -2.5, +8420: three significant digits, whole numbers from 1000 on.
std::string signedText(double v)
{
    if (v == 0) return "0";
    return std::fabs(v) >= 1000 ? fmt::format("{:+.0f}", v) : fmt::format("{:+.3g}", v);
}
}  // namespace

std::vector<Tick> barTicks(double bound, double meanRef)
{
    std::vector<Tick> out;
    for (double t : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
        Tick k{t, signedText(t * bound) + " lx", ""};
        if (meanRef > 0 && std::isfinite(meanRef)) k.relative = signedText(100 * t * bound / meanRef) + " %";
        out.push_back(k);
    }
    return out;
}

std::string errorFigureSvg(const std::string& png, int width, int height, double bound, double meanRef)
{
    // Drawn at 320 px wide (any size: it is a vector figure), the bar below.
    const double W = 320, H = W * height / std::max(width, 1), pad = 40, barY = H + 10, barH = 14;
    const std::vector<std::string> colours = colourBar(65);
    std::ostringstream o;
    o << fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
                     "font-family=\"sans-serif\" font-size=\"10\">\n",
                     W + 2 * pad, barY + barH + 62);
    o << "<defs><linearGradient id=\"bar\" x1=\"0\" x2=\"1\" y1=\"0\" y2=\"0\">";
    for (size_t i = 0; i < colours.size(); ++i)
        o << fmt::format("<stop offset=\"{:.4f}\" stop-color=\"{}\"/>", i / double(colours.size() - 1), colours[i]);
    o << "</linearGradient></defs>\n";
    o << fmt::format("<image x=\"{}\" y=\"0\" width=\"{}\" height=\"{}\" style=\"image-rendering:pixelated\" "
                     "preserveAspectRatio=\"none\" href=\"data:image/png;base64,{}\"/>\n",
                     pad, W, H, util::base64(png.data(), png.size()));
    o << fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"url(#bar)\" stroke=\"#777\" "
                     "stroke-width=\"0.5\"/>\n",
                     pad, barY, W, barH);
    for (const Tick& k : barTicks(bound, meanRef)) {
        const double x = pad + (k.t + 1) / 2 * W;
        o << fmt::format("<line x1=\"{0}\" x2=\"{0}\" y1=\"{1}\" y2=\"{2}\" stroke=\"#333\"/>", x, barY + barH,
                         barY + barH + 4);
        o << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>", x, barY + barH + 15, k.lux);
        if (!k.relative.empty())
            o << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" fill=\"#555\">{}</text>", x,
                             barY + barH + 27, k.relative);
        o << '\n';
    }
    o << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">test - reference in lux (and in % of the "
                     "reference mean {:.3g} lx)</text>\n",
                     pad + W / 2, barY + barH + 43, meanRef);
    o << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">saturated beyond +-{:.3g} lx</text>\n",
                     pad + W / 2, barY + barH + 56, bound);
    o << "</svg>\n";
    return o.str();
}

}  // namespace lb::tonemap
