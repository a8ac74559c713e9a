#include "metrics/image.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace lb {
namespace {

TEST(Exr, WriteReadRoundTripIsExactInFloat)
{
    Image a(7, 5);
    for (size_t i = 0; i < a.px.size(); ++i) a.px[i] = 0.1 * i + 1e-3;
    auto path = (std::filesystem::temp_directory_path() / "lb_test_roundtrip.exr").string();
    writeExr(path, a);
    Image b = readExr(path);
    ASSERT_EQ(b.width, 7);
    ASSERT_EQ(b.height, 5);
    for (size_t i = 0; i < a.px.size(); ++i) EXPECT_EQ(b.px[i], static_cast<double>(static_cast<float>(a.px[i])));
    std::remove(path.c_str());
}

TEST(Exr, MissingOrBadFileIsAnInputError)
{
    EXPECT_THROW(readExr("/nonexistent/file.exr"), InputError);
    auto path = (std::filesystem::temp_directory_path() / "lb_test_garbage.exr").string();
    std::ofstream(path) << "not an exr";
    EXPECT_THROW(readExr(path), InputError);
    std::remove(path.c_str());
}

}  // namespace
}  // namespace lb
