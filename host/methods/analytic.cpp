#include "methods/analytic.h"

#include "photometry/load.h"
#include "util/error.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

namespace lb::methods {

photometry::Table cosineTable(int n, double i0, bool twoSided, double stepDeg)
{
    const double deg = 3.14159265358979323846 / 180.0;
    auto t = photometry::tabulate(
        [&](double, double g) {
            double c = std::cos(g * deg);
            if (g >= 90.0 && !twoSided) return 0.0;
            return i0 * std::pow(std::fabs(c), n);
        },
        2, static_cast<int>(std::lround(180.0 / stepDeg)) + 1);
    t.format = "analytic";
    t.isym = 1;
    t.symmetry = "rotational";
    return t;
}

photometry::Table loadLuminaire(const std::string& s)
{
    const std::string pre = "analytic:cos";
    if (s.rfind(pre, 0) != 0) return photometry::load(s);  // a TILT table is applied per scene (render.h)
    std::string rest = s.substr(pre.size());
    bool two = false;
    if (auto p = rest.find(":two"); p != std::string::npos && p + 4 == rest.size()) {
        two = true;
        rest = rest.substr(0, p);
    }
    char* end = nullptr;
    long n = std::strtol(rest.c_str(), &end, 10);
    if (rest.empty() || *end || n < 0 || n > 200)
        throw InputError("luminaire '" + s + "': expected analytic:cos<n>[:two] with n in 0..200");
    auto t = cosineTable(static_cast<int>(n), 1000.0, two);
    t.source = s;
    return t;
}

void sizeFromFile(const photometry::Table& t, Scene& scene, const std::string& what)
{
    using photometry::OpeningShape;
    photometry::Opening face;
    if (!t.opening.flatFace(face) || face.shape == OpeningShape::Point || !(face.lengthM > 0 && face.widthM > 0))
        throw InputError(fmt::format("{}: '{}' declares no flat luminous opening to size the light by (its opening: "
                                     "{} {} x {} x {} m); give --size WxL (experiment key size: [W, L])",
                                     what, t.source, photometry::shapeName(t.opening.shape), t.opening.lengthM,
                                     t.opening.widthM, t.opening.heightM));
    scene.width = face.lengthM;
    scene.length = face.widthM;
    scene.shape = face.shape == OpeningShape::Rectangle ? LightShape::Rect : LightShape::Disk;
}

}  // namespace lb::methods
