// Placeholder until the photometry issue lands its readers.
#include "photometry/load.h"

#include "util/error.h"

namespace lb::photometry {

Table load(const std::string& path)
{
    throw Error(path + ": luminaire readers not implemented yet", kExitNotImplemented);
}

} // namespace lb::photometry
