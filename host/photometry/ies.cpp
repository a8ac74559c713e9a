// IES LM-63 layout: a version line (absent in LM-63-1986), keyword lines
// ("[KEY] text", free form, may continue with [MORE]) up to the line
// "TILT=NONE|INCLUDE|<file>"; with INCLUDE: geometry, N, N angles, N factors.
// Then numbers, separated by blanks (or commas) and split over lines freely:
// lamps, lumens/lamp, multiplier, Nv, Nh, photometric type, units (1 ft, 2 m),
// width, length, height; ballast factor, ballast-lamp factor (1995: "future
// use"), input watts; Nv vertical angles; Nh horizontal angles; Nh x Nv candela
// (vertical fastest).
#include "photometry/ies.h"

#include "photometry/symmetry.h"
#include "photometry/text.h"
#include "util/error.h"
#include "util/fileio.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

namespace lb::photometry {

Table readIes(const std::string& path, IesExtra* extra) { return readIes(TextFile::read(path), extra); }

static std::string trimmed(const std::string& s)
{
    size_t a = s.find_first_not_of(" \t");
    if (a == std::string::npos) return "";
    return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// The first token like "12,5" (digits, one comma, digits) on lines from
// `first` (0-based) on, as (1-based line, token); (0, "") if none. IES
// separates numbers by blanks or commas, so a decimal comma splits one number
// into two and the reader's first complaint (angles not ascending, a count
// off) would hide the cause.
static std::pair<size_t, std::string> decimalComma(const TextFile& f, size_t first)
{
    for (size_t l = first; l < f.lines.size(); ++l) {
        std::istringstream in(f.lines[l]);
        std::string t;
        while (in >> t) {
            auto k = t.find(',');
            if (k == std::string::npos || k == 0 || k + 1 == t.size() || t.find(',', k + 1) != std::string::npos)
                continue;
            double v;
            if (parseNumber(t, v, true) && std::isdigit(static_cast<unsigned char>(t[k - 1])) &&
                std::isdigit(static_cast<unsigned char>(t[k + 1])))
                return {l + 1, t};
        }
    }
    return {0, ""};
}

static Table readIesBody(const TextFile& f, IesExtra* extraOut);

Table readIes(const TextFile& f, IesExtra* extraOut)
{
    try {
        return readIesBody(f, extraOut);
    } catch (const InputError& e) {
        size_t tilt = 0;
        while (tilt < f.lines.size() && trimmed(f.lines[tilt]).rfind("TILT", 0) != 0) ++tilt;
        auto [line, token] = decimalComma(f, tilt + 1);
        if (line == 0) throw;
        throw InputError(fmt::format("{}:{}: expected '.' as the decimal mark (IES LM-63 separates numbers by blanks "
                                     "or commas), got a decimal comma in {} (the reader then stopped at: {})",
                                     f.path, line, quote(token), e.what()));
    }
}

namespace {

// The numbers after the TILT data: the counts, types and sizes the table needs.
struct IesCounts {
    int nv = 0, nh = 0;
    size_t countLine = 0;  // of Nv, where a count too large for the file is reported
    int units = 2;  // 1 feet, 2 metres
    double width = 0, length = 0, height = 0;  // signed, in the file's units
    size_t widthLine = 0;
};

// The version (line 1) and the TILT= line with its data; returns the cursor
// at the numbers after them.
TokenCursor readTilt(const TextFile& f, IesExtra& x)
{
    size_t i = 0;
    if (!f.lines.empty()) {
        std::string first = trimmed(f.lines[0]);
        if (first.rfind("IES", 0) == 0) x.version = first;
    }
    while (i < f.lines.size() && trimmed(f.lines[i]).rfind("TILT", 0) != 0) ++i;
    if (i == f.lines.size())
        f.fail(f.lines.size() + 1, "a TILT= line (IES LM-63)", f.lines.empty() ? "an empty file" : "end of file");
    std::string tiltLine = trimmed(f.lines[i]);
    auto eq = tiltLine.find('=');
    std::string tilt = eq == std::string::npos ? "" : trimmed(tiltLine.substr(eq + 1));
    TokenCursor in(f, i + 1, true, false);
    if (tilt == "NONE") {
        x.tilt = "NONE";
    } else if (tilt == "INCLUDE") {
        x.tilt = "INCLUDE";
        x.tiltGeometry = in.integer("the TILT lamp-to-luminaire geometry", 1, 3);
        int n = in.integer("the number of TILT angle-factor pairs", 1, kMaxAngles);
        x.tiltAngles.resize(n);
        x.tiltFactors.resize(n);
        // Lamp tilt angles in degrees: 0 .. 180, strictly increasing (a table
        // interpolated in them).
        for (int k = 0; k < n; ++k) {
            size_t l = in.lineNo();
            x.tiltAngles[k] = in.number(fmt::format("TILT angle {} of {}", k + 1, n));
            if (!(x.tiltAngles[k] >= 0 && x.tiltAngles[k] <= 180))
                f.fail(l, "a TILT angle in [0, 180] degrees", fmt::format("{}", x.tiltAngles[k]));
            if (k > 0 && !(x.tiltAngles[k] > x.tiltAngles[k - 1]))
                f.fail(l, fmt::format("TILT angles strictly increasing (after {})", x.tiltAngles[k - 1]),
                       fmt::format("{}", x.tiltAngles[k]));
        }
        for (int k = 0; k < n; ++k) {
            size_t l = in.lineNo();
            x.tiltFactors[k] = in.number(fmt::format("TILT factor {} of {}", k + 1, n));
            // A multiplier of the candela values: 0 .. 10 (real tables stay near 1).
            if (!(x.tiltFactors[k] >= 0 && x.tiltFactors[k] <= 10))
                f.fail(l, "a TILT factor in [0, 10]", fmt::format("{}", x.tiltFactors[k]));
        }
    } else {
        f.fail(i + 1, "TILT=NONE or TILT=INCLUDE (a TILT file is not supported)", quote(tiltLine));
    }
    return in;
}

// A number that must be > 0.
double positive(TokenCursor& in, const TextFile& f, const std::string& what)
{
    size_t l = in.lineNo();
    double v = in.number("the " + what);
    if (!(v > 0)) f.fail(l, "a " + what + " > 0", fmt::format("{}", v));
    return v;
}

// The two lines of numbers after the TILT data (lamps .. input watts).
IesCounts readCounts(TokenCursor& in, const TextFile& f, IesExtra& x)
{
    IesCounts c;
    x.lamps = in.integer("the number of lamps", -1000000, 1000000);
    x.lampLumens = in.number("the lumens per lamp (-1 = absolute)");
    x.multiplier = positive(in, f, "candela multiplier");
    c.countLine = in.lineNo();
    c.nv = in.integer("the number of vertical angles", 2, kMaxAngles);
    c.nh = in.integer("the number of horizontal angles", 1, kMaxAngles);
    size_t l = in.lineNo();
    x.photometricType = in.integer("the photometric type (1 = C)", 1, 3);
    if (x.photometricType == 2)
        f.fail(l, "photometric type 1 (C); type B (2, floodlights) is not supported, convert it to type C", "2");
    if (x.photometricType == 3) f.fail(l, "photometric type 1 (C); type A (3) is not supported", "3");
    c.units = in.integer("the units type (1 feet, 2 metres)", 1, 2);
    c.widthLine = in.lineNo();
    c.width = in.number("the luminous width");
    c.length = in.number("the luminous length");
    c.height = in.number("the luminous height");
    x.ballastFactor = positive(in, f, "ballast factor");
    x.ballastLampFactor = positive(in, f, "ballast-lamp photometric factor");
    x.inputWatts = in.number("the input watts");
    return c;
}

// n angles, each ascending after the previous one.
std::vector<double> ascending(TokenCursor& in, const TextFile& f, int n, const char* name)
{
    std::vector<double> a(n);
    for (int k = 0; k < n; ++k) {
        size_t l = in.lineNo();
        a[k] = in.number(fmt::format("{} angle {} of {}", name, k + 1, n));
        if (k > 0 && !(a[k] > a[k - 1]))
            f.fail(l, fmt::format("{} angles ascending (after {})", name, a[k - 1]), fmt::format("{}", a[k]));
    }
    return a;
}

// The symmetry (Isym as EULUMDAT numbers it) of a set of horizontal angles.
int symmetryOf(const std::vector<double>& h, const TextFile& f, size_t line)
{
    double h0 = h.front(), h1 = h.back();
    if (h.size() == 1 && h0 == 0) return 1;
    if (h0 == 0 && h1 == 90) return 4;
    if (h0 == 0 && h1 == 180) return 2;
    if (h0 == 90 && h1 == 270) return 3;
    if (h0 == 0 && h1 > 180 && h1 <= 360) return 0;
    f.fail(line, "horizontal angles {0}, 0-90, 0-180, 90-270, 0-360 or 0 to (180, 360)", fmt::format("{}-{}", h0, h1));
}

// The Nh x Nv candela values (vertical fastest), times scale, then the end of the file.
std::vector<std::vector<double>> readCandela(TokenCursor& in, const TextFile& f, const IesCounts& c,
                                             const std::vector<double>& h, double scale)
{
    const int nv = c.nv, nh = c.nh;
    // Angles are at most kMaxAngles each; the Nh x Nv table is what could be
    // large, so its count is checked against the file before it is allocated.
    in.requireRoom(double(nv) * nh, fmt::format("Nh x Nv = {} x {} candela values", nh, nv), c.countLine);
    std::vector<std::vector<double>> planes(nh, std::vector<double>(nv));
    for (int p = 0; p < nh; ++p)
        for (int k = 0; k < nv; ++k) {
            size_t l = in.lineNo();
            double v = in.number(fmt::format("candela {} of {} at horizontal angle {}", k + 1, nv, h[p]));
            if (v < 0) f.fail(l, "a candela value >= 0", fmt::format("{}", v));
            planes[p][k] = absoluteCandela(f, l, v, scale, "a candela value");
        }
    if (!in.atEnd()) {
        size_t l = in.lineNo();
        f.fail(l, fmt::format("the end of the file after the {} x {} candela values", nh, nv), quote(in.token("")));
    }
    return planes;
}

// The luminous opening from the signed width, length and height.
Opening opening(const TextFile& f, const IesCounts& c)
{
    const double toM = c.units == 1 ? 0.3048 : 1.0;
    Opening o;
    if (!openingFromIes(c.width * toM, c.length * toM, c.height * toM, o))
        f.fail(c.widthLine,
               "luminous width, length and height with the signs of a shape of LM-63-2019 Table 1 (all >= 0: "
               "rectangle; width < 0: round shapes)",
               fmt::format("width {}, length {}, height {}", c.width, c.length, c.height));
    return o;
}

}  // namespace

static Table readIesBody(const TextFile& f, IesExtra* extraOut)
{
    IesExtra x;
    TokenCursor in = readTilt(f, x);
    const IesCounts c = readCounts(in, f, x);
    std::vector<double> v = ascending(in, f, c.nv, "vertical");
    if (!((v.front() == 0 || v.front() == 90) && (v.back() == 90 || v.back() == 180) && v.front() < v.back()))
        f.fail(in.lastLine(), "vertical angles 0-90, 90-180 or 0-180", fmt::format("{}-{}", v.front(), v.back()));
    std::vector<double> h = ascending(in, f, c.nh, "horizontal");
    const size_t hLine = in.lastLine();
    const int isym = symmetryOf(h, f, hLine);
    const double scale = x.multiplier * x.ballastFactor * x.ballastLampFactor;
    std::vector<std::vector<double>> planes = readCandela(in, f, c, h, scale);

    // A full set that stores 360 keeps its own 360 plane; one that stops short
    // gets 360 = 0 (unfold).
    Table t = unfold(isym, h, v, planes, fmt::format("{}:{}", f.path, hLine));
    t.source = f.path;
    t.format = "ies";
    t.isym = isym;
    t.symmetry = symmetryName(isym);
    t.opening = opening(f, c);
    if (x.tilt == "INCLUDE") t.tilt = {x.tiltGeometry, x.tiltAngles, x.tiltFactors};
    t.validate();
    if (extraOut) *extraOut = x;
    return t;
}

static std::string num(double v) { return fmt::format("{}", v); }

std::string iesText(const Table& t, const std::string& name, const std::string& origin)
{
    t.validate();
    bool rotational = t.nc() == 2;  // one plane read, one plane written
    for (size_t ic = 1; ic < t.nc() && rotational; ++ic)
        for (size_t ig = 0; ig < t.ng(); ++ig)
            if (t.at(ic, ig) != t.at(0, ig)) rotational = false;
    size_t nh = rotational ? 1 : t.nc();
    std::string s;
    auto line = [&](const std::string& x) { s += x + "\r\n"; };
    line("IESNA:LM-63-2002");
    line("[TEST] " + name);
    line("[MANUFAC] lumibench");
    line("[LUMINAIRE] " + name + " (generated by " + origin + ")");
    line("[OTHER] absolute photometry");
    // Values ten to a line, as the standard recommends (lines <= 256 chars).
    auto block = [&](auto get, size_t n) {
        std::string cur;
        for (size_t i = 0; i < n; ++i) {
            cur += (cur.empty() ? "" : " ") + num(get(i));
            if ((i + 1) % 10 == 0 || i + 1 == n) {
                line(cur);
                cur.clear();
            }
        }
    };
    if (t.tilt.anglesDeg.empty()) {
        line("TILT=NONE");
    } else {
        line("TILT=INCLUDE");
        line(std::to_string(t.tilt.geometry));
        line(std::to_string(t.tilt.anglesDeg.size()));
        block([&](size_t i) { return t.tilt.anglesDeg[i]; }, t.tilt.anglesDeg.size());
        block([&](size_t i) { return t.tilt.factors[i]; }, t.tilt.factors.size());
    }
    double w, l, h;
    iesDimensions(t.opening, w, l, h);
    line(fmt::format("1 -1 1 {} {} 1 2 {} {} {}", t.ng(), nh, num(w), num(l), num(h)));
    line("1 1 0");
    block([&](size_t i) { return t.gamma[i]; }, t.ng());
    block([&](size_t i) { return t.c[i]; }, nh);
    for (size_t ic = 0; ic < nh; ++ic) block([&](size_t i) { return t.at(ic, i); }, t.ng());
    return s;
}

void writeIes(const Table& t, const std::string& path, const std::string& name, const std::string& origin)
{
    util::writeFileAtomic(path, iesText(t, name, origin));
}

}  // namespace lb::photometry
