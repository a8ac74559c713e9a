// base64.h -- RFC 4648 base64 (the pictures and float samples that
// report.html and the SVG figures carry inline).
#pragma once

#include <cstddef>
#include <string>

namespace lb::util {

inline std::string base64(const void* data, size_t n)
{
    static const char kB64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const auto* p = static_cast<const unsigned char*>(data);
    std::string o;
    o.reserve((n + 2) / 3 * 4);
    for (size_t i = 0; i < n; i += 3) {
        unsigned v = unsigned(p[i]) << 16 | (i + 1 < n ? unsigned(p[i + 1]) << 8 : 0u) | (i + 2 < n ? p[i + 2] : 0u);
        o += kB64[v >> 18 & 63];
        o += kB64[v >> 12 & 63];
        o += i + 1 < n ? kB64[v >> 6 & 63] : '=';
        o += i + 2 < n ? kB64[v & 63] : '=';
    }
    return o;
}

}  // namespace lb::util
