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

static Table readIesBody(const TextFile& f, IesExtra* extraOut)
{
    IesExtra x;
    // Header: everything up to the TILT= line.
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
    size_t tiltLineNo = i + 1;
    ++i;
    TokenCursor in(f, i, true, false);
    if (tilt == "NONE") {
        x.tilt = "NONE";
    } else if (tilt == "INCLUDE") {
        x.tilt = "INCLUDE";
        x.tiltGeometry = in.integer("the TILT lamp-to-luminaire geometry", 1, 3);
        int n = in.integer("the number of TILT angle-factor pairs", 1, kMaxAngles);
        x.tiltAngles.resize(n);
        x.tiltFactors.resize(n);
        for (int k = 0; k < n; ++k) x.tiltAngles[k] = in.number(fmt::format("TILT angle {} of {}", k + 1, n));
        for (int k = 0; k < n; ++k) {
            size_t l = in.lineNo();
            x.tiltFactors[k] = in.number(fmt::format("TILT factor {} of {}", k + 1, n));
            if (x.tiltFactors[k] < 0) f.fail(l, "a TILT factor >= 0", fmt::format("{}", x.tiltFactors[k]));
        }
    } else {
        f.fail(tiltLineNo, "TILT=NONE or TILT=INCLUDE (a TILT file is not supported)", quote(tiltLine));
    }

    x.lamps = in.integer("the number of lamps", -1000000, 1000000);
    x.lampLumens = in.number("the lumens per lamp (-1 = absolute)");
    size_t l = in.lineNo();
    x.multiplier = in.number("the candela multiplier");
    if (!(x.multiplier > 0)) f.fail(l, "a candela multiplier > 0", fmt::format("{}", x.multiplier));
    const size_t countLine = in.lineNo();
    int nv = in.integer("the number of vertical angles", 2, kMaxAngles);
    int nh = in.integer("the number of horizontal angles", 1, kMaxAngles);
    l = in.lineNo();
    x.photometricType = in.integer("the photometric type (1 = C)", 1, 3);
    if (x.photometricType == 2)
        f.fail(l, "photometric type 1 (C); type B (2, floodlights) is not supported, convert it to type C", "2");
    if (x.photometricType == 3) f.fail(l, "photometric type 1 (C); type A (3) is not supported", "3");
    int units = in.integer("the units type (1 feet, 2 metres)", 1, 2);
    double w = in.number("the luminous width");
    double len = in.number("the luminous length");
    in.number("the luminous height");
    l = in.lineNo();
    x.ballastFactor = in.number("the ballast factor");
    if (!(x.ballastFactor > 0)) f.fail(l, "a ballast factor > 0", fmt::format("{}", x.ballastFactor));
    l = in.lineNo();
    x.ballastLampFactor = in.number("the ballast-lamp photometric factor");
    if (!(x.ballastLampFactor > 0))
        f.fail(l, "a ballast-lamp photometric factor > 0", fmt::format("{}", x.ballastLampFactor));
    x.inputWatts = in.number("the input watts");

    std::vector<double> v(nv), h(nh);
    for (int k = 0; k < nv; ++k) {
        l = in.lineNo();
        v[k] = in.number(fmt::format("vertical angle {} of {}", k + 1, nv));
        if (k > 0 && !(v[k] > v[k - 1]))
            f.fail(l, fmt::format("vertical angles ascending (after {})", v[k - 1]), fmt::format("{}", v[k]));
    }
    if (!((v.front() == 0 || v.front() == 90) && (v.back() == 90 || v.back() == 180) && v.front() < v.back()))
        f.fail(in.lastLine(), "vertical angles 0-90, 90-180 or 0-180", fmt::format("{}-{}", v.front(), v.back()));
    for (int k = 0; k < nh; ++k) {
        l = in.lineNo();
        h[k] = in.number(fmt::format("horizontal angle {} of {}", k + 1, nh));
        if (k > 0 && !(h[k] > h[k - 1]))
            f.fail(l, fmt::format("horizontal angles ascending (after {})", h[k - 1]), fmt::format("{}", h[k]));
    }
    const size_t hLine = in.lastLine();
    // Horizontal set -> symmetry.
    int isym;
    double h0 = h.front(), h1 = h.back();
    if (nh == 1 && h0 == 0)
        isym = 1;
    else if (h0 == 0 && h1 == 90)
        isym = 4;
    else if (h0 == 0 && h1 == 180)
        isym = 2;
    else if (h0 == 90 && h1 == 270)
        isym = 3;
    else if (h0 == 0 && h1 > 180 && h1 <= 360)
        isym = 0;
    else
        f.fail(in.lastLine(), "horizontal angles {0}, 0-90, 0-180, 90-270, 0-360 or 0 to (180, 360)",
               fmt::format("{}-{}", h0, h1));

    const double scale = x.multiplier * x.ballastFactor * x.ballastLampFactor;
    // Angles are at most kMaxAngles each; the Nh x Nv table is what could be
    // large, so its count is checked against the file before it is allocated.
    in.requireRoom(double(nv) * nh, fmt::format("Nh x Nv = {} x {} candela values", nh, nv), countLine);
    std::vector<std::vector<double>> planes(nh, std::vector<double>(nv));
    for (int p = 0; p < nh; ++p)
        for (int k = 0; k < nv; ++k) {
            l = in.lineNo();
            double c = in.number(fmt::format("candela {} of {} at horizontal angle {}", k + 1, nv, h[p]));
            if (c < 0) f.fail(l, "a candela value >= 0", fmt::format("{}", c));
            planes[p][k] = absoluteCandela(f, l, c, scale, "a candela value");
        }
    if (!in.atEnd()) {
        l = in.lineNo();
        f.fail(l, fmt::format("the end of the file after the {} x {} candela values", nh, nv), quote(in.token("")));
    }
    // A full set that stores 360 keeps its own 360 plane; one that stops short
    // gets 360 = 0 (unfold).
    Table t = unfold(isym, h, v, planes, fmt::format("{}:{}", f.path, hLine));
    t.source = f.path;
    t.format = "ies";
    t.isym = isym;
    t.symmetry = symmetryName(isym);
    const double toM = units == 1 ? 0.3048 : 1.0;
    t.widthM = std::abs(w) * toM;  // LM-63-2019: negative = rounded shapes
    t.lengthM = std::abs(len) * toM;
    t.validate();
    if (extraOut) *extraOut = x;
    return t;
}

static std::string num(double v) { return fmt::format("{}", v); }

std::string iesText(const Table& t, const std::string& name)
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
    line("[LUMINAIRE] " + name + " (generated by lumibench luminaire synth)");
    line("[OTHER] absolute photometry");
    line("TILT=NONE");
    line(fmt::format("1 -1 1 {} {} 1 2 {} {} 0", t.ng(), nh, num(t.widthM), num(t.lengthM)));
    line("1 1 0");
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
    block([&](size_t i) { return t.gamma[i]; }, t.ng());
    block([&](size_t i) { return t.c[i]; }, nh);
    for (size_t ic = 0; ic < nh; ++ic) block([&](size_t i) { return t.at(ic, i); }, t.ng());
    return s;
}

void writeIes(const Table& t, const std::string& path, const std::string& name)
{
    util::writeFileAtomic(path, iesText(t, name));
}

}  // namespace lb::photometry
