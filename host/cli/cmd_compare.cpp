// lumibench compare REFERENCE.exr TEST.exr [--json] [--png PREFIX] [--k K] [--bound B]
//
// The error metrics of docs/design.md section 5 (metrics/metrics.h, FLIP from
// metrics/flip.h) as a table or one JSON object, and optionally the pictures of a figure row: PREFIX_ref.png and
// PREFIX_test.png tone mapped with one k (default 1 / mean(reference), or --k
// so that several rows share one k), PREFIX_err.png (orange too bright, blue
// too dark, white no error, saturated at one symmetric bound: tonemap::sharedBound
// of this picture or --bound, so that several rows share one) and
// PREFIX_err.svg, the error picture with its colour bar in lux and in % of the
// reference mean.
#include "cli/commands.h"
#include "metrics/colour_bar.h"
#include "metrics/flip.h"
#include "metrics/image.h"
#include "metrics/metrics.h"
#include "metrics/png.h"
#include "metrics/tonemap.h"
#include "util/check.h"
#include "util/error.h"
#include "util/fileio.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>
#include <memory>

namespace lb::cli {

namespace {

struct CompareArgs {
    std::string ref, test, png;
    bool json = false;
    double k = 0;  // 0: default 1 / mean(reference)
    double bound = 0;  // 0: tonemap::sharedBound of the one picture
};

// "1.234567e-03" or "n/a" for an undefined value.
std::string num(double v) { return std::isfinite(v) ? fmt::format("{:.6e}", v) : std::string("n/a"); }

void runCompare(const CompareArgs& a)
{
    Image R = readExr(a.ref), A = readExr(a.test);
    metrics::Metrics m;
    try {
        m = metrics::compare(R, A);
    } catch (const InputError& e) {
        throw InputError(fmt::format("{} vs {}: {}", a.ref, a.test, e.what()));
    }
    m.flip = metrics::flip(R, A);  // NaN (null) with one warning when flip-evaluator is not available

    nlohmann::json j = m;
    j["reference"] = a.ref;
    j["test"] = a.test;
    j["width"] = R.width;
    j["height"] = R.height;

    if (!a.png.empty()) {
        double k = a.k;
        if (!(k > 0)) {
            try {
                k = tonemap::defaultK(R);
            } catch (const InputError& e) {
                throw InputError(fmt::format("{}; give --k", e.what()));
            }
        }
        // The one bound the error picture saturates at on both sides (0 when
        // the test is exact or every pixel non-finite: white, or magenta).
        const double bound = a.bound > 0 ? a.bound : tonemap::sharedBound(R, {&A});
        const std::string fr = a.png + "_ref.png", ft = a.png + "_test.png", fe = a.png + "_err.png",
                          fs = a.png + "_err.svg";
        const std::string err = encodePng(tonemap::errorPicture(R, A, bound, bound));
        util::writeFilesAtomic({{fr, encodePng(tonemap::tonemapPicture(R, k))},
                                {ft, encodePng(tonemap::tonemapPicture(A, k))},
                                {fe, err},
                                {fs, tonemap::errorFigureSvg(err, R.width, R.height, bound, m.mean_ref)}});
        j["k"] = k;
        j["bound"] = bound;
        j["bound_over"] = bound;
        j["bound_under"] = bound;
        j["colour_bar"] = tonemap::colourBar(33);
        j["pictures"] = {{"ref", fr}, {"test", ft}, {"err", fe}, {"err_svg", fs}};
    }

    // Said on stderr in both modes, so that it is seen even when stdout is parsed.
    if (m.nonfinite > 0)
        std::cerr << fmt::format("lumibench: warning: {} has {} non-finite pixels (excluded; magenta in pictures)\n",
                                 a.test, m.nonfinite);
    if (a.json) {
        std::cout << j.dump(2) << '\n';
        return;
    }
    std::cout << fmt::format("reference  {} ({}x{}, mean {} lx)\n", a.ref, R.width, R.height, num(m.mean_ref))
              << fmt::format("test       {} (mean {} lx)\n", a.test, num(m.mean_test))
              << fmt::format("pixels     {} ({} non-finite in test, excluded from every average)\n", m.pixels,
                             m.nonfinite)
              << fmt::format("NMSE       {}\n", num(m.nmse)) << fmt::format("NRMSE      {}\n", num(m.nrmse))
              << fmt::format("relMSE     {}\n", num(m.relmse))
              << fmt::format("UEB        {} lx (largest over-estimate, max(test - reference, 0))\n", num(m.ueb))
              << fmt::format("LEB        {} lx (largest under-estimate, min(test - reference, 0))\n", num(m.leb))
              << fmt::format("grad NMSE  {} (NMSE of the neighbour differences, {} pairs)\n", num(m.grad_nmse),
                             m.grad_pairs)
              << fmt::format("FLIP       {} (mean HDR-FLIP, NVIDIA flip-evaluator)\n", num(m.flip));
    if (!a.png.empty())
        std::cout << fmt::format("pictures   {} {} {} {} (k = {}, error saturates at +-{} lx, {:.3g} % of the "
                                 "reference mean)\n",
                                 j["pictures"]["ref"].get<std::string>(), j["pictures"]["test"].get<std::string>(),
                                 j["pictures"]["err"].get<std::string>(), j["pictures"]["err_svg"].get<std::string>(),
                                 num(j["k"].get<double>()), num(j["bound"].get<double>()),
                                 100 * j["bound"].get<double>() / m.mean_ref);
}

}  // namespace

void addCompareCommand(CLI::App& app)
{
    auto* cmd = app.add_subcommand("compare",
                                   "Error metrics (NMSE, NRMSE, relMSE, UEB, LEB, grad_nmse, FLIP) of TEST.exr against "
                                   "REFERENCE.exr, and pictures");
    auto a = std::make_shared<CompareArgs>();
    cmd->add_option("reference", a->ref, "Reference image (OpenEXR, channel Y, lux)")->required();
    cmd->add_option("test", a->test, "Test image of the same size")->required();
    cmd->add_flag("--json", a->json,
                  "Print one JSON object (nmse, nrmse, relmse, ueb, leb, nonfinite, pixels, "
                  "mean_ref, mean_test, grad_nmse, grad_pairs, flip, ...) instead of a table; "
                  "flip is null when flip-evaluator cannot be imported");
    cmd->add_option("--png", a->png,
                    "Write PREFIX_ref.png, PREFIX_test.png (tone mapped), PREFIX_err.png "
                    "(orange too bright, blue too dark, white no error, magenta non-finite) and PREFIX_err.svg "
                    "(the error picture with its colour bar in lux and in % of the reference mean)")
        ->check(outFilePath());
    cmd->add_option("--k", a->k,
                    "Tone-mapping scale: display L/(1+L) of L = k E (default 1/mean(reference); "
                    "give one k to every row of a figure; positive and finite)");
    cmd->add_option("--bound", a->bound,
                    "Error (lux) at which the error picture saturates on both sides (give every row of a "
                    "figure the same; default the 99.9th percentile of |test - reference|, docs/figures.md; "
                    "positive and finite)");
    cmd->callback([a, cmd] {
        // Any positive finite value; the bounds only keep nan, inf and 0 out.
        if (cmd->count("--k")) util::checkRange("--k", a->k, 1e-300, 1e300);
        if (cmd->count("--bound")) util::checkRange("--bound", a->bound, 1e-300, 1e300, "lux");
        runCompare(*a);
    });
}

}  // namespace lb::cli
