// lumibench run (not implemented yet: see the open issues).
#include "cli/commands.h"

namespace lb::cli {

void addRunCommand(CLI::App& app)
{
    auto* cmd = app.add_subcommand("run", "Run an experiment file (experiments/*.json) into a results directory");
    cmd->allow_extras();
    cmd->callback([] { notImplemented("run"); });
}

} // namespace lb::cli
