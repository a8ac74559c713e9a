// libpng's simplified API (png_image): no setjmp, errors come back in
// image.message.
#include "metrics/png.h"

#include "util/error.h"
#include "util/fileio.h"

#include <fmt/format.h>
#include <png.h>

#include <cstring>

namespace lb {

static_assert(sizeof(tonemap::Rgb8) == 3, "Rgb8 must be packed RGB bytes for libpng");

std::string encodePng(const tonemap::Picture& pic)
{
    png_image img;
    std::memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = static_cast<png_uint_32>(pic.width);
    img.height = static_cast<png_uint_32>(pic.height);
    img.format = PNG_FORMAT_RGB;
    png_alloc_size_t size = 0;
    // First call: the size; second: the bytes.
    if (!png_image_write_to_memory(&img, nullptr, &size, 0, pic.px.data(), 0, nullptr))
        throw Error(fmt::format("cannot encode a {} x {} PNG: {}", pic.width, pic.height, img.message));
    std::string out(size, '\0');
    if (!png_image_write_to_memory(&img, out.data(), &size, 0, pic.px.data(), 0, nullptr))
        throw Error(fmt::format("cannot encode a {} x {} PNG: {}", pic.width, pic.height, img.message));
    out.resize(size);
    return out;
}

void writePng(const std::string& path, const tonemap::Picture& pic) { util::writeFileAtomic(path, encodePng(pic)); }

tonemap::Picture readPng(const std::string& path)
{
    png_image img;
    std::memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path.c_str()))
        throw InputError(fmt::format("{}: cannot read PNG: {}", path, img.message));
    img.format = PNG_FORMAT_RGB;
    tonemap::Picture pic(static_cast<int>(img.width), static_cast<int>(img.height));
    if (!png_image_finish_read(&img, nullptr, pic.px.data(), 0, nullptr)) {
        png_image_free(&img);
        throw InputError(fmt::format("{}: cannot read PNG: {}", path, img.message));
    }
    return pic;
}

}  // namespace lb
