// EULUMDAT layout (one field per line): 1 company, 2 Ityp, 3 Isym, 4 Nc,
// 5 Dc, 6 Ng, 7 Dg, 8-12 texts, 13-15 luminaire size (mm), 16-17 luminous
// area length / width (mm), 18-21 luminous area heights, 22 DFF %, 23 LOR %,
// 24 conversion factor, 25 tilt, 26 number of lamp sets n, then per set: lamps,
// type, total lamp flux (lm), colour, CRI, watts; 10 direct ratios; Nc C
// angles; Ng gamma angles; Mc x Ng intensities (cd/klm), plane by plane.
//
// Stored planes Mc1..Mc2 by Isym (1-based angle-list indices, modulo Nc):
// 0 all Nc; 1 one; 2 1..Nc/2+1 (C0..C180); 3 3Nc/4+1..3Nc/4+1+Nc/2, i.e.
// C270, C285, ..., C345, C0, ..., C90 in that order (the EULUMDAT definition,
// read so by Aardvark.Data.Photometry, which rendered the seeds' figures, and
// by pyldt); 4 1..Nc/4+1 (C0..C90).
#include "photometry/ldt.h"

#include "photometry/symmetry.h"
#include "photometry/text.h"
#include "util/error.h"
#include "util/fileio.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace lb::photometry {

Table readLdt(const std::string& path) { return readLdt(TextFile::read(path)); }

namespace {

// Fields 1-26 and the lamp sets: what the table needs of them, and the lines
// of the counts that later complaints point at.
struct LdtHeader {
    int isym = 0, nc = 0, ng = 0;
    size_t isymLine = 0, ncLine = 0;
    double lenMm = 0, widMm = 0;  // luminous area (fields 16, 17)
    double heightsMm[4] = {0, 0, 0, 0};  // luminous heights at C0, C90, C180, C270 (fields 18-21)
    double lor = 0;  // light output ratio, %
    double lampFlux = 0;  // total over the lamp sets, lm
};

// Field 26's lamp sets, then the 10 direct ratios: the total lamp flux.
double readLampSets(LineCursor& in, const TextFile& f)
{
    int sets = in.integer("the number of lamp sets n (field 26)", 1, 1000);
    double lampFlux = 0;
    for (int s = 0; s < sets; ++s) {
        in.integer(fmt::format("the number of lamps of set {}", s + 1), -100000, 100000);
        in.text(fmt::format("the lamp type of set {}", s + 1));
        size_t l = in.lineNo();
        double fl = in.number(fmt::format("the total lamp flux in lm of set {}", s + 1));
        if (fl < 0) f.fail(l, fmt::format("a lamp flux >= 0 for set {}", s + 1), fmt::format("{}", fl));
        lampFlux += fl;
        in.text(fmt::format("the colour of set {}", s + 1));
        in.text(fmt::format("the colour rendering of set {}", s + 1));
        in.number(fmt::format("the wattage of set {}", s + 1));
    }
    if (!(lampFlux > 0)) f.fail(in.lineNo() - 4, "a total lamp flux > 0 over all lamp sets", "0");
    for (int i = 0; i < 10; ++i) in.number(fmt::format("direct ratio {} of 10", i + 1));
    return lampFlux;
}

LdtHeader readHeader(LineCursor& in, const TextFile& f)
{
    LdtHeader h;
    in.text("a company line (line 1)");
    in.integer("the type indicator Ityp", 0, 3);
    h.isymLine = in.lineNo();
    h.isym = in.integer("the symmetry indicator Isym", 0, 4);
    h.ncLine = in.lineNo();
    h.nc = in.integer("the number of C planes Nc", 0, kMaxAngles);
    // Rotational files sometimes list no C angle at all (Nc = 0); others need one.
    if (h.nc == 0 && h.isym != 1) f.fail(h.ncLine, "Nc >= 1 unless Isym = 1", "Nc = 0");
    in.number("the C plane distance Dc");
    h.ng = in.integer("the number of gamma angles Ng", 2, kMaxAngles);
    in.number("the gamma distance Dg");
    for (int i = 8; i <= 12; ++i) in.text(fmt::format("text field {}", i));
    // Fields 13-21 are lengths: a negative one is a damaged file, not a shape.
    auto length = [&](const std::string& what) {
        size_t l = in.lineNo();
        double v = in.number(what);
        if (v < 0) f.fail(l, what + " >= 0", fmt::format("{}", v));
        return v;
    };
    for (int i = 13; i <= 15; ++i) length(fmt::format("a luminaire dimension in mm (field {})", i));
    h.lenMm = length("the length / diameter of the luminous area in mm (field 16)");
    h.widMm = length("the width of the luminous area in mm (field 17)");
    for (int i = 18; i <= 21; ++i)
        h.heightsMm[i - 18] = length(fmt::format("a luminous area height in mm (field {})", i));
    in.number("the downward flux fraction DFF in % (field 22)");
    size_t lorLine = in.lineNo();
    h.lor = in.number("the light output ratio LOR in % (field 23)");
    if (h.lor < 0) f.fail(lorLine, "a light output ratio >= 0", fmt::format("{}", h.lor));
    in.number("the conversion factor (field 24)");
    in.number("the tilt angle (field 25)");
    h.lampFlux = readLampSets(in, f);
    return h;
}

// n angles, each ascending after the previous one and within [lo, hi]
// (hiOpen: hi excluded); range and order unchecked when !check.
std::vector<double> readAngles(TokenCursor& tok, const TextFile& f, int n, const char* name, double lo, double hi,
                               bool hiOpen, bool check)
{
    std::vector<double> a(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        size_t l = tok.lineNo();
        a[i] = tok.number(fmt::format("{} angle {} of {}", name, i + 1, n));
        if (!check) continue;
        if (a[i] < lo || (hiOpen ? a[i] >= hi : a[i] > hi))
            f.fail(l, fmt::format("a {} angle in [{}, {}{}", name, lo, hi, hiOpen ? ")" : "]"),
                   fmt::format("{}", a[i]));
        if (i > 0 && !(a[i] > a[i - 1]))
            f.fail(l, fmt::format("{} angles ascending (after {})", name, a[i - 1]), fmt::format("{}", a[i]));
    }
    return a;
}

// The C angles of the stored planes Mc1..Mc2 (Isym: see the top of the file),
// checked against the symmetry's first and last plane.
std::vector<double> storedPlanes(const TextFile& f, const LdtHeader& h, const std::vector<double>& cAll)
{
    const int isym = h.isym, nc = h.nc;
    size_t first = 0, mc = static_cast<size_t>(nc);
    auto need = [&](bool ok, const std::string& what) {
        if (!ok) f.fail(h.ncLine, what, fmt::format("Nc = {} with Isym = {}", nc, isym));
    };
    switch (isym) {
    case 1:
        mc = 1;
        break;
    case 2:
        need(nc % 2 == 0, "an even Nc for Isym 2");
        mc = nc / 2 + 1;
        break;
    case 3:
        need(nc % 4 == 0, "Nc divisible by 4 for Isym 3");
        mc = nc / 2 + 1;
        first = static_cast<size_t>(3 * nc / 4);  // C270, then on through C0 to C90
        break;
    case 4:
        need(nc % 4 == 0, "Nc divisible by 4 for Isym 4");
        mc = nc / 4 + 1;
        break;
    default:
        break;
    }
    // (Isym 1 may list no angle at all; its one plane stands for every C.)
    std::vector<double> cStored = {0};
    if (isym != 1) {
        cStored.resize(mc);
        for (size_t p = 0; p < mc; ++p) cStored[p] = cAll[(first + p) % cAll.size()];
    }
    const double firstC[] = {0, 0, 0, 270, 0}, lastC[] = {-1, 0, 180, 90, 90};
    if (isym == 3 && cStored.front() != firstC[isym])
        f.fail(h.isymLine, fmt::format("stored planes starting at C = {} for Isym {}", firstC[isym], isym),
               fmt::format("C = {}", cStored.front()));
    if (isym >= 2 && cStored.back() != lastC[isym])
        f.fail(h.isymLine, fmt::format("stored planes ending at C = {} for Isym {}", lastC[isym], isym),
               fmt::format("C = {}", cStored.back()));
    if ((isym == 0 || isym == 2 || isym == 4) && cAll[0] != 0)
        f.fail(h.isymLine, "the first C angle 0", fmt::format("{}", cAll[0]));
    return cStored;
}

// The Mc x Ng intensities, cd/klm -> absolute cd, then the end of the file.
std::vector<std::vector<double>> readIntensities(TokenCursor& tok, const TextFile& f, const LdtHeader& h,
                                                 const std::vector<double>& cStored)
{
    const size_t mc = cStored.size();
    const int ng = h.ng;
    const double scale = h.lampFlux / 1000.0;
    tok.requireRoom(double(mc) * ng,
                    fmt::format("Mc x Ng = {} x {} intensities (Nc = {}, Isym = {})", mc, ng, h.nc, h.isym), h.ncLine);
    std::vector<std::vector<double>> planes(mc, std::vector<double>(static_cast<size_t>(ng)));
    for (size_t p = 0; p < mc; ++p)
        for (int i = 0; i < ng; ++i) {
            size_t l = tok.lineNo();
            double v = tok.number(fmt::format("intensity {} of plane C = {} (cd/klm)", i + 1, cStored[p]));
            if (v < 0) f.fail(l, "an intensity >= 0", fmt::format("{}", v));
            planes[p][i] = absoluteCandela(f, l, v, scale, "an intensity");
        }
    if (!tok.atEnd()) {
        size_t l = tok.lineNo();
        f.fail(l,
               fmt::format("the end of the file after the {} x {} intensities (Mc x Ng for Nc = {}, Isym = {})", mc, ng,
                           h.nc, h.isym),
               quote(tok.token("")));
    }
    return planes;
}

}  // namespace

Table readLdt(const TextFile& f)
{
    LineCursor in(f);
    const LdtHeader h = readHeader(in, f);

    // Angles. Numeric blocks are read as tokens, so a file that puts several
    // numbers on a line still reads; the usual layout is one per line.
    TokenCursor tok(f, in.index(), false, true);
    std::vector<double> cAll = readAngles(tok, f, h.nc, "C", 0, 360, true, h.isym != 1);
    std::vector<double> gamma = readAngles(tok, f, h.ng, "gamma", 0, 180, false, true);
    std::vector<double> cStored = storedPlanes(f, h, cAll);
    std::vector<std::vector<double>> planes = readIntensities(tok, f, h, cStored);

    // unfold() takes the C90-C270 half for Isym 3: plane C stands for its mirror
    // image 180 - C there (C270 -> 270, C0 -> 180, C90 -> 90).
    std::vector<double> cUnfold = cStored;
    if (h.isym == 3)
        for (double& c : cUnfold) c = c <= 90 ? 180 - c : 540 - c;
    Table t = unfold(h.isym, cUnfold, gamma, planes, fmt::format("{}:{}", f.path, h.isymLine));
    t.source = f.path;
    t.format = "ldt";
    t.isym = h.isym;
    t.symmetry = symmetryName(h.isym);
    t.declaredFluxLm = h.lampFlux * h.lor / 100.0;
    t.opening = openingFromLdt(h.lenMm, h.widMm, h.heightsMm);  // the luminous area, not the luminaire (13-15)
    t.validate();
    return t;
}

// Shortest text that reads back as the same double.
constexpr double kDeg = 3.14159265358979323846 / 180.0;

static std::string num(double v) { return fmt::format("{}", v); }

std::string ldtText(const Table& t, const std::string& name, const std::string& origin)
{
    t.validate();
    bool rotational = t.nc() == 2;  // write what was read: only a one-plane table as Isym 1
    for (size_t ic = 1; ic < t.nc() && rotational; ++ic)
        for (size_t ig = 0; ig < t.ng(); ++ig)
            if (t.at(ic, ig) != t.at(0, ig)) rotational = false;
    size_t nc = t.nc() - 1;  // the 360 plane is implied
    // Flux and downward fraction by the trapezoidal rule on the nodes (cheap;
    // the lamp flux only sets the cd/klm scale, which reading undoes).
    double total = 0, down = 0;
    for (size_t ic = 0; ic + 1 < t.nc(); ++ic)
        for (size_t ig = 0; ig + 1 < t.ng(); ++ig) {
            double g0 = t.gamma[ig] * kDeg, g1 = t.gamma[ig + 1] * kDeg;
            double i = 0.25 * (t.at(ic, ig) + t.at(ic, ig + 1) + t.at(ic + 1, ig) + t.at(ic + 1, ig + 1));
            double f = i * (std::cos(g0) - std::cos(g1)) * (t.c[ic + 1] - t.c[ic]) * kDeg;
            total += f;
            if (t.gamma[ig + 1] <= 90) down += f;
        }
    double downFraction = total > 0 ? down / total : 1;
    double flux = t.declaredFluxLm > 0 ? t.declaredFluxLm : (total > 0 ? total : 1000);
    auto uniformStep = [](const std::vector<double>& a, size_t n) {
        if (n < 2) return 0.0;
        double d = a[1] - a[0];
        for (size_t i = 2; i < n; ++i)
            if (std::abs(a[i] - a[i - 1] - d) > 1e-9) return 0.0;
        return d;
    };
    double lenMm, widMm, heightMm;
    if (!ldtDimensions(t.opening, lenMm, widMm, heightMm))
        throw InputError(fmt::format("EULUMDAT: expected a point, rectangular or round luminous opening (fields "
                                     "16-21), got a {} of {} x {} x {} m; write an IES file instead",
                                     shapeName(t.opening.shape), t.opening.lengthM, t.opening.widthM,
                                     t.opening.heightM));
    if (!t.tilt.trivial())
        throw InputError("EULUMDAT: expected a luminaire without a TILT table (EULUMDAT has no field for one), got "
                         "TILT=INCLUDE factors from " +
                         (t.source.empty() ? std::string("the table") : t.source) + "; write an IES file instead");
    std::string s;
    auto line = [&](const std::string& x) { s += x + "\r\n"; };
    line("lumibench");
    line("1");
    line(rotational ? "1" : "0");
    line(std::to_string(nc));
    line(num(uniformStep(t.c, t.nc())));
    line(std::to_string(t.ng()));
    line(num(uniformStep(t.gamma, t.ng())));
    line("-");
    line(name);
    line(name);
    line(name + ".ldt");
    line("generated by " + origin);
    // Fields 13-15, the luminaire's size: the opening's, as nothing else is known.
    line(num(std::round(lenMm)));
    line(num(std::round(widMm)));
    line(num(std::round(heightMm)));
    line(num(lenMm));
    line(num(widMm));
    for (int i = 0; i < 4; ++i) line(num(heightMm));
    line(num(std::round(1000 * downFraction) / 10));
    line("100");
    line("1");
    line("0");
    line("1");
    line("1");
    line("synthetic");
    line(num(flux));
    line("-");
    line("-");
    line("0");
    for (int i = 0; i < 10; ++i) line("0");
    for (size_t i = 0; i < nc; ++i) line(num(t.c[i]));
    for (double g : t.gamma) line(num(g));
    size_t planes = rotational ? 1 : nc;
    for (size_t ic = 0; ic < planes; ++ic)
        for (size_t ig = 0; ig < t.ng(); ++ig) line(num(t.at(ic, ig) * 1000.0 / flux));
    return s;
}

void writeLdt(const Table& t, const std::string& path, const std::string& name, const std::string& origin)
{
    util::writeFileAtomic(path, ldtText(t, name, origin));
}

}  // namespace lb::photometry
