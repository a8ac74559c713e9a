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

void ltcInfo(const std::string& file, const std::string& againstFile, int ns)
{
    std::string path = file.empty() ? ltc::defaultTablePath() : file;
    ltc::Table t = ltc::read(path);
    double worst = 0, mean = 0;
    for (const auto& c : t.cells) {
        worst = std::max(worst, c.l1);
        mean += c.l1;
    }
    fmt::print("{}: {} x {} cells, frame {}, objective {}, samples {}, norm panels {}; relative L1 fit error "
               "(the fit's samples) mean {:.4f}, max {:.4f}\n",
               path, t.options.size, t.options.size, t.options.frame == ltc::Frame::Fixed ? "fixed" : "free",
               t.options.objective == ltc::Objective::L3 ? "l3" : "l1", t.options.samples, t.options.normPanels,
               mean / t.cells.size(), worst);
    std::string other = againstFile.empty() ? ltc::dataDir() + "/ltc/ggx-fixed.json" : againstFile;
    std::unique_ptr<ltc::Table> a;
    if (other != "none") {
        a = std::make_unique<ltc::Table>(ltc::read(other));
        fmt::print("against {}\n", other);
    }
    fmt::print("L1 distance int |norm D - f_r cos| dw / norm ({}^2 samples from each of the BRDF and the LTC), at "
               "the theta_o nodes and midpoints (bilinear lookup); midpoint excess: the largest L1 at a midpoint "
               "above both its nodes'\n{}",
               ns, ltc::qualitySummary(t, a.get(), ns));
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
    auto frame = std::make_shared<std::string>("free"), objective = std::make_shared<std::string>("l1");
    fit->add_option("--frame", *frame,
                    "free: the LTC's frame fitted too (default); fixed: pinned to the lobe's mean direction "
                    "(Heitz et al.)")
        ->check(CLI::IsMember({"fixed", "free"}));
    fit->add_option("--objective", *objective,
                    "l1: the L1 distance to the lobe (default); l3: Heitz et al.'s cubed difference")
        ->check(CLI::IsMember({"l1", "l3"}));
    fit->add_flag("--quiet", *quiet, "no per-cell lines");
    fit->callback([o, out, quiet, frame, objective] {
        o->frame = *frame == "fixed" ? ltc::Frame::Fixed : ltc::Frame::Free;
        o->objective = *objective == "l3" ? ltc::Objective::L3 : ltc::Objective::L1;
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

    auto* info = cmd->add_subcommand("info",
                                     "Summary of an LTC table file (default: the committed one) and, per alpha "
                                     "and theta_o range, its L1 distance to the lobe beside another table's");
    auto file = std::make_shared<std::string>();
    auto against = std::make_shared<std::string>();
    auto ns = std::make_shared<int>(64);
    info->add_option("file", *file, "table file (default data/ltc/ggx.json)");
    info->add_option("--against", *against,
                     "table to compare with (default data/ltc/ggx-fixed.json, the fixed-frame l3 fit; "
                     "'none': no comparison)");
    info->add_option("--samples", *ns, "sample grid per side of the L1 estimate")->check(CLI::Range(8, 1024));
    info->callback([file, against, ns] { ltcInfo(*file, *against, *ns); });
}

}  // namespace lb::cli
