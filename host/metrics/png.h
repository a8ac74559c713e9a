// png.h -- 8-bit RGB PNG files of tone-mapped and error pictures (libpng).
#pragma once

#include "metrics/tonemap.h"

#include <string>

namespace lb {

// The bytes of an 8-bit sRGB PNG of `pic`.
std::string encodePng(const tonemap::Picture& pic);
// Writes encodePng(pic) to `path` atomically (util/fileio.h); throws
// lb::Error naming the file on failure.
void writePng(const std::string& path, const tonemap::Picture& pic);
// Reads any PNG as 8-bit RGB; throws lb::InputError naming the file.
tonemap::Picture readPng(const std::string& path);

}  // namespace lb
