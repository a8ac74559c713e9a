// lumibench ltc fit|info: the suite's own LTC table for the specular scene
// (host/ltc/ltc.h; the committed table is data/ltc/ggx.json).
#include "cli/commands.h"

#include "ltc/ltc.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace lb::cli {

namespace {

struct FitPrint {
    bool quiet;
};

void printCell(const ltc::Table& t, int i, int j, void* user)
{
    if (static_cast<FitPrint*>(user)->quiet) return;
    const ltc::Cell& c = t.at(i, j);
    std::fprintf(stderr, "cell %2d %2d  alpha %.5f  theta %.4f  norm %.6f  error %.3e  l1 %.4f\n", i, j, t.alpha(i),
                 t.theta(j), c.norm, c.error, c.l1);
}

}  // namespace

void addLtcCommand(CLI::App& app)
{
    auto* cmd =
        app.add_subcommand("ltc", "The LTC table of the specular scene (Heitz et al. 2016 fit, data/ltc/ggx.json)");
    cmd->require_subcommand(1);

    auto* fit =
        cmd->add_subcommand("fit", "Fit the LTC table (deterministic) and write it; prints the fit error per cell");
    auto o = std::make_shared<ltc::FitOptions>();
    auto out = std::make_shared<std::string>();
    auto quiet = std::make_shared<bool>(false);
    fit->add_option("--out", *out, "table file to write (JSON)")->required()->check(outFilePath());
    fit->add_option("--size", o->size, "cells per side (roughness x view angle)")->check(CLI::Range(2, 1024));
    fit->add_option("--samples", o->samples, "sample grid per side of the fit error")->check(CLI::Range(4, 1024));
    fit->add_option("--norm-panels", o->normPanels, "Gauss-Legendre panels per side of the albedo")
        ->check(CLI::Range(4, 1024));
    fit->add_option("--max-eval", o->maxEval, "Nelder-Mead evaluations per cell at most")
        ->check(CLI::Range(10, 100000));
    fit->add_option("--power", o->power, "exponent of the fit error (Heitz et al.: 3)")->check(CLI::Range(1.0, 4.0));
    fit->add_flag("--quiet", *quiet, "no per-cell lines");
    fit->callback([o, out, quiet] {
        FitPrint p{*quiet};
        ltc::Table t = ltc::fit(*o, printCell, &p);
        ltc::write(t, *out);
        double worst = 0, mean = 0;
        for (const auto& c : t.cells) {
            worst = std::max(worst, c.l1);
            mean += c.l1;
        }
        fmt::print("wrote {} ({} x {} cells); relative L1 fit error: mean {:.4f}, max {:.4f}\n", *out, o->size, o->size,
                   mean / t.cells.size(), worst);
    });

    auto* info = cmd->add_subcommand("info", "Summary of an LTC table file (default: the committed one)");
    auto file = std::make_shared<std::string>();
    info->add_option("file", *file, "table file (default data/ltc/ggx.json)");
    info->callback([file] {
        std::string path = file->empty() ? ltc::defaultTablePath() : *file;
        ltc::Table t = ltc::read(path);
        double worst = 0, mean = 0;
        for (const auto& c : t.cells) {
            worst = std::max(worst, c.l1);
            mean += c.l1;
        }
        fmt::print("{}: {} x {} cells, samples {}, norm panels {}; relative L1 fit error mean {:.4f}, max {:.4f}\n",
                   path, t.options.size, t.options.size, t.options.samples, t.options.normPanels, mean / t.cells.size(),
                   worst);
    });
}

}  // namespace lb::cli
