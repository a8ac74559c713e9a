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

// Generated file names (a scene's folder, a cell's pictures) are at most this
// many bytes, which leaves room below the file systems' 255 for the suffixes
// written after them ("_test.png", ".tmp.PID.SEQ").
constexpr size_t kMaxNameBytes = 200;

// `name` itself when it has at most `max` bytes; else its first bytes (cut at
// a UTF-8 character's start), '-' and digestHex(name): `max` bytes in all, and
// two long names that differ anywhere stay apart.
std::string shortName(const std::string& name, size_t max = kMaxNameBytes);

}  // namespace lb::util
