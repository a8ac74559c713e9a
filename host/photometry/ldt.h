// ldt.h -- EULUMDAT (.ldt) reading and writing (docs/design.md section 3).
#pragma once

#include "photometry/table.h"
#include "photometry/text.h"

#include <string>

namespace lb::photometry {

// Reads an EULUMDAT file: Isym 0-4 unfolded to C in [0, 360], any number of
// lamp sets (absolute cd = value x sum of the sets' lamp flux / 1000; the
// number of lamps, which some files give negative, does not enter), decimal
// commas, CRLF. Bad input throws InputError "FILE:LINE: expected ..., got ...".
Table readLdt(const TextFile& f);
Table readLdt(const std::string& path);

// Writes the full table (Isym 1 for a one-plane table with C = {0, 360}, else Isym 0) with
// one lamp set whose flux is the table's declared flux (else its integrated
// flux) and LOR 100 %. Reading it back gives the same table (to ~1e-15).
std::string ldtText(const Table& t, const std::string& name);
void writeLdt(const Table& t, const std::string& path, const std::string& name);

}  // namespace lb::photometry
