// Reading a luminaire file: by extension (.ldt / .ies, any case), else by
// content (an IES file has a TILT= line; EULUMDAT does not).
#include "photometry/load.h"

#include "photometry/ies.h"
#include "photometry/ldt.h"
#include "photometry/text.h"
#include "util/check.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cctype>
#include <filesystem>
#include "lb_build_config.h"

namespace lb::photometry {

Table load(const std::string& pathIn)
{
    std::string path = util::requireUtf8(pathIn, "the luminaire file");  // every output holds the name as text
    // The suite's own luminaires by short name: "lambert" -> luminaires/lambert.ldt.
    namespace fs = std::filesystem;
    // error_code forms: a link loop or an unreadable directory is the reader's
    // complaint (naming the file, exit 2), not an exception from here.
    std::error_code ec;
    if (!fs::exists(path, ec) && fs::path(path).extension().empty() && path.find('/') == std::string::npos) {
        fs::path own = fs::path(LB_SOURCE_DIR) / "luminaires" / (path + ".ldt");
        if (fs::exists(own, ec)) path = own.string();
    }
    TextFile f = TextFile::read(path);
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".ldt") return readLdt(f);
    if (ext == ".ies") return readIes(f);
    for (const auto& l : f.lines)
        if (l.find("TILT=") != std::string::npos) return readIes(f);
    return readLdt(f);
}

double lampTiltDeg(double rotation) { return std::fabs(180.0 - rotation * 180.0 / 3.14159265358979323846); }

double tiltFactor(const Tilt& t, double rotation)
{
    if (t.factors.empty() || t.factors.size() != t.anglesDeg.size()) return 1;
    const std::vector<double>& a = t.anglesDeg;
    // a table that ends at 90 degrees holds a lamp the same tilted either way
    const double g = a.back() <= 90 ? 90 - std::fabs(90 - lampTiltDeg(rotation)) : lampTiltDeg(rotation);
    if (g <= a.front()) return t.factors.front();
    if (g >= a.back()) return t.factors.back();
    const size_t k = size_t(std::upper_bound(a.begin(), a.end(), g) - a.begin());  // a[k-1] <= g < a[k]
    const double w = (g - a[k - 1]) / (a[k] - a[k - 1]);
    return (1 - w) * t.factors[k - 1] + w * t.factors[k];
}

Table tiltedFor(const Table& t, double rotation)
{
    Table out = t;
    out.tilt = Tilt{};
    const double f = tiltFactor(t.tilt, rotation);
    if (f != 1)
        for (double& v : out.cd) v *= f;
    return out;
}

}  // namespace lb::photometry
