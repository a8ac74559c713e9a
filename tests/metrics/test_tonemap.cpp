// Tone mapping (thesis Eq. 6.8 with a fixed k), error colours and PNG files.
#include "metrics/png.h"
#include "metrics/tonemap.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

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

TEST(ErrorColour, WhiteOrangeBlue)
{
    EXPECT_EQ(tonemap::errorColour(0.0, 2.0, 1.0), tonemap::kWhite);
    EXPECT_EQ(tonemap::errorColour(2.0, 2.0, 1.0), tonemap::kOrange);  // at UEB: saturated
    EXPECT_EQ(tonemap::errorColour(50.0, 2.0, 1.0), tonemap::kOrange);  // beyond: stays saturated
    EXPECT_EQ(tonemap::errorColour(-1.0, 2.0, 1.0), tonemap::kBlue);  // at |LEB|
    EXPECT_EQ(tonemap::errorColour(-9.0, 2.0, 1.0), tonemap::kBlue);
    // Half way to orange (255,128,0): 255 + 0.5 (x - 255) -> (255, 191.5 -> 192, 127.5 -> 128).
    EXPECT_EQ(tonemap::errorColour(1.0, 2.0, 1.0), (Rgb8{255, 192, 128}));
    // A quarter way to blue (0,102,255): (191.25 -> 191, 216.75 -> 217, 255).
    EXPECT_EQ(tonemap::errorColour(-0.25, 2.0, 1.0), (Rgb8{191, 217, 255}));
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
    EXPECT_EQ(q.at(0, 1), (Rgb8{255, 128, 0}));
    EXPECT_EQ(q.at(1, 0), (Rgb8{0, 102, 255}));
    EXPECT_EQ(q.at(1, 1), (Rgb8{255, 192, 128}));
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
