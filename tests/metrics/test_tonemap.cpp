// Tone mapping (thesis Eq. 6.8 with a fixed k), error colours and PNG files.
#include "metrics/png.h"
#include "metrics/colour_bar.h"
#include "metrics/tonemap.h"
#include "util/error.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

namespace lb {
namespace {

using tonemap::Rgb8;

// Per-process names: several checkouts may run the suite on one machine at once.
std::string tmp(const std::string& name)
{
    return (std::filesystem::temp_directory_path() / (std::to_string(getpid()) + "_" + name)).string();
}

TEST(Tonemap, ReinhardCurveWithFixedK)
{
    // L/(1+L): L = 1 -> 1/2, L = 3 -> 3/4, L = 0 -> 0; one or two roundings: 4 ulp.
    EXPECT_DOUBLE_EQ(tonemap::tonemapValue(1.0, 1.0), 0.5);
    EXPECT_DOUBLE_EQ(tonemap::tonemapValue(30.0, 0.1), 0.75);
    EXPECT_EQ(tonemap::tonemapValue(0.0, 10.0), 0.0);
    EXPECT_EQ(tonemap::tonemapValue(-5.0, 1.0), 0.0);  // negative irradiance shows black
    EXPECT_TRUE(std::isnan(tonemap::tonemapValue(std::numeric_limits<double>::infinity(), 1.0)));
    EXPECT_EQ(tonemap::toByte(0.5), 128);  // 127.5 rounds half away from zero
    EXPECT_EQ(tonemap::toByte(0.0), 0);
    EXPECT_EQ(tonemap::toByte(1.0), 255);
    EXPECT_EQ(tonemap::toByte(2.0), 255);  // clamped
}

TEST(Tonemap, DefaultKMapsTheReferenceMeanToHalfGrey)
{
    Image r(2, 2);
    r.px = {1, 2, 3, 4};
    EXPECT_DOUBLE_EQ(tonemap::defaultK(r), 0.4);  // 1 / 2.5, one division: 4 ulp
    auto p = tonemap::tonemapPicture(r, 0.4);
    // E = 1: L = 0.4, 0.4/1.4 = 0.2857 -> 72.86 -> 73; E = 4: 1.6/2.6 -> 156.9 -> 157.
    EXPECT_EQ(p.at(0, 0), (Rgb8{73, 73, 73}));
    EXPECT_EQ(p.at(1, 1), (Rgb8{157, 157, 157}));
    EXPECT_THROW(tonemap::defaultK(Image(3, 3, 0.0)), InputError);
}

TEST(Tonemap, NonFinitePixelsAreMagenta)
{
    Image r(2, 1);
    r.px = {std::numeric_limits<double>::quiet_NaN(), 1.0};
    auto p = tonemap::tonemapPicture(r, 1.0);
    EXPECT_EQ(p.at(0, 0), tonemap::kNonFinite);
    EXPECT_EQ(p.at(0, 1), (Rgb8{128, 128, 128}));
}

// CIELAB (D65) of an 8-bit sRGB colour, and of one seen with a colour vision
// deficiency: Machado, Oliveira and Fernandes (2009), severity 1, a matrix on
// linear RGB. Written here apart from tonemap.cpp's own conversion.
struct Lab {
    double L, a, b;
};
double linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
Lab labOfLinear(const double l[3])
{
    const double M[3][3] = {{0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};
    const double w[3] = {0.95047, 1.0, 1.08883};
    double f[3];
    for (int i = 0; i < 3; ++i) {
        const double t = std::clamp(M[i][0] * l[0] + M[i][1] * l[1] + M[i][2] * l[2], 0.0, 2.0) / w[i];
        f[i] = t > std::pow(6.0 / 29, 3) ? std::cbrt(t) : t / (3 * std::pow(6.0 / 29, 2)) + 4.0 / 29;
    }
    return {116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2])};
}
using Cvd = std::array<std::array<double, 3>, 3>;
const Cvd kNormal{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
const Cvd kProtan{{{0.152286, 1.052583, -0.204868}, {0.114503, 0.786281, 0.099216}, {-0.003882, -0.048116, 1.051998}}};
const Cvd kDeutan{{{0.367322, 0.860646, -0.227968}, {0.280085, 0.672501, 0.047413}, {-0.011820, 0.042940, 0.968881}}};
const Cvd kTritan{{{1.255528, -0.076749, -0.178779}, {-0.078411, 0.930809, 0.147602}, {0.004733, 0.691367, 0.303900}}};
Lab labOf(Rgb8 c, const Cvd& m = kNormal)
{
    const double l[3] = {linear(c.r / 255.0), linear(c.g / 255.0), linear(c.b / 255.0)};
    double s[3];
    for (int i = 0; i < 3; ++i) s[i] = std::clamp(m[i][0] * l[0] + m[i][1] * l[1] + m[i][2] * l[2], 0.0, 1.0);
    return labOfLinear(s);
}
double deltaE(Lab x, Lab y) { return std::hypot(x.L - y.L, x.a - y.a, x.b - y.b); }

// What a diverging error map needs, for `colour(t)` at t in [-1, 1] (negative:
// too dark), as a list of failures (empty: all hold).
std::vector<std::string> divergingFailures(const std::function<Rgb8(double)>& colour)
{
    std::vector<std::string> out;
    const int steps = 16;
    for (int side : {1, -1}) {
        // perceptually uniform: equal steps of |t| are equal colour differences
        // (within 25 %: 8-bit rounding, about 0.3 Delta E on steps of about 5.5,
        // and sRGB's gamut at the saturated blue end)
        double lo = 1e9, hi = 0;
        for (int i = 0; i < steps; ++i) {
            const double d =
                deltaE(labOf(colour(side * i / double(steps))), labOf(colour(side * (i + 1) / double(steps))));
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
        if (hi > 1.25 * lo) out.push_back(fmt::format("side {}: steps of {:.2f} to {:.2f} Delta E", side, lo, hi));
    }
    // equal errors equally strong: the two sides' lightness alike (1.5 L*: under
    // a just noticeable difference of about 2)
    for (int i = 1; i <= steps; ++i) {
        const double t = i / double(steps), dl = labOf(colour(t)).L - labOf(colour(-t)).L;
        if (std::abs(dl) > 1.5) out.push_back(fmt::format("t {}: lightness {:.1f} apart", t, dl));
    }
    // under each colour vision deficiency: each side still darkens with |t|
    // (the size reads right), and the two sides stay apart from |t| = 1/4 on
    // (Delta E 20: unmistakable, ten times a just noticeable difference)
    for (const auto& [name, m] : {std::pair{"protan", kProtan}, {"deutan", kDeutan}, {"tritan", kTritan}}) {
        for (int i = 0; i < steps; ++i)
            for (int side : {1, -1})
                if (labOf(colour(side * (i + 1) / double(steps)), m).L >= labOf(colour(side * i / double(steps)), m).L)
                    out.push_back(fmt::format("{}: side {} not darker at step {}", name, side, i + 1));
        for (int i = steps / 4; i <= steps; ++i) {
            const double t = i / double(steps), d = deltaE(labOf(colour(t), m), labOf(colour(-t), m));
            if (d < 20) out.push_back(fmt::format("{}: sides {:.1f} Delta E apart at |t| {}", name, d, t));
        }
    }
    return out;
}

// White blended in sRGB bytes to `over` at t = 1 and to `under` at t = -1.
std::function<Rgb8(double)> srgbBlend(Rgb8 over, Rgb8 under)
{
    return [=](double t) {
        const Rgb8 e = t >= 0 ? over : under;
        auto mix = [&](uint8_t x) { return static_cast<uint8_t>(std::lround(255.0 + std::abs(t) * (x - 255.0))); };
        return Rgb8{mix(e.r), mix(e.g), mix(e.b)};
    };
}

TEST(ErrorColour, MapIsPerceptuallyUniformAndSurvivesColourBlindness)
{
    const auto map = [](double t) { return tonemap::errorColour(t, 1.0, 1.0); };
    const auto failures = divergingFailures(map);
    EXPECT_TRUE(failures.empty()) << fmt::format("{}", fmt::join(failures, "\n"));
    // The checks can fail. The former map (sRGB blends to (255,128,0) and
    // (0,102,255)): uneven steps, ends 19 L* apart.
    const auto old = divergingFailures(srgbBlend({255, 128, 0}, {0, 102, 255}));
    EXPECT_TRUE(
        std::any_of(old.begin(), old.end(), [](const std::string& f) { return f.find("lightness") != f.npos; }));
    EXPECT_TRUE(std::any_of(old.begin(), old.end(), [](const std::string& f) { return f.find("steps of") != f.npos; }));
    // Red against green: apart in normal vision, 5.6 Delta E for a deutan.
    const auto rg = divergingFailures(srgbBlend({200, 80, 0}, {80, 150, 0}));
    EXPECT_TRUE(
        std::any_of(rg.begin(), rg.end(), [](const std::string& f) { return f.find("deutan: sides") != f.npos; }));
}

TEST(ErrorColour, WhiteOrangeBlue)
{
    EXPECT_EQ(tonemap::errorColour(0.0, 2.0, 1.0), tonemap::kWhite);
    EXPECT_EQ(tonemap::errorColour(2.0, 2.0, 1.0), tonemap::kOrange);  // at UEB: saturated
    EXPECT_EQ(tonemap::errorColour(50.0, 2.0, 1.0), tonemap::kOrange);  // beyond: stays saturated
    EXPECT_EQ(tonemap::errorColour(-1.0, 2.0, 1.0), tonemap::kBlue);  // at |LEB|
    EXPECT_EQ(tonemap::errorColour(-9.0, 2.0, 1.0), tonemap::kBlue);
    // Half way to orange and a quarter way to blue, in CIELAB: white (100, 0, 0)
    // + t (end - white). The 8-bit rounding moves a colour by at most half a
    // step per channel, under 1 Delta E here.
    auto near = [](Rgb8 got, double t, Rgb8 end) {
        const Lab w = labOf(tonemap::kWhite), e = labOf(end), g = labOf(got);
        return deltaE(g, {w.L + t * (e.L - w.L), w.a + t * (e.a - w.a), w.b + t * (e.b - w.b)});
    };
    EXPECT_LT(near(tonemap::errorColour(1.0, 2.0, 1.0), 0.5, tonemap::kOrange), 1.0);
    EXPECT_LT(near(tonemap::errorColour(-0.25, 2.0, 1.0), 0.25, tonemap::kBlue), 1.0);
    // A zero bound: nothing on that side to scale by, white (no division by zero).
    EXPECT_EQ(tonemap::errorColour(1.0, 0.0, 1.0), tonemap::kWhite);
    EXPECT_EQ(tonemap::errorColour(std::numeric_limits<double>::quiet_NaN(), 1.0, 1.0), tonemap::kNonFinite);
}

TEST(ErrorColour, PictureOfSignedErrors)
{
    Image r(3, 1), a(3, 1);
    r.px = {1, 1, 1};
    a.px = {1, 3, 0};  // no error, +2 (= UEB), -1 (= LEB)
    auto p = tonemap::errorPicture(r, a, 2.0, 1.0);
    EXPECT_EQ(p.at(0, 0), tonemap::kWhite);
    EXPECT_EQ(p.at(0, 1), tonemap::kOrange);
    EXPECT_EQ(p.at(0, 2), tonemap::kBlue);
    EXPECT_THROW(tonemap::errorPicture(r, Image(1, 3), 1, 1), InputError);
}

// One bound for a scene's pictures: the 99.9th percentile of each picture's
// |error|, the largest over the pictures. One outlier pixel among 2000 does
// not set it (it would pale the rest 100x); below 0.1 % of exact pixels the
// largest error sets it; a sign does not matter.
TEST(ErrorBound, SharedBoundIgnoresOneOutlierPixelAndTakesTheWorstPicture)
{
    Image r(2000, 1, 10.0), a(2000, 1, 10.0), b(2000, 1, 10.0), c(2000, 1, 10.0);
    for (int i = 0; i < 2000; ++i) {
        a.px[i] = 10.0 + (i % 2 ? 1.0 : -1.0);  // |error| 1 everywhere
        b.px[i] = 10.0 - 3.0 * (i % 2);  // |error| 3 on half of the pixels, too dark
    }
    a.px[7] = 110.0;  // one outlier pixel: +100
    EXPECT_DOUBLE_EQ(tonemap::errorQuantile(r, a, 1.0), 100.0);
    EXPECT_DOUBLE_EQ(tonemap::errorQuantile(r, a, tonemap::kBoundQuantile), 1.0);
    EXPECT_DOUBLE_EQ(tonemap::sharedBound(r, {&a}), 1.0);
    EXPECT_DOUBLE_EQ(tonemap::sharedBound(r, {&a, &b}), 3.0);  // the worst picture's scale for both
    EXPECT_DOUBLE_EQ(tonemap::sharedBound(r, {&b, &a}), 3.0);
    c.px[3] = 12.5;  // exact but for one pixel: that pixel's error
    EXPECT_DOUBLE_EQ(tonemap::sharedBound(r, {&c}), 2.5);
    EXPECT_DOUBLE_EQ(tonemap::sharedBound(r, {&r}), 0.0);
    a.px[8] = std::numeric_limits<double>::quiet_NaN();  // non-finite pixels are left out
    EXPECT_DOUBLE_EQ(tonemap::errorQuantile(r, a, tonemap::kBoundQuantile), 1.0);
    EXPECT_THROW(tonemap::errorQuantile(r, Image(3, 3), 0.5), InputError);
    // The bar: 33 colours from full blue over white to full orange.
    const auto bar = tonemap::colourBar(33);
    ASSERT_EQ(bar.size(), 33u);
    EXPECT_EQ(bar.front(), "#0080ff");
    EXPECT_EQ(bar[16], "#ffffff");
    EXPECT_EQ(bar.back(), "#d55e00");
}

TEST(Png, WriteReadRoundTripIsExact)
{
    tonemap::Picture p(5, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            p.at(y, x) =
                Rgb8{static_cast<uint8_t>(50 * x), static_cast<uint8_t>(100 * y), static_cast<uint8_t>(7 + x + y)};
    auto path = tmp("lb_test_roundtrip.png");
    writePng(path, p);
    auto q = readPng(path);  // libpng reading it back: 8-bit RGB is lossless
    ASSERT_EQ(q.width, 5);
    ASSERT_EQ(q.height, 3);
    for (size_t i = 0; i < p.px.size(); ++i) EXPECT_EQ(q.px[i], p.px[i]) << i;
    std::remove(path.c_str());
}

TEST(Png, ErrorPictureReadBackHasTheExpectedColours)
{
    Image r(2, 2, 4.0), a(2, 2);
    a.px = {4.0, 6.0, 1.0, 5.0};  // white, orange (+2 = bound), blue (-3 = bound), half orange
    auto path = tmp("lb_test_err.png");
    writePng(path, tonemap::errorPicture(r, a, 2.0, 3.0));
    auto q = readPng(path);
    EXPECT_EQ(q.at(0, 0), (Rgb8{255, 255, 255}));
    EXPECT_EQ(q.at(0, 1), (Rgb8{213, 94, 0}));
    EXPECT_EQ(q.at(1, 0), (Rgb8{0, 128, 255}));
    EXPECT_EQ(q.at(1, 1), tonemap::errorColour(1.0, 2.0, 3.0));
    std::remove(path.c_str());
}

TEST(Png, BadFilesAreErrors)
{
    EXPECT_THROW(readPng("/nonexistent/x.png"), InputError);
    auto path = tmp("lb_test_garbage.png");
    std::ofstream(path) << "not a png";
    EXPECT_THROW(readPng(path), InputError);
    std::remove(path.c_str());
    EXPECT_THROW(writePng("/nonexistent/dir/x.png", tonemap::Picture(1, 1)), Error);
}

}  // namespace
}  // namespace lb
