// lumibench stability [--json] [--out DIR] [--res N] [--quick] [--case NAME...] [--method NAME...]
//
// Every registered method in float and double on the catalogue of extreme
// scenes (host/stability/stability.h); exit 1 when a requirement fails.
#include "cli/commands.h"

#include "stability/stability.h"
#include "util/check.h"
#include "util/error.h"

#include <fmt/format.h>

#include <iostream>

namespace lb::cli {

void addStabilityCommand(CLI::App& app)
{
    struct Opts {
        stability::Options run;
        std::string out;
        bool json = false;
        int device = -1;
    };
    auto o = std::make_shared<Opts>();
    auto* cmd = app.add_subcommand("stability",
                                   "Run every method in float and double on the catalogue of extreme "
                                   "scenes; exit 1 when a requirement fails");
    cmd->add_option("--res", o->run.res, "Image resolution N (cases in the light plane use N + 1 when N is even)")
        ->capture_default_str();
    cmd->add_flag("--quick", o->run.quick, "Only the quick subset of the catalogue (CI)");
    cmd->add_option("--case", o->run.cases, "Only these cases (repeatable)");
    cmd->add_option("--method", o->run.methods, "Only these method families (repeatable)");
    cmd->add_option("--out", o->out, "Write DIR/stability.json, DIR/report.md and DIR/png/ (worst error images)")
        ->check(outDirPath());
    cmd->add_option("--device", o->device, "OpenCL device index >= 0 (lumibench devices)");
    cmd->add_flag("--json", o->json, "Print the whole result as one JSON object");
    cmd->callback([o, cmd] {
        util::checkRange("--res", o->run.res, 3, 4096);
        ocl::Runtime rt(deviceFlag(*cmd, o->device));
        o->run.progress = !o->json;
        auto results = stability::run(rt, o->run);
        if (!o->out.empty()) stability::writeReport(o->out, results, rt, o->run);
        auto j = stability::toJson(results, rt, o->run);
        if (o->json) {
            std::cout << j.dump() << std::endl;
        } else {
            for (auto& cr : results) {
                std::cout << fmt::format("{:<18} {}\n", cr.c.name,
                                         !cr.skipped.empty() ? "skipped: " + cr.skipped
                                             : cr.ok()       ? "ok"
                                                             : "FAIL");
                for (auto& f : cr.failures) std::cout << "    " << f << '\n';
                for (auto& r : cr.rows)
                    for (auto& f : r.failures) std::cout << fmt::format("    {} {}: {}\n", r.method, r.precision, f);
            }
        }
        if (!j["ok"].get<bool>()) throw Error("stability: requirements failed (see above or the report)");
    });
}

}  // namespace lb::cli
