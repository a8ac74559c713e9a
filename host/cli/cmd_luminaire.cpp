// lumibench luminaire info|eval|dump|synth|convert.
#include "cli/commands.h"

#include "methods/sh_fit.h"

#include "photometry/ies.h"
#include "photometry/ldt.h"
#include "photometry/load.h"
#include "photometry/synth.h"
#include "photometry/text.h"
#include "util/error.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

namespace lb::cli {

namespace {

using photometry::Table;

nlohmann::json summary(const Table& t)
{
    nlohmann::json j;
    j["file"] = t.source;
    j["format"] = t.format;
    double flux = t.fluxLm();
    j["flux_lm"] = flux;
    j["declared_flux_lm"] = t.declaredFluxLm > 0 ? nlohmann::json(t.declaredFluxLm) : nlohmann::json(nullptr);
    if (t.declaredFluxLm > 0) j["flux_rel_diff"] = flux / t.declaredFluxLm - 1;
    j["max_cd"] = t.maxCd();
    j["isym"] = t.isym;
    j["symmetry"] = t.symmetry;
    j["c_planes"] = t.nc();
    j["gammas"] = t.ng();
    j["gamma_range"] = {t.gamma.front(), t.gamma.back()};
    // The luminous opening: length along C0-C180, width along C90-C270 (opening.h).
    j["shape"] = photometry::shapeName(t.opening.shape);
    j["length_m"] = t.opening.lengthM;
    j["width_m"] = t.opening.widthM;
    j["height_m"] = t.opening.heightM;
    if (t.format == "ies") {
        photometry::IesExtra x;
        photometry::readIes(t.source, &x);
        j["ies"] = {{"version", x.version},
                    {"tilt", x.tilt},
                    {"tilt_factors_all_1", t.tilt.trivial()},
                    {"lamps", x.lamps},
                    {"lamp_lumens", x.lampLumens},
                    {"multiplier", x.multiplier},
                    {"ballast_factor", x.ballastFactor},
                    {"ballast_lamp_factor", x.ballastLampFactor},
                    {"input_watts", x.inputWatts}};
    }
    return j;
}

// "12.5" -> 12.5, or an InputError naming the argument.
double angleArg(const std::string& s, const char* what)
{
    double v;
    if (!photometry::parseNumber(s, v, false))
        throw InputError(fmt::format("luminaire eval: expected {} in degrees, got {}", what, photometry::quote(s)));
    return v;
}

// Writes t as OUT's extension says (.ldt or .ies, any case), named by OUT's stem.
void writeByExtension(const Table& t, const std::string& out, const std::string& verb)
{
    std::string ext = std::filesystem::path(out).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    std::string name = std::filesystem::path(out).stem().string();
    if (ext == ".ldt")
        photometry::writeLdt(t, out, name, "lumibench luminaire " + verb);
    else if (ext == ".ies")
        photometry::writeIes(t, out, name, "lumibench luminaire " + verb);
    else
        throw InputError(fmt::format("luminaire {}: expected an output file FILE.ldt or FILE.ies, got {}", verb,
                                     photometry::quote(out)));
}

void addConvert(CLI::App* cmd)
{
    auto* conv = cmd->add_subcommand(
        "convert", "Rewrite a luminaire file as EULUMDAT or IES LM-63, by OUT's extension (.ldt, .ies)");
    conv->footer("The intensity table (absolute cd), the luminous opening (shape and size) and an IES TILT=INCLUDE "
                 "table are kept; the other header fields are not. EULUMDAT holds only point, rectangular and "
                 "round openings and no TILT table: such a file is refused. IN and OUT may be the same file.");
    auto in = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    conv->add_option("in", *in, "IES or LDT file to read")->required();
    conv->add_option("out", *out, "File to write, OUT.ldt or OUT.ies")->required()->check(outFilePath());
    conv->callback([in, out] {
        writeByExtension(photometry::load(*in), *out, "convert");
        std::cout << summary(photometry::load(*out)).dump() << '\n';
    });
}

// luminaire info: the summary, optionally with the sh fit's error per L.
void addInfo(CLI::App* cmd)
{
    auto* info = cmd->add_subcommand("info", "Summary of a luminaire file (format, flux, max cd, symmetry, grid)");
    auto file = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    info->add_option("file", *file, "IES or LDT file")->required();
    info->add_flag("--json", *json, "Print one JSON object");
    auto sh = std::make_shared<bool>(false);
    info->add_flag("--sh", *sh,
                   "Also the error of the `sh` method's fit (methods/sh_fit.h: least squares with its default "
                   "ridge) at L = 0, 2, 4, 8, 12, 16: relative L2 of the intensity over the sphere (sh_fit_error)");
    info->callback([file, json, sh] {
        const Table t = photometry::load(*file);
        auto j = summary(t);
        if (*sh)
            for (int L : {0, 2, 4, 8, 12, 16}) {
                methods::ShFitOptions o;
                o.L = L;
                j["sh_fit_error"][std::to_string(L)] = methods::shFit(t, o).error;
            }
        if (*json) {
            std::cout << j.dump() << '\n';
            return;
        }
        for (auto& [k, v] : j.items()) std::cout << fmt::format("{:<18} {}\n", k, v.dump());
    });
}

}  // namespace

void addLuminaireCommand(CLI::App& app)
{
    auto* cmd = app.add_subcommand("luminaire", "Read, evaluate and synthesise luminaires (IES LM-63, EULUMDAT)");
    cmd->require_subcommand(1);

    addInfo(cmd);

    auto* eval = cmd->add_subcommand("eval", "Absolute candela at (gamma, C) pairs in degrees, one per line");
    auto efile = std::make_shared<std::string>();
    auto angles = std::make_shared<std::vector<std::string>>();
    eval->add_option("file", *efile, "IES or LDT file")->required();
    eval->add_option("angles", *angles, "GAMMA C [GAMMA C ...]")->required()->allow_extra_args();
    eval->callback([efile, angles] {
        if (angles->size() % 2 != 0)
            throw InputError(fmt::format("luminaire eval: expected GAMMA C pairs, got {} numbers", angles->size()));
        Table t = photometry::load(*efile);
        for (size_t i = 0; i < angles->size(); i += 2) {
            double g = angleArg((*angles)[i], "GAMMA");
            double c = std::fmod(angleArg((*angles)[i + 1], "C"), 360.0);
            if (c < 0) c += 360;
            std::cout << fmt::format("{:.9g}\n", t.intensity(c, g));
        }
    });

    auto* dump =
        cmd->add_subcommand("dump", "The unfolded table (C, gamma, cd) and the summary as JSON (plots/polar.py)");
    auto dfile = std::make_shared<std::string>();
    dump->add_option("file", *dfile, "IES or LDT file")->required();
    dump->add_flag("--json", "JSON output (the only format)");
    dump->callback([dfile] {
        Table t = photometry::load(*dfile);
        auto j = summary(t);
        j["c"] = t.c;
        j["gamma"] = t.gamma;
        j["cd"] = t.cd;
        std::cout << j.dump() << '\n';
    });

    auto* syn = cmd->add_subcommand("synth", "Write one of the suite's own luminaires (.ldt or .ies by extension)");
    auto kind = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    auto params = std::make_shared<photometry::SynthParams>();
    std::string kinds;
    for (const auto& k : photometry::synthKinds()) kinds += "\n  " + k + ": " + photometry::synthDescription(k);
    syn->add_option("kind", *kind, "Profile:" + kinds)->required();
    syn->add_option("--out", *out, "Output file, FILE.ldt or FILE.ies (default: print the summary only)")
        ->check(outFilePath());
    syn->add_option("--flux", params->flux, "Luminous flux in lm")->capture_default_str();
    syn->add_option("--n", params->n, "Phong exponent")->capture_default_str();
    syn->add_option("--gamma-step", params->gammaStep, "Gamma step in degrees of the exact profiles")
        ->capture_default_str();
    syn->callback([kind, out, params] {
        Table t = photometry::synth(*kind, *params);
        if (!out->empty()) {
            writeByExtension(t, *out, "synth");
            t = photometry::load(*out);
        }
        std::cout << summary(t).dump() << '\n';
    });
    addConvert(cmd);
}

}  // namespace lb::cli
