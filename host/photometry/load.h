// load.h -- reading luminaire files into a Table (docs/design.md section 3).
#pragma once

#include "photometry/table.h"

#include <string>

namespace lb::photometry {

// Reads an IES LM-63 or EULUMDAT file (chosen by extension, then by content)
// into an unfolded table of absolute candela. Bad input throws lb::InputError
// with "FILE:LINE: expected ..., got ...".
Table load(const std::string& path);

// For a scene: throws InputError naming the file when its TILT=INCLUDE
// table has a factor other than 1, which the scene does not apply (the
// factor of the lamp's tilt angle would scale every candela value).
void requireNoTilt(const Table& t);

}  // namespace lb::photometry
