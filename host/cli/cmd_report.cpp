// lumibench report DIR: re-makes DIR/results.csv, DIR/plots/, DIR/report.md
// and DIR/report.html from DIR/results.json without re-running anything.
#include "cli/commands.h"

#include "experiments/report.h"
#include "experiments/results.h"

#include <filesystem>

#include <iostream>

namespace lb::cli {

void addReportCommand(CLI::App& app)
{
    auto dir = std::make_shared<std::string>();
    auto noPlots = std::make_shared<bool>(false);
    auto* cmd = app.add_subcommand(
        "report", "Write DIR/results.csv, DIR/report.md, DIR/report.html and DIR/plots/ from DIR/results.json");
    cmd->add_option("dir", *dir, "Results directory")->required();
    cmd->add_flag("--no-plots", *noPlots, "Tables only");
    cmd->callback([dir, noPlots] {
        const std::string json = (std::filesystem::path(*dir) / "results.json").string();
        if (results::exists(json)) results::compact(json, {});  // an interrupted run's journal folded in
        results::Results doc = results::load(json);
        experiments::nameLuminaires(doc);  // older records: the names their files give
        results::saveCsv(json, doc);
        experiments::ReportSteps steps;
        std::filesystem::path name(*dir);
        if (name.filename().empty()) name = name.parent_path();  // "out/main/"
        steps.tag = name.filename().string();
        if (*noPlots) steps.plotNote = "--no-plots";
        experiments::makeReport(*dir, steps);
        std::cerr << "report: " << *dir << "/report.html (and report.md; the records as a table: results.csv)\n";
    });
}

}  // namespace lb::cli
