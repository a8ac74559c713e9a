// lumibench -- benchmark of real-time approximations of photometric polygonal lights.
#include "cl/runtime.h"
#include "cli/commands.h"
#include "util/error.h"

#include <fmt/format.h>

#include <iostream>

int main(int argc, char** argv)
{
    CLI::App app{"lumibench: a benchmark of real-time approximations of photometric polygonal lights\n"
                 "(scattered sampling / cubature against Monte Carlo integration and a converged reference).\n"
                 "Conventions: docs/design.md. Exit codes: 0 ok, 1 error, 2 bad input.",
                 "lumibench"};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "Print help for every subcommand");
    lb::cli::addDevicesCommand(app);
    lb::cli::addLuminaireCommand(app);
    lb::cli::addRenderCommand(app);
    lb::cli::addCompareCommand(app);
    lb::cli::addRunCommand(app);
    lb::cli::addMergeCommand(app);
    lb::cli::addReportCommand(app);
    lb::cli::addTuneCommand(app);
    lb::cli::addStabilityCommand(app);
    lb::cli::addBenchCommand(app);
    lb::cli::addLtcCommand(app);
    lb::cli::addSequenceCommand(app);
    lb::cli::addMethodsCommand(app);
    lb::cli::strictNumericFlags(app);
    try {
        // CLI11 reads "--opt=" as "--opt" and takes the next argument as its
        // value ("--method= --out x.exr" complained about --out): an empty
        // value after '=' is refused here, naming the option.
        for (int i = 1; i < argc; ++i) {
            std::string a = argv[i];
            if (a == "--") break;
            if (a.size() > 3 && a.rfind("--", 0) == 0 && a.back() == '=' && a.find('=') == a.size() - 1)
                throw lb::InputError(
                    fmt::format("{}: expected a value after '=', got an empty value", a.substr(0, a.size() - 1)));
        }
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int rc = app.exit(e);
        return rc == 0 ? 0 : lb::kExitInput;
    } catch (const lb::Error& e) {
        std::cerr << "lumibench: error: " << e.what() << '\n';
        return e.code;
    } catch (const cl::Error& e) {
        std::cerr << "lumibench: OpenCL error: " << e.what() << " failed: " << lb::ocl::errorString(e.err()) << '\n';
        return lb::kExitError;
    } catch (const std::exception& e) {
        std::cerr << "lumibench: error: " << e.what() << '\n';
        return lb::kExitError;
    }
    return 0;
}
