// lumibench stability (not implemented yet: see the open issues).
#include "cli/commands.h"

namespace lb::cli {

void addStabilityCommand(CLI::App& app)
{
    auto* cmd = app.add_subcommand("stability", "Run every method on the catalogue of extreme scenes");
    cmd->allow_extras();
    cmd->callback([] { notImplemented("stability"); });
}

} // namespace lb::cli
