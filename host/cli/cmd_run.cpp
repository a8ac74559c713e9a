// lumibench run EXP --out DIR [--luminaires DIR] [--shard K/N] [--res N] [--reps K]
// [--device I] [--no-report]: runs an experiment file into DIR/results.json
// and DIR/results.csv, then writes DIR/report.md, DIR/report.html and
// DIR/plots/ (host/experiments/runner.h, report.h).
#include "cli/commands.h"

#include "experiments/report.h"
#include "experiments/runner.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>

namespace lb::cli {

void addRunCommand(CLI::App& app)
{
    struct Opts {
        std::string exp, out, luminaires, shard = "1/1";
        int res = 0, reps = 0, timeRes = 0, seeds = 0, device = -1;
        bool noReport = false, quiet = false;
    };
    auto o = std::make_shared<Opts>();
    auto* cmd = app.add_subcommand("run", "Run an experiment file (experiments/*.json) into a results directory");
    cmd->add_option("experiment", o->exp, "Experiment file, e.g. experiments/smoke.json")->required();
    cmd->add_option("--out", o->out,
                    "Results directory (results.json, results.csv, report.md, report.html, plots/, images/); "
                    "a rerun resumes: it skips the cells already there and recomputes those "
                    "whose inputs changed (scene, method, reference, luminaire file content, "
                    "kernel sources, reps, time_res)")
        ->required()
        ->check(outDirPath());
    cmd->add_option("--luminaires", o->luminaires,
                    "Use every .ldt/.ies file in this directory instead of the "
                    "experiment's list");
    cmd->add_option("--shard", o->shard, "Run shard K of N: the scenes with index % N == K-1")->capture_default_str();
    cmd->add_option("--res", o->res, "Override the experiment's resolution (1 .. 16384)");
    cmd->add_option("--reps", o->reps, "Override the experiment's timed runs per cell (5 .. 1000)");
    cmd->add_option("--time-res", o->timeRes,
                    "Override the experiment's timing resolution: every method is timed at N x N pixels "
                    "(default 512, DESIGN 6; 0 .. 16384, 0 = at --res), whatever the error image's --res");
    cmd->add_option("--seeds", o->seeds,
                    "Override the experiment's seeds: methods with a seed (mc) are rendered with R seeds, their "
                    "records the mean with a 95 % interval (default 8; 1 .. 1000; 1 = one draw)");
    cmd->add_option("--device", o->device, "OpenCL device index >= 0 (lumibench devices)");
    cmd->add_flag("--no-report", o->noReport, "Do not write report.md, report.html and plots (e.g. for shards)");
    cmd->add_flag("--quiet", o->quiet, "No progress lines on stderr");
    std::string keys;
    for (const auto& k : experiments::experimentKeys()) keys += (keys.empty() ? "" : ", ") + k;
    cmd->footer(
        "Experiment keys: " + keys +
        ". Every key with its range and default: docs/experiments.md. Leaving out time_res times every "
        "method at 512 x 512 whatever res is (the paper's scale; a small experiment then still takes the "
        "time of 512^2 launches); seeds (default 8) renders methods with a seed that many times. The "
        "report opens with the answer in one sentence and the verdicts at equal time: per method and Monte Carlo "
        "baseline (\"mc\": a SPEC or a list of {\"label\", \"spec\"}), wins / ties / losses by 95 % "
        "intervals over the seeds, and the off-time pairs (outside equal_time_tolerance) apart, with why.");
    cmd->callback([o, cmd] {
        experiments::Overrides ov;  // range-checked by loadExperiment like the keys they replace
        ov.name = [](const std::string& key) {  // the flag: "time_res" -> "--time-res"
            std::string flag = "--" + key;
            std::replace(flag.begin(), flag.end(), '_', '-');
            return flag;
        };
        ov.luminaireDir = o->luminaires;
        if (cmd->count("--res")) ov.res = o->res;
        if (cmd->count("--reps")) ov.reps = o->reps;
        if (cmd->count("--time-res")) ov.timeRes = o->timeRes;
        if (cmd->count("--seeds")) ov.seeds = o->seeds;
        experiments::RunOptions ro;
        experiments::parseShard("--shard", o->shard, ro.shardK, ro.shardN);
        auto e = experiments::loadExperiment(o->exp, ov);
        ro.outDir = o->out;
        ro.device = deviceFlag(*cmd, o->device);
        ro.progress = !o->quiet;
        auto s = experiments::run(e, ro);
        std::cerr << fmt::format(
            "[{}] shard {}/{}: {} scenes, {} cells ({} computed, {} of them recomputed because "
            "their inputs changed, {} already done), {} equal-time partners off-time (no verdict), {:.1f} s "
            "-> {}/results.json and results.csv{}\n",
            e.name, ro.shardK, ro.shardN, s.scenes, s.cells, s.computed, s.stale, s.skipped, s.equalTimeOff, s.seconds,
            o->out,
            s.dropped ? fmt::format(" ({} records of cells no longer in the experiment moved to "
                                    "results.dropped.json)",
                                    s.dropped)
                      : "");
        if (!o->noReport) {
            experiments::ReportSteps steps;
            steps.tag = e.name;
            steps.progress = !o->quiet;
            experiments::makeReport(o->out, steps);
            std::cerr << fmt::format("[{}] report: {}/report.html (and report.md)\n", e.name, o->out);
        }
    });
}

}  // namespace lb::cli
