// lumibench luminaire info|eval|synth (issue: photometric data).
#include "cli/commands.h"

namespace lb::cli {

void addLuminaireCommand(CLI::App& app)
{
    auto* cmd = app.add_subcommand("luminaire", "Read, evaluate and synthesise luminaires (IES LM-63, EULUMDAT)");
    cmd->require_subcommand(1);
    auto* info = cmd->add_subcommand("info", "Summary of a luminaire file (format, flux, max cd, symmetry, grid)");
    info->add_option("file", "IES or LDT file")->required();
    info->add_flag("--json", "Print one JSON object");
    info->callback([] { notImplemented("luminaire info"); });
    auto* eval = cmd->add_subcommand("eval", "Absolute candela at (gamma, C) pairs in degrees, one per line");
    eval->add_option("file", "IES or LDT file")->required();
    eval->add_option("angles", "GAMMA C [GAMMA C ...]")->required();
    eval->callback([] { notImplemented("luminaire eval"); });
}

} // namespace lb::cli
