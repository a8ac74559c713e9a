// digest.h -- content digests: 64-bit FNV-1a, written as 16 hex digits.
// Used wherever a key must change when content changes (the reference cache,
// results records, the program cache); not a cryptographic hash: it detects
// changed and damaged files, not forged ones.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace lb::util {

struct Digest {
    std::uint64_t h = 1469598103934665603ull;
    Digest& bytes(const void* p, size_t n)
    {
        auto* b = static_cast<const unsigned char*>(p);
        for (size_t i = 0; i < n; ++i) {
            h ^= b[i];
            h *= 1099511628211ull;
        }
        return *this;
    }
    // The string and its terminating NUL, so that ("ab", "c") != ("a", "bc").
    Digest& str(const std::string& s) { return bytes(s.data(), s.size() + 1); }
    std::string hex() const;
};

// The digest of `bytes` as 16 hex digits.
std::string digestHex(const std::string& bytes);

}  // namespace lb::util
