// lumibench devices: the OpenCL devices and the index --device takes.
#include "cl/runtime.h"
#include "cli/commands.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace lb::cli {

nlohmann::json devicesJson()
{
    auto devs = ocl::listDevices();
    const int def = devs.empty() ? -1 : ocl::chooseDevice(-1);
    nlohmann::json a = nlohmann::json::array();
    for (auto& d : devs)
        a.push_back({{"index", d.index},
                     {"platform", d.platform},
                     {"name", d.name},
                     {"vendor", d.vendor},
                     {"version", d.version},
                     {"driver", d.driver},
                     {"type", d.type},
                     {"fp64", d.fp64},
                     {"compute_units", d.computeUnits},
                     {"global_mem_bytes", d.globalMem},
                     {"default", d.index == def}});
    return a;
}

void addDevicesCommand(CLI::App& app)
{
    auto* cmd = app.add_subcommand("devices",
                                   "List OpenCL devices; the index is what --device and "
                                   "$LUMIBENCH_DEVICE take (default: the first PoCL device)");
    auto json = std::make_shared<bool>(false);
    cmd->add_flag("--json", *json, "Print a JSON array instead of a table");
    cmd->callback([json] {
        if (*json) {
            std::cout << devicesJson().dump(2) << '\n';
            return;
        }
        auto devs = ocl::listDevices();
        int def = devs.empty() ? -1 : ocl::chooseDevice(-1);
        if (devs.empty()) {
            std::cout << "no OpenCL devices (install pocl-opencl-icd: scripts/install-deps.sh)\n";
            return;
        }
        for (auto& d : devs)
            std::cout << fmt::format("{}{} [{}] {} | {} | {} | driver {} | {} CU | fp64 {}\n", d.index,
                                     d.index == def ? "*" : " ", d.type, d.name, d.platform, d.version, d.driver,
                                     d.computeUnits, d.fp64 ? "yes" : "no");
        std::cout << "* default device\n";
    });
}

}  // namespace lb::cli
