// image.h -- irradiance images (lux per pixel) and their OpenEXR files
// (docs/design.md section 5: one FLOAT channel named Y).
#pragma once

#include <string>
#include <vector>

namespace lb {

struct Image {
    int width = 0, height = 0;
    std::vector<double> px;  // row-major, row 0 at the top

    Image() = default;
    Image(int w, int h, double v = 0.0) : width(w), height(h), px(static_cast<size_t>(w) * h, v) {}
    double& at(int row, int col) { return px[static_cast<size_t>(row) * width + col]; }
    double at(int row, int col) const { return px[static_cast<size_t>(row) * width + col]; }
};

// `img` as the bytes of a single-channel FLOAT OpenEXR file (channel "Y").
std::string encodeExr(const Image& img);
// Writes encodeExr(img) to `path` atomically (util/fileio.h: nothing is left
// behind when the write fails); throws lb::Error naming the path.
void writeExr(const std::string& path, const Image& img);
// Reads channel Y of an OpenEXR file; throws lb::InputError naming the file when
// it is missing, unreadable or has no Y channel.
Image readExr(const std::string& path);

}  // namespace lb
