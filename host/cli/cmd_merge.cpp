// lumibench merge (not implemented yet: see the open issues).
#include "cli/commands.h"

namespace lb::cli {

void addMergeCommand(CLI::App& app)
{
    auto* cmd = app.add_subcommand("merge", "Merge result directories of shards into one");
    cmd->allow_extras();
    cmd->callback([] { notImplemented("merge"); });
}

} // namespace lb::cli
