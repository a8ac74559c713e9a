// lumibench merge --out DIR IN... : merges the results of shards (directories
// holding results.json, or results files) into DIR/results.json, then writes
// DIR/results.csv, DIR/report.md, DIR/report.html and DIR/plots/ (unless
// --no-report).
#include "cli/commands.h"

#include "experiments/report.h"
#include "experiments/results.h"
#include "util/error.h"
#include "util/fileio.h"

#include <fmt/format.h>

#include <filesystem>
#include <set>
#include <iostream>

namespace lb::cli {

void addMergeCommand(CLI::App& app)
{
    struct Opts {
        std::vector<std::string> inputs;
        std::string out;
        bool noReport = false, force = false;
    };
    auto o = std::make_shared<Opts>();
    auto* cmd = app.add_subcommand(
        "merge",
        "Merge result directories of shards into one. Records are kept one per cell (method, parameters, "
        "luminaire, height, rotation, res, precision, device); of several, the one from the later input "
        "wins. An equal-time partner's cell is its scene, device, matched method and baseline (its MC SPEC): each "
        "method keeps one partner per scene and baseline, so runs with other baselines keep both. Inputs of different "
        "experiments or commits, and a record replaced by "
        "one computed from other inputs, are refused, naming both, unless --force.");
    cmd->add_option("inputs", o->inputs, "Result directories (with results.json) or results files")->required();
    cmd->add_option("--out", o->out, "Output directory (DIR/results.json, results.csv, report.md, report.html, plots/)")
        ->required()
        ->check(outDirPath());
    cmd->add_flag("--no-report", o->noReport, "Do not write report.md, report.html and plots");
    cmd->add_flag("--force", o->force,
                  "Write into a non-empty --out directory (its results.json is replaced), and merge inputs of "
                  "different experiments, commits or cell inputs (each difference and replacement is printed)");
    cmd->callback([o] {
        namespace fs = std::filesystem;
        std::error_code ec;
        if (fs::exists(o->out, ec) && !fs::is_directory(o->out, ec))
            throw InputError(fmt::format("--out {}: expected a directory, got a file", o->out));
        // Non-empty: anything in --out besides the inputs themselves (shard
        // directories inside the output, as experiments/run-parallel.sh makes).
        if (!o->force && fs::is_directory(o->out, ec)) {
            std::set<fs::path> inputs;
            for (const auto& in : o->inputs) inputs.insert(fs::weakly_canonical(in, ec));
            for (const auto& entry : fs::directory_iterator(o->out, ec))
                if (!inputs.count(fs::weakly_canonical(entry.path(), ec)))
                    throw InputError(fmt::format(
                        "--out {}: expected an empty or new directory, got one holding {} (merging would replace "
                        "its results); give --force to write there anyway",
                        o->out, entry.path().filename().string()));
        }
        std::vector<std::string> files;
        for (const auto& in : o->inputs)
            files.push_back(fs::is_directory(in, ec) ? (fs::path(in) / "results.json").string() : in);
        results::MergeStats st;
        auto doc = results::mergeResults(files, &st, {o->force});
        for (const auto& f : st.forced) std::cerr << "lumibench: warning: merge --force: " << f << '\n';
        fs::create_directories(o->out);
        util::removeStaleTemporaries(o->out);
        results::save((fs::path(o->out) / "results.json").string(), doc);
        results::saveCsv((fs::path(o->out) / "results.json").string(), doc);
        // Saved pictures come along, so the merged report can show them.
        for (const auto& in : o->inputs) {
            fs::path img = fs::path(in) / "images";
            if (fs::is_directory(in, ec) && fs::is_directory(img, ec) && fs::absolute(in) != fs::absolute(o->out))
                util::copyTreeAtomic(img.string(), (fs::path(o->out) / "images").string());
        }
        std::cerr << fmt::format("merged {} files: {} records in, {} out ({} replaced by a later one of the same "
                                 "cell and inputs{}) -> {}/results.json\n",
                                 st.files, st.records_in, st.records_out, st.replaced,
                                 st.forced.empty() ? "" : fmt::format("; {} differences forced", st.forced.size()),
                                 o->out);
        std::cerr << fmt::format("table: {}/results.csv (intervals: results_long.csv)\n", o->out);
        if (!o->noReport) {
            std::string note = experiments::makePlots(o->out);
            if (!note.empty()) std::cerr << "lumibench: warning: plots not made: " << note << '\n';
            experiments::writeReport(o->out, note);
            std::cerr << fmt::format("report: {}/report.html (and report.md)\n", o->out);
        }
    });
}

}  // namespace lb::cli
