// lumibench tune (not implemented yet: see the open issues).
#include "cli/commands.h"

namespace lb::cli {

void addTuneCommand(CLI::App& app)
{
    auto* cmd = app.add_subcommand("tune", "Tune epsilons and sample placement with nlopt against NMSE");
    cmd->allow_extras();
    cmd->callback([] { notImplemented("tune"); });
}

} // namespace lb::cli
