// ies.h -- IES LM-63 (1986/1991/1995/2002/2019) reading and writing (docs/design.md section 3).
#pragma once

#include "photometry/table.h"
#include "photometry/text.h"

#include <string>
#include <vector>

namespace lb::photometry {

// What an IES file says beyond the table (kept, not applied).
struct IesExtra {
    std::string version;  // first line, e.g. "IESNA:LM-63-2002" ("" for LM-63-1986)
    std::string tilt;  // "NONE", "INCLUDE" (a TILT=<file> is rejected)
    int tiltGeometry = 0;  // lamp-to-luminaire geometry 1..3 (INCLUDE only)
    std::vector<double> tiltAngles, tiltFactors;
    double lampLumens = 0;  // per lamp; -1 = absolute photometry
    int lamps = 0;
    double multiplier = 1, ballastFactor = 1, ballastLampFactor = 1, inputWatts = 0;
    int photometricType = 1;
};

// Reads a type C file: absolute cd = value x candela multiplier x ballast
// factor x ballast-lamp photometric factor. Horizontal angle sets {0}, 0-90,
// 0-180, 90-270, 0-360 and 0-(180, 360) (360 added, equal to 0); vertical
// 0-90, 90-180, 0-180. Type B and A files are rejected with a clear message.
// Bad input throws InputError "FILE:LINE: expected ..., got ...".
Table readIes(const TextFile& f, IesExtra* extra = nullptr);
Table readIes(const std::string& path, IesExtra* extra = nullptr);

// LM-63-2002 text of the full table (0-360 horizontal, or {0} when every
// plane is equal, i.e. the table has C = {0, 360}), TILT=NONE, lumens -1, multiplier 1, metres.
std::string iesText(const Table& t, const std::string& name);
void writeIes(const Table& t, const std::string& path, const std::string& name);

}  // namespace lb::photometry
