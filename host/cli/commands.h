// commands.h -- every subcommand of build/lumibench registers itself here, one
// file per command (cmd_<name>.cpp), so commands can grow independently.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace lb::cli {

void addDevicesCommand(CLI::App& app);
void addLuminaireCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addCompareCommand(CLI::App& app);
void addRunCommand(CLI::App& app);
void addMergeCommand(CLI::App& app);
void addReportCommand(CLI::App& app);
void addTuneCommand(CLI::App& app);
void addStabilityCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);

// For commands whose issue has not landed: a clear message and exit code 3.
[[noreturn]] void notImplemented(const std::string& what);

// An angle in radians from a number or an expression like pi, 3pi/4, 3*pi/4,
// 0.75pi (cmd_render.cpp); InputError otherwise.
double parseAngle(const std::string& text);

} // namespace lb::cli
