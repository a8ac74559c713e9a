// commands.h -- every subcommand of build/lumibench registers itself here, one
// file per command (cmd_<name>.cpp), so commands can grow independently.
#pragma once

#include "methods/registry.h"
#include "scene/scene.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

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
void addLtcCommand(CLI::App& app);
void addSequenceCommand(CLI::App& app);
void addMethodsCommand(CLI::App& app);

// Every numeric flag of `app` and its subcommands parsed strictly: a plain
// decimal number, the whole value (no empty value, no 0x10, no nan); call
// after every command is registered.
void strictNumericFlags(CLI::App& app);
// Checks of an --out flag: a non-empty path that is a regular file or does
// not exist yet (outFilePath), or a directory or does not exist yet
// (outDirPath). A FIFO or device (/dev/null) is refused: it would block or
// be replaced.
CLI::Validator outFilePath();
CLI::Validator outDirPath();

// The normalized scene from the flags render and bench share, each
// range-checked with a message naming the flag (limits in scene/scene.h;
// cmd_render.cpp).
Scene sceneFromFlags(double height, const std::string& rotation, const std::string& size, double extent, int res);

// The --device flag: -1 (the default device) when not given, else an index >= 0.
int deviceFlag(const CLI::App& cmd, int device);
// The --precision flag: float or double.
methods::Precision precisionFlag(const std::string& text);
// --scene, --alpha, --eye, --albedo into scene (a flag of another kind is an error).
void sceneKindFromFlags(const CLI::App& cmd, const std::string& kind, double alpha, const std::string& eye,
                        double albedo, Scene& scene);
// The devices as `devices --json` prints them (index, name, ..., default).
nlohmann::json devicesJson();
// A work-group size "WxH" (bench --local) into lx, ly; InputError naming
// `name` unless both are >= 1 with lx * ly <= 1024.
void parseLocal(const std::string& name, const std::string& text, size_t& lx, size_t& ly);
// The scene as `render --json` prints it (kind and the kind's values included).
nlohmann::json sceneJson(const Scene& scene);

}  // namespace lb::cli
