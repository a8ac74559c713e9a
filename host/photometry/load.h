// load.h -- reading luminaire files into a Table (docs/design.md section 3).
#pragma once

#include "photometry/table.h"

#include <string>

namespace lb::photometry {

// Reads an IES LM-63 or EULUMDAT file (chosen by extension, then by content)
// into an unfolded table of absolute candela. Bad input throws lb::InputError
// with "FILE:LINE: expected ..., got ...".
Table load(const std::string& path);

// IES TILT=INCLUDE as LM-63 intends it: the candela values hold for the lamp
// untilted, and a luminaire tilted by g degrees multiplies them by the
// factor of g in the file's table. The scene's light looks straight down at
// rotation R = pi, so its tilt is g = |180 - R in degrees| (0 at R = pi, 90
// at pi/2, 180 facing up), folded to 180 - g above 90 when the table ends at
// 90 degrees (as Radiance's ies2rad does for a vertical lamp, geometry 1:
// tilt.cal's tilt_ang and tilt_ang2; geometries 2 and 3 take the same angle
// here). The factor is interpolated linearly between the table's angles and
// held at its end values beyond them. 1 without a table.
double lampTiltDeg(double rotation);
double tiltFactor(const Tilt& t, double rotation);
// The table a scene of rotation R renders: every candela value times
// tiltFactor(t.tilt, R), the tilt table dropped (it is applied).
Table tiltedFor(const Table& t, double rotation);

}  // namespace lb::photometry
