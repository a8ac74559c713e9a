// The luminous opening: LM-63-2019 Table 1 sign rules, the EULUMDAT fields.
#include "photometry/opening.h"

#include <algorithm>

namespace lb::photometry {

const char* shapeName(OpeningShape s)
{
    // In the order of the enumeration.
    static const char* const names[] = {"point",
                                        "rectangle",
                                        "circle",
                                        "ellipse",
                                        "vertical-cylinder",
                                        "sphere",
                                        "cylinder-along-length",
                                        "cylinder-along-width",
                                        "vertical-circle"};
    return names[static_cast<int>(s)];
}

Opening Opening::rectangle(double lengthM, double widthM, double heightM)
{
    return {OpeningShape::Rectangle, lengthM, widthM, heightM};
}

Opening Opening::circle(double diameterM, double heightM)
{
    return {heightM > 0 ? OpeningShape::VerticalCylinder : OpeningShape::Circle, diameterM, diameterM, heightM};
}

bool Opening::flatFace(Opening& face) const
{
    face = *this;
    face.heightM = 0;
    switch (shape) {
    case OpeningShape::Point:
    case OpeningShape::Circle:
    case OpeningShape::Ellipse:
        return true;
    case OpeningShape::Rectangle:
    case OpeningShape::VerticalCylinder:
        if (heightM > 0 && heightM >= 0.5 * std::min(lengthM, widthM)) return false;
        if (shape == OpeningShape::VerticalCylinder)
            face.shape = lengthM == widthM ? OpeningShape::Circle : OpeningShape::Ellipse;
        return true;
    default:
        return false;
    }
}

bool Opening::round() const
{
    return (shape == OpeningShape::Circle || shape == OpeningShape::VerticalCylinder) && lengthM == widthM;
}

// Table 1 with w, l, h the magnitudes and the signs as the file gives them.
bool openingFromIes(double width, double length, double height, Opening& o)
{
    const double w = -width, l = -length, h = -height;  // magnitudes of the negative ones
    o = Opening{};
    if (width == 0 && length == 0 && height == 0) return true;  // a point
    if (width >= 0 && length >= 0 && height >= 0) {
        o = Opening::rectangle(length, width, height);
        return true;
    }
    if (width < 0 && length < 0) {
        if (height < 0) {
            o = {OpeningShape::Sphere, l, w, h};
        } else {
            const bool circular = width == length;
            o = {height > 0     ? OpeningShape::VerticalCylinder
                     : circular ? OpeningShape::Circle
                                : OpeningShape::Ellipse,
                 l, w, height};
        }
        return true;
    }
    if (width < 0 && length == 0 && height >= 0) {  // the 1995 / 2002 round opening
        o = Opening::circle(w, height);
        return true;
    }
    if (width < 0 && length == 0 && height < 0) {
        o = {OpeningShape::VerticalCircle, 0, w, h};
        return true;
    }
    if (width < 0 && length > 0 && height < 0) {
        o = {OpeningShape::CylinderAlongLength, length, w, h};
        return true;
    }
    if (width > 0 && length < 0 && height < 0) {
        o = {OpeningShape::CylinderAlongWidth, l, width, h};
        return true;
    }
    return false;
}

void iesDimensions(const Opening& o, double& width, double& length, double& height)
{
    width = o.widthM, length = o.lengthM, height = o.heightM;
    switch (o.shape) {
    case OpeningShape::Point:
    case OpeningShape::Rectangle:
        break;
    case OpeningShape::Circle:
    case OpeningShape::Ellipse:
    case OpeningShape::VerticalCylinder:
        width = -o.widthM, length = -o.lengthM;
        break;
    case OpeningShape::Sphere:
        width = -o.widthM, length = -o.lengthM, height = -o.heightM;
        break;
    case OpeningShape::CylinderAlongLength:
    case OpeningShape::VerticalCircle:
        width = -o.widthM, height = -o.heightM;
        break;
    case OpeningShape::CylinderAlongWidth:
        length = -o.lengthM, height = -o.heightM;
        break;
    }
}

Opening openingFromLdt(double lengthMm, double widthMm, const double heightsMm[4])
{
    const double h = std::max(std::max(heightsMm[0], heightsMm[1]), std::max(heightsMm[2], heightsMm[3])) / 1000;
    if (lengthMm == 0 && widthMm == 0) return Opening{};
    if (widthMm == 0) return Opening::circle(lengthMm / 1000, h);  // b1 = 0: circular, diameter = length
    return Opening::rectangle(lengthMm / 1000, widthMm / 1000, h);
}

bool ldtDimensions(const Opening& o, double& lengthMm, double& widthMm, double& heightMm)
{
    lengthMm = o.lengthM * 1000, widthMm = o.widthM * 1000, heightMm = o.heightM * 1000;
    if (o.shape == OpeningShape::Point) return true;
    // A rectangle of width 0 would read back as a circle or a point (field 17 = 0).
    if (o.shape == OpeningShape::Rectangle) return o.widthM > 0;
    if (o.round()) {
        widthMm = 0;
        return true;
    }
    return false;
}

bool Tilt::trivial() const
{
    return std::all_of(factors.begin(), factors.end(), [](double f) { return f == 1; });
}

}  // namespace lb::photometry
