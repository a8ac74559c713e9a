// lumibench compare (not implemented yet: see the open issues).
#include "cli/commands.h"

namespace lb::cli {

void addCompareCommand(CLI::App& app)
{
    auto* cmd = app.add_subcommand("compare", "Error metrics (NMSE, NRMSE, relMSE, UEB, LEB) of TEST.exr against REFERENCE.exr");
    cmd->allow_extras();
    cmd->callback([] { notImplemented("compare"); });
}

} // namespace lb::cli
