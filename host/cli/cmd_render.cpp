// lumibench render (issue: scene, reference, baselines).
#include "cli/commands.h"

namespace lb::cli {

void addRenderCommand(CLI::App& app)
{
    auto* cmd = app.add_subcommand("render", "Render the normalized evaluation scene with one method to OpenEXR");
    cmd->add_option("--luminaire", "IES or LDT file")->required();
    cmd->add_option("--method", "Method SPEC, e.g. mc:n=24")->required();
    cmd->add_option("--height", "Height h of the light")->required();
    cmd->add_option("--rotation", "Rotation R in radians (pi/2 .. pi)")->required();
    cmd->add_option("--out", "Output .exr")->required();
    cmd->callback([] { notImplemented("render"); });
}

} // namespace lb::cli
