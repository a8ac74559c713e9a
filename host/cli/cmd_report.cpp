// lumibench report DIR: re-makes DIR/plots/ and DIR/report.md from
// DIR/results.json without re-running anything.
#include "cli/commands.h"

#include "experiments/report.h"

#include <iostream>

namespace lb::cli {

void addReportCommand(CLI::App& app)
{
    auto dir = std::make_shared<std::string>();
    auto noPlots = std::make_shared<bool>(false);
    auto* cmd = app.add_subcommand("report", "Write DIR/report.md and DIR/plots/ from DIR/results.json");
    cmd->add_option("dir", *dir, "Results directory")->required();
    cmd->add_flag("--no-plots", *noPlots, "Tables only");
    cmd->callback([dir, noPlots] {
        std::string note = *noPlots ? std::string("--no-plots") : experiments::makePlots(*dir);
        if (!note.empty() && !*noPlots) std::cerr << "lumibench: warning: plots not made: " << note << '\n';
        experiments::writeReport(*dir, note);
        std::cerr << "report: " << *dir << "/report.md\n";
    });
}

} // namespace lb::cli
