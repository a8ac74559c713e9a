#include "util/digest.h"

#include <fmt/format.h>

namespace lb::util {

std::string Digest::hex() const { return fmt::format("{:016x}", h); }

std::string digestHex(const std::string& bytes) { return Digest().bytes(bytes.data(), bytes.size()).hex(); }

std::string shortName(const std::string& name, size_t max)
{
    if (name.size() <= max) return name;
    const std::string tail = "-" + digestHex(name);
    size_t keep = max > tail.size() ? max - tail.size() : 0;
    while (keep > 0 && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80) --keep;  // a continuation byte
    return name.substr(0, keep) + tail;
}

}  // namespace lb::util
