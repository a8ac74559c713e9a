#include "util/check.h"

#include "util/error.h"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>

namespace lb::util {

namespace {

std::string withUnit(const std::string& unit) { return unit.empty() ? "" : " " + unit; }

// An unsigned decimal number: digits with at most one '.', no sign or exponent.
bool unsignedDecimal(const std::string& s, double& v)
{
    if (s.empty() || s.find_first_not_of("0123456789.") != std::string::npos) return false;
    auto r = std::from_chars(s.data(), s.data() + s.size(), v, std::chars_format::fixed);
    return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(v);
}

}  // namespace

double checkRange(const std::string& name, double v, double lo, double hi, const std::string& unit)
{
    if (!(v >= lo && v <= hi))  // false for nan
        throw InputError(fmt::format("{}: expected a number in [{}, {}]{}, got {}", name, lo, hi, withUnit(unit), v));
    return v;
}

long checkIntRange(const std::string& name, long v, long lo, long hi, const std::string& unit)
{
    if (v < lo || v > hi)
        throw InputError(fmt::format("{}: expected an integer in [{}, {}]{}, got {}", name, lo, hi, withUnit(unit), v));
    return v;
}

double parseReal(const std::string& name, const std::string& text)
{
    double v = 0;
    const char* b = text.data();
    const char* e = b + text.size();
    if (b != e && *b == '+') ++b;
    auto r = std::from_chars(b, e, v, std::chars_format::general);
    if (text.empty() || r.ec != std::errc() || r.ptr != e || !std::isfinite(v))
        throw InputError(fmt::format("{}: expected a finite number, got '{}'", name, text));
    return v;
}

double parseAngle(const std::string& name, const std::string& text)
{
    std::string s;
    for (char ch : text)
        if (!std::isspace(static_cast<unsigned char>(ch))) s += ch;
    auto bad = [&]() -> double {
        throw InputError(fmt::format("{}: expected radians in [0, 2pi] as a number or C*pi/D with unsigned C and "
                                     "D > 0 (e.g. 2.356, pi, 3pi/4), got '{}'",
                                     name, text));
    };
    double v;
    if (auto p = s.find("pi"); p != std::string::npos) {
        std::string coef = s.substr(0, p), rest = s.substr(p + 2);
        if (!coef.empty() && coef.back() == '*') coef.pop_back();
        double c = 1;
        if (!coef.empty() && !unsignedDecimal(coef, c)) return bad();
        v = c * 3.14159265358979323846;
        if (!rest.empty()) {
            double d = 0;
            if (rest[0] != '/' || !unsignedDecimal(rest.substr(1), d) || !(d > 0)) return bad();
            v /= d;
        }
    } else {
        double d = 0;
        const char* b = s.data();
        auto r = std::from_chars(b, b + s.size(), d, std::chars_format::general);
        if (s.empty() || r.ec != std::errc() || r.ptr != b + s.size() || !std::isfinite(d)) return bad();
        v = d;
    }
    if (!(v >= 0 && v <= kTwoPi * (1 + 1e-15)))  // 2pi as written rounds up by at most an ulp
        throw InputError(fmt::format("{}: expected radians in [0, 2pi], got '{}' = {}", name, text, v));
    return v;
}

namespace {

// Offset of the first byte of `s` that is not part of a well-formed UTF-8
// sequence (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF), or npos.
size_t firstBadUtf8(const std::string& s)
{
    const auto* b = reinterpret_cast<const unsigned char*>(s.data());
    for (size_t i = 0, n = s.size(); i < n;) {
        const unsigned c = b[i];
        size_t len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        if (len == 0 || i + len > n || (len == 2 && c < 0xC2)) return i;
        for (size_t k = 1; k < len; ++k)
            if ((b[i + k] & 0xC0) != 0x80) return i;
        if (len == 3) {
            const unsigned cp = ((c & 0x0F) << 12) | ((b[i + 1] & 0x3F) << 6) | (b[i + 2] & 0x3F);
            if (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF)) return i;
        }
        if (len == 4) {
            const unsigned cp = ((c & 0x07) << 18) | ((b[i + 1] & 0x3F) << 12) | ((b[i + 2] & 0x3F) << 6);
            if (cp < 0x10000 || cp > 0x10FFFF) return i;
        }
        i += len;
    }
    return std::string::npos;
}

}  // namespace

const std::string& requireUtf8(const std::string& name, const std::string& what)
{
    const size_t bad = firstBadUtf8(name);
    if (bad == std::string::npos) return name;
    std::string shown;
    for (unsigned char c : name) shown += c >= 0x20 && c < 0x7F ? std::string(1, char(c)) : fmt::format("\\x{:02x}", c);
    throw InputError(fmt::format("{}: {}'s name is not valid UTF-8 (byte 0x{:02x} at offset {}); expected a UTF-8 "
                                 "name: rename the file",
                                 shown, what, static_cast<unsigned char>(name[bad]), bad));
}

}  // namespace lb::util
