// lumibench bench (not implemented yet: see the open issues).
#include "cli/commands.h"

namespace lb::cli {

void addBenchCommand(CLI::App& app)
{
    auto* cmd = app.add_subcommand("bench", "Benchmark kernels against naive versions");
    cmd->allow_extras();
    cmd->callback([] { notImplemented("bench"); });
}

} // namespace lb::cli
