// opening.h -- the luminous opening a luminaire file declares (docs/luminaire-openings.md).
//
// Axes: both IES LM-63 and EULUMDAT give the length along the C0-C180 axis
// and the width along C90-C270; the height runs along the gamma = 0 axis
// (the luminous sides). In the scene (DESIGN section 2) u is C0, so the
// light's W (along u) is the opening's length and its L (along v) the width.
#pragma once

#include <string>
#include <vector>

namespace lb::photometry {

// The shapes of LM-63-2019 Table 1 (EULUMDAT has the point, the rectangle,
// the circle and luminous sides).
enum class OpeningShape {
    Point,  // no size given
    Rectangle,  // length x width; heightM > 0: with luminous sides (a box)
    Circle,  // diameter lengthM == widthM
    Ellipse,  // axes lengthM, widthM
    VerticalCylinder,  // cross-section a circle or ellipse (lengthM, widthM), heightM tall
    Sphere,  // lengthM == widthM == heightM; an ellipsoid when they differ
    CylinderAlongLength,  // horizontal, axis along C0-C180 (lengthM long), section widthM x heightM
    CylinderAlongWidth,  // horizontal, axis along C90-C270 (widthM long), section lengthM x heightM
    VerticalCircle,  // a disk (ellipse) facing C0: widthM across, heightM tall
};

// "point", "rectangle", "circle", "ellipse", "vertical-cylinder", "sphere",
// "cylinder-along-length", "cylinder-along-width", "vertical-circle".
const char* shapeName(OpeningShape s);

struct Opening {
    OpeningShape shape = OpeningShape::Point;
    double lengthM = 0;  // along C0-C180 (a circle's diameter)
    double widthM = 0;  // along C90-C270 (a circle's diameter)
    double heightM = 0;  // along gamma = 0 (luminous sides), 0 if none

    static Opening rectangle(double lengthM, double widthM, double heightM = 0);
    static Opening circle(double diameterM, double heightM = 0);  // a vertical cylinder when heightM > 0

    // The flat opening facing gamma = 0 that a planar light can stand for:
    // the opening itself when it is a point, a flat rectangle, circle or
    // ellipse; the bottom face of a rectangle with luminous sides or of a
    // vertical cylinder whose height is under half its smaller horizontal
    // dimension (the threshold below which Radiance's ies2rad models a
    // cylinder as a disk); false otherwise (spheres, tall cylinders,
    // horizontal cylinders, vertical circles).
    bool flatFace(Opening& face) const;
    bool round() const;  // a circle or a vertical cylinder of circular section

    bool operator==(const Opening& o) const
    {
        return shape == o.shape && lengthM == o.lengthM && widthM == o.widthM && heightM == o.heightM;
    }
    bool operator!=(const Opening& o) const { return !(*this == o); }
};

// IES LM-63: the signed width, length and height (metres, in that order as
// the file stores them) to an opening, per LM-63-2019 Table 1; and, as the
// 1995 and 2002 files write a round opening, width < 0 with length 0 (a
// circle, or a vertical cylinder when height > 0). Returns false for a sign
// pattern the table does not define (the caller reports it with the line).
bool openingFromIes(double width, double length, double height, Opening& out);
// The signed width, length and height LM-63-2019 Table 1 gives the opening
// (a circle as -d -d 0, which the older rule, width < 0, reads alike).
void iesDimensions(const Opening& o, double& width, double& length, double& height);

// EULUMDAT fields 16 (length / diameter of the luminous area), 17 (width,
// 0 = circular) and 18-21 (luminous heights in the C0, C90, C180, C270
// planes), millimetres. The opening keeps the largest of the four heights.
Opening openingFromLdt(double lengthMm, double widthMm, const double heightsMm[4]);
// Fields 16, 17 and the one height written to 18-21, or false when EULUMDAT
// has no field for the shape (ellipse, sphere, horizontal cylinders,
// vertical circle, elliptical cylinder, a rectangle of width 0).
bool ldtDimensions(const Opening& o, double& lengthMm, double& widthMm, double& heightMm);

// IES TILT=INCLUDE: candela factors by lamp tilt angle. Empty when the file
// has TILT=NONE (or is not an IES file).
struct Tilt {
    int geometry = 0;  // lamp-to-luminaire geometry 1..3
    std::vector<double> anglesDeg, factors;

    // No table, or every factor 1: the tilt changes nothing.
    bool trivial() const;
};

}  // namespace lb::photometry
