// lumibench luminaire info|eval|dump|synth (issue: photometric data).
#include "cli/commands.h"

#include "photometry/ies.h"
#include "photometry/ldt.h"
#include "photometry/load.h"
#include "photometry/synth.h"
#include "photometry/text.h"
#include "util/error.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

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
    j["width_m"] = t.widthM;
    j["length_m"] = t.lengthM;
    if (t.format == "ies") {
        photometry::IesExtra x;
        photometry::readIes(t.source, &x);
        j["ies"] = {{"version", x.version},
                    {"tilt", x.tilt},
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

}  // namespace

void addLuminaireCommand(CLI::App& app)
{
    auto* cmd = app.add_subcommand("luminaire", "Read, evaluate and synthesise luminaires (IES LM-63, EULUMDAT)");
    cmd->require_subcommand(1);

    auto* info = cmd->add_subcommand("info", "Summary of a luminaire file (format, flux, max cd, symmetry, grid)");
    auto file = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    info->add_option("file", *file, "IES or LDT file")->required();
    info->add_flag("--json", *json, "Print one JSON object");
    info->callback([file, json] {
        auto j = summary(photometry::load(*file));
        if (*json) {
            std::cout << j.dump() << '\n';
            return;
        }
        for (auto& [k, v] : j.items()) std::cout << fmt::format("{:<18} {}\n", k, v.dump());
    });

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
            std::string ext = std::filesystem::path(*out).extension().string();
            std::string name = std::filesystem::path(*out).stem().string();
            if (ext == ".ldt")
                photometry::writeLdt(t, *out, name);
            else if (ext == ".ies")
                photometry::writeIes(t, *out, name);
            else
                throw InputError(fmt::format("luminaire synth: expected --out FILE.ldt or FILE.ies, got \"{}\"", *out));
            t = photometry::load(*out);
        }
        std::cout << summary(t).dump() << '\n';
    });
}

}  // namespace lb::cli
