// lumibench tune EXP --out DIR: nlopt search of a method's continuous
// parameters against the NMSE over the experiment's training scenes (host/tune).
#include "cli/commands.h"
#include "tune/tune.h"
#include "util/check.h"

#include <fmt/format.h>

#include <memory>

namespace lb::cli {

void addTuneCommand(CLI::App& app)
{
    struct Opts {
        std::string exp, out;
        int device = -1;
        bool quiet = false, noPlot = false;
        int maxeval = 0;
        double maxtime = -1;
    };
    auto o = std::make_shared<Opts>();
    auto* cmd = app.add_subcommand("tune", "Tune epsilons and sample placement with nlopt against NMSE");
    cmd->add_option("experiment", o->exp, "Tune experiment file, e.g. experiments/tune-smoke.json")->required();
    cmd->add_option("--out", o->out, "Output directory (tune.json, tune.png)")->required()->check(outDirPath());
    cmd->add_option("--maxeval", o->maxeval, "Override the experiment's evaluation budget (1 .. 1e6)");
    cmd->add_option("--maxtime", o->maxtime, "Override the experiment's time budget (seconds, 0 .. 1e7, 0 = none)");
    cmd->add_option("--device", o->device, "OpenCL device index >= 0 (lumibench devices)");
    cmd->add_flag("--no-plot", o->noPlot, "Do not draw tune.png");
    cmd->add_flag("--quiet", o->quiet, "No progress lines on stderr");
    cmd->callback([o, cmd] {
        tune::TuneExperiment e = tune::loadTuneExperiment(o->exp);
        // The same bounds as the tune file's maxeval and maxtime keys.
        if (cmd->count("--maxeval")) e.maxeval = util::checkRange("--maxeval", o->maxeval, 1, 1000000);
        if (cmd->count("--maxtime")) e.maxtime = util::checkRange("--maxtime", o->maxtime, 0.0, 1e7, "s");
        tune::TuneOptions t;
        t.outDir = o->out;
        t.device = deviceFlag(*cmd, o->device);
        t.quiet = o->quiet;
        t.plot = !o->noPlot;
        auto doc = tune::runTune(e, t);
        // With cross-validation its table first; the tuned SPEC is always the last line.
        if (auto table = tune::crossValidationTable(doc); !table.empty()) fmt::print("{}\n", table);
        fmt::print("{}\n", doc["tuned"]["spec"].get<std::string>());
    });
}

}  // namespace lb::cli
