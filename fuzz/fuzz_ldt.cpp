// libFuzzer target for the EULUMDAT reader: any input ends in a Table that
// passed validate() or in lb::InputError; anything else is a bug.
// Build and run: see fuzz/README.md.
#include "photometry/ldt.h"
#include "util/error.h"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::string text(reinterpret_cast<const char*>(data), size);
    try {
        auto t = lb::photometry::readLdt(lb::photometry::TextFile::fromString("fuzz.ldt", text));
        t.validate();
    } catch (const lb::InputError&) {
    }
    return 0;
}
