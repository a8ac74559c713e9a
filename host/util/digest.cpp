#include "util/digest.h"

#include <fmt/format.h>

namespace lb::util {

std::string Digest::hex() const { return fmt::format("{:016x}", h); }

std::string digestHex(const std::string& bytes) { return Digest().bytes(bytes.data(), bytes.size()).hex(); }

}  // namespace lb::util
