// bind_run.cpp -- the experiment runner and the benchmark as `lumibench run`
// and `lumibench bench --json` call them (cli/cmd_run.cpp, cmd_bench.cpp).
// lb.run (lumibench/__init__.py) reads the results.csv this writes.
#include "common.h"

#include "bench/bench.h"
#include "cli/commands.h"
#include "experiments/report.h"
#include "experiments/runner.h"
#include "methods/analytic.h"
#include "util/check.h"
#include "util/error.h"

#include <fmt/format.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>

namespace lb::py {

namespace {

struct RunArgs {
    std::string experiment, out, luminaires, shard;
    std::optional<int> res, reps, timeRes, seeds, device;
    bool report = true, progress = false;
};

void checkOutDir(std::string out)
{
    if (std::string why = cli::outDirPath()(out); !why.empty()) throw InputError("out: " + why);
}

nb::object runExperiment(const RunArgs& a)
{
    const std::string& out = a.out;
    checkOutDir(out);
    experiments::Overrides ov;  // range-checked by loadExperiment, named by the keyword
    ov.name = [](const std::string& key) { return key; };
    ov.luminaireDir = a.luminaires;
    ov.res = a.res;
    ov.reps = a.reps;
    ov.timeRes = a.timeRes;
    ov.seeds = a.seeds;
    experiments::RunOptions ro;
    experiments::parseShard("shard", a.shard, ro.shardK, ro.shardN);
    if (a.device) ro.device = util::checkRange("device", *a.device, 0, 4095);
    ro.outDir = out;
    ro.progress = a.progress;
    nb::gil_scoped_release unlocked;
    auto e = experiments::loadExperiment(a.experiment, ov);
    auto s = experiments::run(e, ro);
    if (a.report) {
        experiments::ReportSteps steps;
        steps.tag = e.name;
        steps.progress = a.progress;
        experiments::makeReport(out, steps);
    }
    nb::gil_scoped_acquire locked;
    return toPython({{"name", e.name},
                     {"scenes", s.scenes},
                     {"cells", s.cells},
                     {"computed", s.computed},
                     {"stale", s.stale},
                     {"skipped", s.skipped},
                     {"equal_time_off", s.equalTimeOff},
                     {"dropped", s.dropped},
                     {"seconds", s.seconds}});
}

struct BenchArgs {
    std::string luminaire, rotation, local;
    double height = 1;
    int res = 512, reps = 5, samples = 32, rounds = 3;
    std::optional<int> device;
    bool quick = false;
};

nb::object bench(const BenchArgs& a)
{
    Scene scene;
    scene.height = util::checkRange("height", a.height, 0, kMaxSceneLength, "m");
    scene.rotation = util::parseAngle("rotation", a.rotation);
    scene.res = util::checkRange("res", a.res, 1, kMaxRes);
    util::checkRange("reps", a.reps, 1, ocl::kMaxReps);
    util::checkRange("samples", a.samples, 1, 1 << 20);  // the MC kernel's largest N
    util::checkRange("rounds", a.rounds, 1, ocl::kMaxReps);
    if (a.device) util::checkRange("device", *a.device, 0, 4095);
    bench::Options opt;
    cli::parseLocal("local", a.local, opt.lx, opt.ly);
    opt.res = a.res, opt.reps = a.reps, opt.samples = a.samples, opt.rounds = a.rounds, opt.quick = a.quick;
    nlohmann::json doc;
    {
        nb::gil_scoped_release unlocked;
        photometry::Table table = methods::loadLuminaire(a.luminaire);
        Device d = py::device(a.device);
        doc = bench::run(d.rt, table, scene, opt);
    }
    return toPython(doc);
}

const char* kBenchDoc = R"(`lumibench bench --json` as a dict: MC samples per second against the naive
kernel, every method's time per pixel, cubature against MC 8 and its
equal-time N (docs/performance.md).)";

}  // namespace

void bindRun(nb::module_& m)
{
    m.def(
        "_run",
        [](std::string experiment, std::string out, std::string luminaires, std::string shard, std::optional<int> res,
           std::optional<int> reps, std::optional<int> timeRes, std::optional<int> seeds, std::optional<int> device,
           bool report, bool progress) {
            return runExperiment(
                {experiment, out, luminaires, shard, res, reps, timeRes, seeds, device, report, progress});
        },
        nb::arg("experiment"), nb::arg("out"), nb::arg("luminaires"), nb::arg("shard"), nb::arg("res").none(),
        nb::arg("reps").none(), nb::arg("time_res").none(), nb::arg("seeds").none(), nb::arg("device").none(),
        nb::arg("report"), nb::arg("progress"),
        "The runner of `lumibench run` (experiments::run, makeReport); lumibench.run wraps it.");
    m.def("_check_out_dir", &checkOutDir, nb::arg("out"), "InputError unless OUT is a directory or does not exist.");
    m.def(
        "bench",
        [](std::string luminaire, double height, std::string rotation, int res, int reps, int samples, int rounds,
           std::string local, std::optional<int> device, bool quick) {
            return bench({luminaire, rotation, local, height, res, reps, samples, rounds, device, quick});
        },
        nb::kw_only(), nb::arg("luminaire") = "batwing", nb::arg("height") = 1.0, nb::arg("rotation") = "3pi/4",
        nb::arg("res") = 512, nb::arg("reps") = 5, nb::arg("samples") = 32, nb::arg("rounds") = 3,
        nb::arg("local") = "8x8", nb::arg("device") = nb::none(), nb::arg("quick") = false, kBenchDoc);
}

}  // namespace lb::py
