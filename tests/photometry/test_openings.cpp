// The luminous opening: LM-63-2019 Table 1 and the older round-opening rule,
// the EULUMDAT fields, the real files' declared openings, write -> read round
// trips, and the TILT=INCLUDE table kept on the table and refused by scenes.
#include "methods/analytic.h"
#include "photometry/ies.h"
#include "photometry/ldt.h"
#include "photometry/load.h"
#include "photometry/opening.h"
#include "photometry/synth.h"
#include "testutil.h"
#include "util/error.h"

#include <array>
#include <filesystem>
#include <fstream>

namespace lb::photometry {
namespace {

namespace fs = std::filesystem;
using S = OpeningShape;

Opening fromIes(double w, double l, double h)
{
    Opening o;
    EXPECT_TRUE(openingFromIes(w, l, h, o)) << w << " " << l << " " << h;
    return o;
}

TEST(Openings, IesSignsFollowLm63Table1)
{
    // One row per shape of LM-63-2019 Table 1: (width, length, height) signed
    // as the file stores them -> shape, length (C0-C180), width (C90-C270), height.
    struct Row {
        double w, l, h;
        Opening want;
    };
    const Row rows[] = {
        {0, 0, 0, {S::Point, 0, 0, 0}},
        {0.2, 0.5, 0, {S::Rectangle, 0.5, 0.2, 0}},
        {0.2, 0.5, 0.1, {S::Rectangle, 0.5, 0.2, 0.1}},  // luminous sides
        {-0.1, -0.1, 0, {S::Circle, 0.1, 0.1, 0}},
        {-0.1, -0.3, 0, {S::Ellipse, 0.3, 0.1, 0}},
        {-0.1, -0.1, 0.2, {S::VerticalCylinder, 0.1, 0.1, 0.2}},
        {-0.1, -0.3, 0.2, {S::VerticalCylinder, 0.3, 0.1, 0.2}},  // elliptical section
        {-0.1, -0.1, -0.1, {S::Sphere, 0.1, 0.1, 0.1}},
        {-0.1, -0.2, -0.3, {S::Sphere, 0.2, 0.1, 0.3}},  // ellipsoid
        {-0.1, 0.6, -0.1, {S::CylinderAlongLength, 0.6, 0.1, 0.1}},
        {0.6, -0.1, -0.2, {S::CylinderAlongWidth, 0.1, 0.6, 0.2}},
        {-0.1, 0, -0.1, {S::VerticalCircle, 0, 0.1, 0.1}},
        // The 1995 / 2002 files' round opening: width < 0, length 0.
        {-0.08, 0, 0, {S::Circle, 0.08, 0.08, 0}},
        {-0.1, 0, 0.13, {S::VerticalCylinder, 0.1, 0.1, 0.13}},
    };
    for (const Row& r : rows) {
        Opening o = fromIes(r.w, r.l, r.h);
        EXPECT_EQ(o, r.want) << r.w << " " << r.l << " " << r.h << " -> " << shapeName(o.shape);
        // Written back as Table 1 signs it, it reads as the same opening (the
        // older circle -d 0 0 is written -d -d 0).
        double w, l, h;
        iesDimensions(o, w, l, h);
        EXPECT_EQ(fromIes(w, l, h), o) << shapeName(o.shape);
    }
    // Sign patterns Table 1 does not define.
    Opening o;
    const std::array<std::array<double, 3>, 4> undefined = {
        {{-0.1, 0.2, 0}, {0.1, -0.2, 0}, {0, 0, -0.1}, {0.1, 0.2, -0.1}}};
    for (auto [w, l, h] : undefined) EXPECT_FALSE(openingFromIes(w, l, h, o)) << w << " " << l << " " << h;
}

TEST(Openings, LdtFieldsAndWhatEulumdatCannotHold)
{
    const double none[4] = {0, 0, 0, 0}, sides[4] = {60, 60, 60, 40};
    EXPECT_EQ(openingFromLdt(110, 0, none), (Opening{S::Circle, 0.11, 0.11, 0}));  // width 0: circular
    EXPECT_EQ(openingFromLdt(2000, 72, none), (Opening{S::Rectangle, 2.0, 0.072, 0}));
    EXPECT_EQ(openingFromLdt(620, 620, sides), (Opening{S::Rectangle, 0.62, 0.62, 0.06}));  // the largest height
    EXPECT_EQ(openingFromLdt(100, 0, sides), (Opening{S::VerticalCylinder, 0.1, 0.1, 0.06}));
    EXPECT_EQ(openingFromLdt(0, 0, none), Opening{});
    double l, w, h;
    ASSERT_TRUE(ldtDimensions(Opening::circle(0.11), l, w, h));
    EXPECT_EQ(w, 0);  // circular: field 17 = 0, field 16 the diameter
    EXPECT_EQ(l, 110);
    for (Opening o :
         {Opening{S::Ellipse, 0.3, 0.1, 0}, Opening{S::Sphere, 0.1, 0.1, 0.1},
          Opening{S::CylinderAlongLength, 0.6, 0.1, 0.1}, Opening{S::VerticalCircle, 0, 0.1, 0.1},
          Opening::rectangle(0.5, 0), Opening::rectangle(0, 0, 0.1)})  // would read back as a circle, a point
        EXPECT_FALSE(ldtDimensions(o, l, w, h)) << shapeName(o.shape);
    Table t = synth("lambert", SynthParams{});
    t.opening = {S::Ellipse, 0.3, 0.1, 0};
    EXPECT_NE(test::inputErrorOf([&] { ldtText(t, "x"); }).find("ellipse"), std::string::npos);
}

TEST(Openings, ShapeNamesFollowTheEnumeration)
{
    EXPECT_STREQ(shapeName(S::Point), "point");
    EXPECT_STREQ(shapeName(S::Sphere), "sphere");
    EXPECT_STREQ(shapeName(S::VerticalCircle), "vertical-circle");
}

TEST(Openings, FlatFace)
{
    Opening f;
    ASSERT_TRUE((Opening{S::VerticalCylinder, 0.076, 0.076, 0.001}).flatFace(f));
    EXPECT_EQ(f, Opening::circle(0.076));
    ASSERT_TRUE(Opening::rectangle(0.62, 0.62, 0.06).flatFace(f));
    EXPECT_EQ(f, Opening::rectangle(0.62, 0.62));
    // Height at or over half the diameter: not a disk (ies2rad's threshold).
    EXPECT_FALSE((Opening{S::VerticalCylinder, 0.1, 0.1, 0.05}).flatFace(f));
    EXPECT_FALSE((Opening{S::Sphere, 0.1, 0.1, 0.1}).flatFace(f));
    EXPECT_TRUE((Opening{S::Ellipse, 0.3, 0.1, 0}).flatFace(f));
}

TEST(Openings, IesReaderKeepsTheSignsAndRefusesUndefinedOnes)
{
    auto ies = [](const std::string& dims, const std::string& units = "2") {
        return "IESNA:LM-63-2002\n[TEST] t\nTILT=NONE\n1 -1 1 3 1 1 " + units + " " + dims +
            "\n1 1 10\n0 45 90\n0\n3 2 1\n";
    };
    EXPECT_EQ(readIes(TextFile::fromString("c.ies", ies("-0.092 -0.092 0"))).opening, Opening::circle(0.092));
    // Feet: 0.33 ft = 0.100584 m across, 0.44 ft = 0.134112 m high.
    Opening cyl = readIes(TextFile::fromString("f.ies", ies("-0.33 0 0.44", "1"))).opening;
    EXPECT_EQ(cyl, Opening::circle(0.33 * 0.3048, 0.44 * 0.3048));
    std::string e = test::inputErrorOf([&] { readIes(TextFile::fromString("bad.ies", ies("-0.1 0.2 0"))); });
    EXPECT_NE(e.find("bad.ies:4:"), std::string::npos) << e;
    EXPECT_NE(e.find("LM-63-2019 Table 1"), std::string::npos) << e;
    EXPECT_NE(e.find("width -0.1, length 0.2, height 0"), std::string::npos) << e;
}

std::string ieslib(const std::string& dir, const std::string& stem)
{
    return dir + "/luminaires/ieslibrary/" + stem + ".ies";
}

TEST(Openings, IesLibraryFilesDeclareTheirOpenings)
{
    LB_REQUIRE_SHARED(dir);
    // From each file's text (width length height, metres unless noted).
    const std::pair<const char*, Opening> want[] = {
        {"007cfb11e343e2f42e3b476be4ab684e", Opening::circle(0.080)},  // -0.080 0 0
        {"00c6ce79e1d2cdf3a1fb491aaaa47ae0", Opening::circle(0.150)},  // -0.150 0 0
        {"01dac7d6c646814dcda6780e7b7b4566", Opening::circle(0.075)},  // -0.075 0 0
        {"02a7562c650498ebb301153dbbf59207", Opening::rectangle(0.270, 0.240)},  // 0.240 0.270 0
        {"0646706b3d2d9658994fc4ad80681dec", Opening::circle(0.120)},  // -0.120 0 0
        {"06b4cfdc8805709e767b5e2e904be8ad", Opening::circle(0.120)},  // -0.120 0 0
        {"108b32f07d6d38a7a6528a6d307440df", Opening::circle(0.076, 0.001)},  // -0.076 -0.076 0.001
        {"1a936937a49c63374e6d4fbed9252b29", Opening::circle(0.092)},  // -0.092 -0.092 0
        {"1aec5958092c236d005093ca27ebe378", Opening::circle(0.33 * 0.3048, 0.44 * 0.3048)},  // feet
    };
    int roundFlat = 0;
    for (const auto& [stem, o] : want) {
        Table t = load(ieslib(dir, stem));
        EXPECT_EQ(t.opening, o) << stem << ": " << shapeName(t.opening.shape) << " " << t.opening.lengthM << " x "
                                << t.opening.widthM << " x " << t.opening.heightM;
        Opening face;
        if (t.opening.round() && t.opening.flatFace(face) && face.shape == S::Circle) {
            ++roundFlat;
            EXPECT_GE(face.lengthM, 0.075) << stem;
            EXPECT_LE(face.lengthM, 0.150) << stem;
        }
    }
    // Seven round downlights of 75-150 mm (six flat circles and one 1 mm high
    // cylinder); the 100 x 134 mm cylinder has no flat face, 02a7 is 270 x 240 mm.
    EXPECT_EQ(roundFlat, 7);
    EXPECT_EQ(load(ieslib(dir, "108b32f07d6d38a7a6528a6d307440df")).opening.shape, S::VerticalCylinder);
    Opening face;
    EXPECT_FALSE(load(ieslib(dir, "1aec5958092c236d005093ca27ebe378")).opening.flatFace(face));
}

TEST(Openings, ZumtobelFilesDeclareTheirOpenings)
{
    LB_REQUIRE_SHARED(dir);
    auto z = [&](const std::string& f) { return load(dir + "/luminaires/zumtobel/" + f).opening; };
    // Fields 16-21 of each file (mm); ARCOS3's luminaire is 120 x 120, its
    // luminous area a 110 mm disk (field 17 = 0).
    EXPECT_EQ(z("ARCOS3_60712332.LDT"), Opening::circle(0.110));
    EXPECT_EQ(z("SLOTLIGHT_42184612.LDT"), Opening::rectangle(2.000, 0.072));
    EXPECT_EQ(z("LINETIK-S_42184482.LDT"), Opening::rectangle(1.000, 0.013));
    EXPECT_EQ(z("PANOS_60813872.LDT"), Opening::rectangle(0.127, 0.127));
    EXPECT_EQ(z("MIREL_42925637.LDT"), Opening::rectangle(0.345, 0.345));
    EXPECT_EQ(z("PERLUCE_42182932.LDT"), Opening::rectangle(0.620, 0.620, 0.060));
    EXPECT_EQ(z("INTRO_60714483.LDT"), Opening::rectangle(0.001, 0.085, 0.085));
}

// LDT stores millimetres: x 1000 and / 1000 again, each correctly rounded,
// so a dimension comes back within 2 ulp (4.4e-16 relative); 1e-15 covers it.
void expectSameOpening(const Opening& a, const Opening& b, const std::string& what)
{
    EXPECT_EQ(a.shape, b.shape) << what;
    EXPECT_NEAR(a.lengthM, b.lengthM, 1e-15 * a.lengthM) << what;
    EXPECT_NEAR(a.widthM, b.widthM, 1e-15 * a.widthM) << what;
    EXPECT_NEAR(a.heightM, b.heightM, 1e-15 * a.heightM) << what;
}

TEST(Openings, WriteThenReadKeepsTheOpening)
{
    LB_REQUIRE_SHARED(dir);
    int n = 0;
    for (auto& e : fs::recursive_directory_iterator(dir + "/luminaires")) {
        std::string ext = e.path().extension().string();
        if (ext != ".ies" && ext != ".LDT") continue;
        ++n;
        Table t = load(e.path().string());
        Table viaIes = readIes(TextFile::fromString("w.ies", iesText(t, "w")));
        EXPECT_EQ(viaIes.opening, t.opening) << e.path();  // metres, shortest round-trip text: exact
        Table viaLdt = readLdt(TextFile::fromString("w.ldt", ldtText(t, "w")));
        expectSameOpening(t.opening, viaLdt.opening, e.path().string() + " via ldt");
        Table back = readLdt(TextFile::fromString("w.ldt", ldtText(viaIes, "w")));
        expectSameOpening(t.opening, back.opening, e.path().string() + " via ies, ldt");
    }
    EXPECT_EQ(n, 16);
}

const char* kTilted = "IESNA:LM-63-2002\n[TEST] t\nTILT=INCLUDE\n1\n3\n0 45 90\n1 0.9 0.8\n"
                      "1 -1 1 3 1 1 2 -0.1 -0.1 0\n1 1 10\n0 45 90\n0\n3 2 1\n";

TEST(Openings, TiltTableIsKeptWrittenBackAndAppliedAtTheScenesTilt)
{
    Table t = readIes(TextFile::fromString("tilted.ies", kTilted));
    EXPECT_EQ(t.tilt.geometry, 1);
    EXPECT_EQ(t.tilt.anglesDeg, (std::vector<double>{0, 45, 90}));
    EXPECT_EQ(t.tilt.factors, (std::vector<double>{1, 0.9, 0.8}));
    EXPECT_FALSE(t.tilt.trivial());
    // IES keeps it on a round trip; EULUMDAT has no field for it.
    Table back = readIes(TextFile::fromString("w.ies", iesText(t, "w")));
    EXPECT_EQ(back.tilt.factors, t.tilt.factors);
    EXPECT_EQ(back.tilt.geometry, 1);
    EXPECT_NE(test::inputErrorOf([&] { ldtText(t, "w"); }).find("TILT"), std::string::npos);
    // The lamp's tilt is |180 - R| degrees; by hand, with the table 0 45 90 -> 1 0.9 0.8
    // (it ends at 90: a tilt g above 90 reads 180 - g):
    const double pi = 3.14159265358979323846;
    const std::vector<std::pair<double, double>> hand = {{pi, 1.0},  // untilted
                                                         {3 * pi / 4, 0.9},  // 45 degrees: a node
                                                         {pi / 2, 0.8},  // 90
                                                         {5 * pi / 6, 1 - 0.1 * 30.0 / 45},  // 30: between 0 and 45
                                                         {pi / 3, 0.9 - 0.1 * 15.0 / 45},  // 120, folded to 60
                                                         {7 * pi / 4, 0.9},  // 135 the other way, folded to 45
                                                         {0.0, 1.0}};  // 180: facing up, folded to 0
    for (const auto& [R, f] : hand) {
        EXPECT_NEAR(tiltFactor(t.tilt, R), f, 1e-12) << R;
        const Table s = tiltedFor(t, R);
        EXPECT_TRUE(s.tilt.factors.empty());
        for (size_t k = 0; k < t.cd.size(); ++k) EXPECT_NEAR(s.cd[k], f * t.cd[k], 1e-12 * t.cd[k]) << R << " " << k;
    }
    // A table beyond 90 degrees is not folded; beyond its last angle the last factor holds.
    Tilt wide{1, {0, 90, 150}, {1, 0.5, 0.2}};
    EXPECT_NEAR(tiltFactor(wide, pi / 3), 0.5 - 0.3 * 30.0 / 60, 1e-12);  // 120
    EXPECT_NEAR(tiltFactor(wide, 0.0), 0.2, 1e-12);  // 180
    EXPECT_EQ(tiltFactor(Tilt{}, pi / 2), 1.0);
    // The scenes' loader keeps the file (before: refused at every rotation).
    fs::path d = test::freshDir("tilt");
    {
        std::ofstream(d / "tilted.ies") << kTilted;
    }
    EXPECT_EQ(methods::loadLuminaire((d / "tilted.ies").string()).tilt.factors, t.tilt.factors);
    fs::remove_all(d);
}

}  // namespace
}  // namespace lb::photometry
