#include "photometry/text.h"

#include "util/error.h"
#include "util/fileio.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace lb::photometry {

TextFile TextFile::fromString(const std::string& path, const std::string& text)
{
    TextFile f;
    f.path = path;
    std::string cur;
    for (size_t i = 0; i < text.size(); ++i) {
        char ch = text[i];
        if (ch == '\n' || ch == '\r') {
            f.lines.push_back(cur);
            cur.clear();
            if (ch == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
        } else {
            cur.push_back(ch);
        }
    }
    if (!cur.empty()) f.lines.push_back(cur);
    return f;
}

TextFile TextFile::read(const std::string& path)
{
    // Refuses a directory and stops reading at the limit (a /dev/zero ends there).
    std::string text = util::readFile(path, "a luminaire file", kMaxFileBytes);
    if (text.empty()) throw InputError(fmt::format("{}:1: expected a luminaire file, got an empty file", path));
    return fromString(path, text);
}

void TextFile::fail(size_t line, const std::string& what, const std::string& got) const
{
    throw InputError(fmt::format("{}:{}: expected {}, got {}", path, line, what, got));
}

std::string quote(const std::string& token)
{
    std::string s = "\"";
    size_t n = 0;
    for (unsigned char ch : token) {
        if (++n > 40) {
            s += "...";
            break;
        }
        if (ch < 0x20 || ch >= 0x7f)
            s += fmt::format("\\x{:02x}", ch);
        else
            s.push_back(static_cast<char>(ch));
    }
    return s + "\"";
}

bool parseNumber(const std::string& token, double& out, bool decimalComma)
{
    std::string t = token;
    if (decimalComma && t.find('.') == std::string::npos) {
        auto k = t.find(',');
        if (k != std::string::npos && t.find(',', k + 1) == std::string::npos) t[k] = '.';
    }
    size_t b = (!t.empty() && t[0] == '+') ? 1 : 0;
    if (b == t.size()) return false;
    // from_chars: locale-independent; only plain decimal / exponent notation.
    const char* first = t.data() + b;
    const char* last = t.data() + t.size();
    if (*first != '-' && *first != '.' && !std::isdigit(static_cast<unsigned char>(*first))) return false;
    auto r = std::from_chars(first, last, out, std::chars_format::general);
    return r.ec == std::errc() && r.ptr == last && std::isfinite(out);
}

static std::string trim(const std::string& s)
{
    size_t a = s.find_first_not_of(" \t\f\v");
    if (a == std::string::npos) return "";
    size_t b = s.find_last_not_of(" \t\f\v");
    return s.substr(a, b - a + 1);
}

std::string LineCursor::text(const std::string& what)
{
    if (atEnd()) f_.fail(f_.lines.size() + 1, what, "end of file");
    return trim(f_.lines[i_++]);
}

double LineCursor::number(const std::string& what, bool decimalComma)
{
    size_t line = lineNo();
    std::string t = text(what);
    double v;
    if (!parseNumber(t, v, decimalComma)) f_.fail(line, what, t.empty() ? "an empty line" : quote(t));
    return v;
}

int LineCursor::integer(const std::string& what, int lo, int hi)
{
    size_t line = lineNo();
    std::string t = text(what);
    double v;
    if (!parseNumber(t, v, true) || v != std::floor(v) || v < lo || v > hi)
        f_.fail(line, fmt::format("{} (an integer in [{}, {}])", what, lo, hi), t.empty() ? "an empty line" : quote(t));
    return static_cast<int>(v);
}

bool TokenCursor::fill()
{
    while (line_ < f_.lines.size()) {
        const std::string& l = f_.lines[line_];
        while (pos_ < l.size() && (std::isspace(static_cast<unsigned char>(l[pos_])) || (commaSep_ && l[pos_] == ',')))
            ++pos_;
        if (pos_ < l.size()) return true;
        ++line_;
        pos_ = 0;
    }
    return false;
}

bool TokenCursor::atEnd() { return !fill(); }

std::string TokenCursor::token(const std::string& what)
{
    if (!fill()) f_.fail(f_.lines.size() + 1, what, "end of file");
    const std::string& l = f_.lines[line_];
    size_t a = pos_;
    while (pos_ < l.size() && !std::isspace(static_cast<unsigned char>(l[pos_])) && !(commaSep_ && l[pos_] == ','))
        ++pos_;
    tokLine_ = line_ + 1;
    return l.substr(a, pos_ - a);
}

double TokenCursor::number(const std::string& what)
{
    std::string t = token(what);
    double v;
    if (!parseNumber(t, v, decComma_)) f_.fail(tokLine_, what, quote(t));
    return v;
}

void TokenCursor::requireRoom(double count, const std::string& what, size_t declLine)
{
    fill();
    double left = 0;  // characters from the cursor to the end of the file, line ends included
    for (size_t l = line_; l < f_.lines.size(); ++l) left += double(f_.lines[l].size() + 1);
    left -= double(pos_);
    // At most one number per byte: a loose bound, so that a file cut short by
    // a few values still names the line where it ends, while a count the
    // file cannot possibly hold fails here, before its arrays are allocated.
    if (count > left)
        f_.fail(declLine,
                fmt::format("{} that the rest of the file can hold (at most {:.0f} numbers in {:.0f} bytes)", what,
                            left, left),
                fmt::format("{:.0f} numbers", count));
}

double absoluteCandela(const TextFile& f, size_t line, double raw, double scale, const std::string& what)
{
    const double v = raw * scale;
    if (!(v >= 0 && v <= kMaxCandela))
        f.fail(line, fmt::format("{} in [0, {:g}] cd after the file's multipliers (x {:g})", what, kMaxCandela, scale),
               fmt::format("{:g} cd", v));
    return v;
}

int TokenCursor::integer(const std::string& what, int lo, int hi)
{
    std::string t = token(what);
    double v;
    if (!parseNumber(t, v, decComma_) || v != std::floor(v) || v < lo || v > hi)
        f_.fail(tokLine_, fmt::format("{} (an integer in [{}, {}])", what, lo, hi), quote(t));
    return static_cast<int>(v);
}

}  // namespace lb::photometry
