// text.h -- line-tracking reading of luminaire text files, shared by the
// EULUMDAT and IES readers, so that every complaint reads
//     FILE:LINE: expected WHAT, got TOKEN
// and ends the program with exit code 2 (lb::InputError).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace lb::photometry {

// Counts read from a file are capped before anything is allocated from them.
constexpr int kMaxAngles = 10000;
// Files larger than this are not luminaires (the largest real ones are ~100 kB).
constexpr size_t kMaxFileBytes = 16u << 20;
// Largest absolute candela accepted (after every multiplier). Real luminaires
// stay below 1e7 cd; the kernels compute I cos / r^2 in float (max 3.4e38),
// so 1e20 keeps that finite down to r = 1e-9 m while leaving 13 orders of
// magnitude above any real file.
constexpr double kMaxCandela = 1e20;

struct TextFile;
// `raw` x `scale` (the file's multipliers) as absolute candela; fails at
// `line` unless the product is finite, >= 0 and <= kMaxCandela.
double absoluteCandela(const TextFile& f, size_t line, double raw, double scale, const std::string& what);

// A file split into lines (\n, \r\n or a lone \r end a line; the ends are dropped).
struct TextFile {
    std::string path;
    std::vector<std::string> lines;

    static TextFile read(const std::string& path);  // throws InputError if unreadable
    static TextFile fromString(const std::string& path, const std::string& text);

    // Throws InputError("PATH:LINE: expected WHAT, got GOT"); line is 1-based.
    [[noreturn]] void fail(size_t line, const std::string& what, const std::string& got) const;
};

// How a token looks in a message: quoted, shortened, control bytes escaped.
std::string quote(const std::string& token);

// Strict number parsing: the whole token must be a finite decimal number.
// decimalComma accepts "12,5" (EULUMDAT). Returns false when it is not one.
bool parseNumber(const std::string& token, double& out, bool decimalComma);

// Reads a file line by line (EULUMDAT: one field per line).
class LineCursor {
public:
    explicit LineCursor(const TextFile& f, size_t firstLine = 0) : f_(f), i_(firstLine) {}
    bool atEnd() const { return i_ >= f_.lines.size(); }
    size_t lineNo() const { return i_ + 1; }  // of the next line
    size_t index() const { return i_; }
    // The next line, trimmed; at the end of the file fails with "expected WHAT".
    std::string text(const std::string& what);
    double number(const std::string& what, bool decimalComma = true);
    // An integer in [lo, hi].
    int integer(const std::string& what, int lo, int hi);

private:
    const TextFile& f_;
    size_t i_;
};

// Reads whitespace-separated tokens across lines (IES: numbers may be split
// over lines arbitrarily; commas also separate). Can start from a line index.
class TokenCursor {
public:
    TokenCursor(const TextFile& f, size_t firstLine, bool commaSeparates, bool decimalComma)
        : f_(f), line_(firstLine), commaSep_(commaSeparates), decComma_(decimalComma)
    {
    }
    bool atEnd();  // no token left
    size_t lineNo()
    {
        fill();
        return line_ + 1;
    }  // of the next token
    size_t lastLine() const { return tokLine_; }  // of the token read last
    // Fails at `declLine` unless the rest of the file can hold `count` more
    // numbers (at most one per byte), so that declared counts are checked
    // against the file's size before anything is allocated from them.
    void requireRoom(double count, const std::string& what, size_t declLine);
    std::string token(const std::string& what);
    double number(const std::string& what);
    int integer(const std::string& what, int lo, int hi);

private:
    bool fill();
    const TextFile& f_;
    size_t line_;
    size_t pos_ = 0;
    bool commaSep_, decComma_;
    size_t tokLine_ = 0;
};

}  // namespace lb::photometry
