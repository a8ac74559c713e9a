// lumibench bench: fast kernels against a naive one, every method's time per
// pixel, cubature against MC 8 and its equal-time N (host/bench/bench.h).
#include "cli/commands.h"

#include "bench/bench.h"
#include "methods/analytic.h"
#include "util/check.h"
#include "util/error.h"
#include "util/json_file.h"

#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <set>

namespace lb::cli {

void parseLocal(const std::string& name, const std::string& text, size_t& lx, size_t& ly)
{
    auto x = text.find_first_of("xX");
    try {
        if (x == std::string::npos) throw std::invalid_argument("");
        lx = std::stoul(text.substr(0, x));
        ly = std::stoul(text.substr(x + 1));
    } catch (const std::exception&) {
        throw InputError(fmt::format("{}: expected WxH, got '{}'", name, text));
    }
    if (lx < 1 || ly < 1 || lx * ly > 1024) throw InputError(fmt::format("{}: work-group {} out of range", name, text));
}

namespace {

// --equal-time TEXT: the protocol's keys over bench::benchProtocol's.
equaltime::Protocol protocolFlag(const std::string& text, bool quick, int reps)
{
    const nlohmann::json j = util::parseJson(text, "--equal-time");
    if (!j.is_object()) throw InputError(fmt::format("--equal-time: expected a JSON object, found {}", j.dump()));
    const util::JsonKeys r{"--equal-time", j};
    const std::vector<std::string>& keys = equaltime::protocolKeys();
    r.onlyKnown(std::set<std::string>(keys.begin(), keys.end()));
    equaltime::ReadRules rules;
    rules.elsewhere = {{"reps", "--reps"}, {"time_res", "--res"}};
    equaltime::Protocol p = bench::benchProtocol(quick, reps);
    equaltime::readProtocol(r, p, rules);
    return p;
}

}  // namespace

void addBenchCommand(CLI::App& app)
{
    struct Opts {
        std::string luminaire = "batwing";
        double height = 1.0;
        std::string rotation = "3pi/4";
        int res = 512, reps = 5, samples = 32, rounds = 3, device = -1;
        std::string local = "8x8";
        std::string equalTime;
        bool quick = false, json = false, filters = false;
    };
    auto o = std::make_shared<Opts>();
    auto* cmd = app.add_subcommand("bench", "Benchmark the kernels against a naive MC kernel");
    cmd->add_option("--luminaire", o->luminaire, "IES or LDT file or short name")->capture_default_str();
    cmd->add_option("--height", o->height, "Height h of the light (m, 0 .. 1e4)")->capture_default_str();
    cmd->add_option("--rotation", o->rotation, "Rotation R (radians in 0 .. 2pi, or e.g. 3pi/4)")
        ->capture_default_str();
    cmd->add_option("--res", o->res, "Image resolution N (1 .. 16384)")->capture_default_str();
    cmd->add_option("--reps", o->reps, "Timed launches after one warm-up (median; 1 .. 1000)")->capture_default_str();
    cmd->add_option("--samples", o->samples, "MC N of the samples/s comparison (1 .. 2^20)")->capture_default_str();
    cmd->add_option("--rounds", o->rounds, "Alternating naive / fast rounds (median of each; 1 .. 1000)")
        ->capture_default_str();
    cmd->add_option("--local", o->local, "Work-group size WxH")->capture_default_str();
    cmd->add_option("--device", o->device, "OpenCL device index >= 0 (lumibench devices)");
    cmd->add_flag("--quick", o->quick, "Fewer methods and fit points (smoke tests)");
    cmd->add_option("--equal-time", o->equalTime,
                    "The equal-time protocol as a JSON object: rounds, tolerance, mc, fit, mode, subpixel "
                    "(docs/experiments.md; reps and time_res are --reps and --res)");
    cmd->add_flag("--filters", o->filters, "Only the image filters' rows (mc:denoise=...; the header and one section)");
    cmd->add_flag("--json", o->json, "Print one JSON document to stdout");
    cmd->callback([o, cmd] {
        Scene scene = sceneFromFlags(o->height, o->rotation, "1x1", 5, o->res);
        util::checkRange("--reps", o->reps, 1, ocl::kMaxReps);
        util::checkRange("--samples", o->samples, 1, 1 << 20);  // the MC kernel's largest N
        util::checkRange("--rounds", o->rounds, 1, ocl::kMaxReps);
        const int device = deviceFlag(*cmd, o->device);
        bench::Options opt;
        parseLocal("--local", o->local, opt.lx, opt.ly);
        opt.res = o->res;
        opt.reps = o->reps;
        opt.samples = o->samples;
        opt.rounds = o->rounds;
        opt.quick = o->quick;
        if (!o->equalTime.empty()) opt.protocol = protocolFlag(o->equalTime, o->quick, o->reps);
        opt.filtersOnly = o->filters;
        photometry::Table table = methods::loadLuminaire(o->luminaire);
        ocl::Runtime rt(device);
        auto doc = bench::run(rt, table, scene, opt);
        if (o->json)
            std::cout << doc.dump() << std::endl;
        else
            std::cout << bench::format(doc);
    });
}

}  // namespace lb::cli
