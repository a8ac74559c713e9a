// Reading a luminaire file: by extension (.ldt / .ies, any case), else by
// content (an IES file has a TILT= line; EULUMDAT does not).
#include "photometry/load.h"

#include "photometry/ies.h"
#include "photometry/ldt.h"
#include "photometry/text.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include "lb_build_config.h"

namespace lb::photometry {

Table load(const std::string& pathIn)
{
    std::string path = pathIn;
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

void requireNoTilt(const Table& t)
{
    if (t.tilt.trivial()) return;
    auto [lo, hi] = std::minmax_element(t.tilt.factors.begin(), t.tilt.factors.end());
    throw InputError(fmt::format("{}: expected TILT=NONE or TILT=INCLUDE with every factor 1, got TILT=INCLUDE with "
                                 "factors {} .. {} over lamp tilts {} .. {} degrees: TILT=INCLUDE is not applied by "
                                 "the scene, so this file cannot be rendered as it is",
                                 t.source, *lo, *hi, t.tilt.anglesDeg.front(), t.tilt.anglesDeg.back()));
}

}  // namespace lb::photometry
