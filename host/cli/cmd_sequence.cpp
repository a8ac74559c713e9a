// lumibench sequence: an animated sequence of the indirect scene (docs/design.md
// section 9): per-frame metrics and the flicker of each method
// (experiments/sequence.h).
#include "cli/commands.h"

#include "experiments/sequence.h"
#include "methods/analytic.h"
#include "util/check.h"
#include "util/error.h"
#include "util/fileio.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <iostream>

namespace lb::cli {

void addSequenceCommand(CLI::App& app)
{
    struct Opts {
        std::string luminaire, path = "rotate", rotation = "pi", from, to, precision = "float", out,
                               reference = "reference";
        std::vector<std::string> methods;
        double height = 1.1, albedo = 0.5;
        int res = 32, frames = 8, device = -1;
        bool noCache = false;
    };
    auto o = std::make_shared<Opts>();
    auto* cmd =
        app.add_subcommand("sequence", "Animated sequence of the indirect scene: per-frame metrics and flicker");
    cmd->add_option("--luminaire", o->luminaire, "IES or LDT file (or analytic:cos<n>[:two])")->required();
    cmd->add_option("--method", o->methods, "Method SPEC (repeatable), e.g. acrsm:k=64")->required();
    cmd->add_option("--path", o->path,
                    "rotate (R from --from to --to at --height) or lift (height from --from to --to "
                    "at --rotation)")
        ->capture_default_str();
    cmd->add_option("--from", o->from, "Path start (rotate: default pi/2; lift: default 0.1 m)");
    cmd->add_option("--to", o->to, "Path end (rotate: default pi; lift: default 1.1 m)");
    cmd->add_option("--frames", o->frames, "Frames F (2 .. 1000)")->capture_default_str();
    cmd->add_option("--height", o->height, "Height h (m) where the path does not move it")->capture_default_str();
    cmd->add_option("--rotation", o->rotation, "Rotation R where the path does not move it")->capture_default_str();
    cmd->add_option("--albedo", o->albedo, "Albedo of walls and ceiling (0 .. 1)")->capture_default_str();
    cmd->add_option("--res", o->res, "Image resolution N")->capture_default_str();
    cmd->add_option("--reference", o->reference, "Reference SPEC")->capture_default_str();
    cmd->add_option("--precision", o->precision, "float or double")->capture_default_str();
    cmd->add_option("--device", o->device, "OpenCL device index >= 0");
    cmd->add_option("--out", o->out, "Output JSON file")->required()->check(outFilePath());
    cmd->add_flag("--no-cache", o->noCache, "Do not read or write the reference cache");
    cmd->callback([o, cmd] {
        Scene base = sceneFromFlags(o->height, o->rotation, "1x1", 5.0, o->res);
        base.kind = SceneKind::Indirect;
        base.albedo = util::checkRange("--albedo", o->albedo, 0.0, 1.0);
        experiments::SequencePath path;
        path.kind = o->path;
        path.frames = util::checkRange("--frames", o->frames, 2, 1000);
        if (o->path == "lift") {
            path.from = 0.1;
            path.to = 1.1;
        } else if (o->path != "rotate") {
            throw InputError(fmt::format("--path: expected rotate or lift, got '{}'", o->path));
        }
        if (!o->from.empty())
            path.from = o->path == "rotate" ? util::parseAngle("--from", o->from) : util::parseReal("--from", o->from);
        if (!o->to.empty())
            path.to = o->path == "rotate" ? util::parseAngle("--to", o->to) : util::parseReal("--to", o->to);
        methods::Precision prec = precisionFlag(o->precision);
        photometry::Table table = methods::loadLuminaire(o->luminaire);
        ocl::Runtime rt(deviceFlag(*cmd, o->device));
        experiments::SequenceOptions so;
        so.referenceSpec = o->reference;
        so.render.useCache = !o->noCache;
        so.render.progress = false;
        nlohmann::json j = experiments::runSequence(rt, table, base, path, o->methods, prec, so);
        j["luminaire"] = o->luminaire;
        j["device"] = rt.info().name;
        j["driver"] = rt.info().driver;
        j["albedo"] = base.albedo;
        util::writeFileAtomic(o->out, j.dump(1) + "\n");
        for (auto& [spec, v] : j["flicker"].items())
            std::cout << fmt::format(
                "{:40s} flicker {:.4g} (per sequence {:.4g})  mean NMSE {:.4g}  mean time {:.3f} ms\n", spec,
                v.get<double>(), j["flicker_seq"][spec].get<double>(), j["mean"][spec]["nmse"].get<double>(),
                j["mean"][spec]["time_ms"].get<double>());
    });
}

}  // namespace lb::cli
