// bind_render.cpp -- lb.devices, lb.methods, lb.render and lb.reference:
// the registry and methods::render as `lumibench devices`, `methods` and
// `render` use them (cli/cmd_devices.cpp, cmd_methods.cpp, cmd_render.cpp).
#include "common.h"
#include "scene_args.h"

#include "cli/commands.h"
#include "methods/render.h"
#include "util/check.h"
#include "util/error.h"

#include <fmt/format.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>

#include <chrono>

namespace lb::py {

namespace {

using methods::Kind;

nlohmann::json paramJson(const methods::Param& p)
{
    static const char* kinds[] = {"real", "int", "choice", "list", "text"};
    nlohmann::json j = {{"name", p.name},       {"kind", kinds[static_cast<int>(p.kind)]},
                        {"default", p.def},     {"allowed", p.allowed()},
                        {"meaning", p.meaning}, {"tunable", p.tunable}};
    if (p.kind == Kind::Real || p.kind == Kind::Int) {
        j["min"] = p.lo;
        j["max"] = p.hi;
        j["scale"] = p.scale == methods::Scale::Log ? "log" : "linear";
    }
    if (p.kind == Kind::Choice || p.kind == Kind::List) j["choices"] = p.choices;
    return j;
}

nlohmann::json methodsJson()
{
    nlohmann::json a = nlohmann::json::array();
    for (const auto& f : methods::registry().all()) {
        nlohmann::json scenes = nlohmann::json::array(), shapes = nlohmann::json::array(),
                       params = nlohmann::json::array();
        for (SceneKind k : f.scenes) scenes.push_back(sceneKindName(k));
        for (LightShape s : f.shapes) shapes.push_back(lightShapeName(s));
        for (const auto& p : f.params) params.push_back(paramJson(p));
        a.push_back({{"name", f.name},
                     {"summary", f.summary},
                     {"scenes", scenes},
                     {"shapes", shapes},
                     {"kernel", f.file},
                     {"expensive", f.expensive},
                     {"params", params}});
    }
    return a;
}

// One render as `lumibench render` makes it, with the GIL released for
// everything but the argument parsing.
struct Rendered {
    methods::RenderResult r;
    methods::MethodSpec spec;
    Scene scene;
    ocl::DeviceInfo device;
    methods::Precision precision = methods::Precision::Float;
    double wallMs = 0;  // methods::render's wall time
};

Rendered renderWith(const photometry::Table& table, const PyScene& ps, const std::string& specText,
                    const std::string& precision, std::optional<int> device, std::optional<long> seed, int reps,
                    bool cache)
{
    if (specText.empty()) throw InputError("spec: expected a SPEC such as mc:n=24, got an empty value");
    Rendered out;  // (members assigned one by one: GCC 12 destroys a half-built aggregate twice when one throws)
    out.spec = methods::parseSpec(specText, ps.scene.kind);
    if (seed) out.spec = out.spec.with("seed", std::to_string(*seed));
    try {
        out.precision = methods::parsePrecision(precision);
    } catch (const InputError& e) {
        throw InputError(fmt::format("precision: {}", e.what()));
    }
    util::checkRange("reps", reps, 1, ocl::kMaxReps);
    if (device) util::checkRange("device", *device, 0, 4095);
    nb::gil_scoped_release unlocked;
    out.scene = ps.resolve(table);
    Device d = py::device(device);
    out.device = d.rt.info();
    methods::RenderOptions opt;
    opt.reps = reps;
    opt.useCache = cache;
    const auto t0 = std::chrono::steady_clock::now();
    out.r = methods::render(d.rt, table, out.scene, out.spec, out.precision, opt);
    out.wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

// `render --json`'s object, without the output files.
nb::object infoOf(const photometry::Table& table, const Rendered& x)
{
    const auto& t = x.r.timing;
    nlohmann::json j = {
        {"method", x.spec.name},
        {"spec", x.spec.canonical()},
        {"params", x.spec.paramsJson()},
        {"luminaire", table.source},
        {"scene", cli::sceneJson(x.scene)},
        {"device", x.device.name},
        {"driver", x.device.driver},
        {"platform", x.device.platform},
        {"precision", methods::precisionName(x.precision)},
        {"time_ms",
         {{"median", t.median_ms}, {"min", t.min_ms}, {"max", t.max_ms}, {"reps", t.reps}, {"samples", t.samples_ms}}},
        {"time_res", x.r.timeRes},
        {"build_s", x.r.buildSeconds},
        {"nonfinite", x.r.nonfinite},
        {"cached", x.r.cached},
        {"stats", x.r.stats},
        {"wall_ms", x.wallMs},
    };
    return toPython(j);
}

nb::tuple render(const photometry::Table& table, const PyScene& scene, const std::string& spec,
                 const std::string& precision, std::optional<int> device, std::optional<long> seed, int reps,
                 bool cache)
{
    Rendered x = renderWith(table, scene, spec, precision, device, seed, reps, cache);
    nb::object info = infoOf(table, x);
    return nb::make_tuple(toNumpy(std::move(x.r.image), x.precision == methods::Precision::Double), info);
}

nb::tuple reference(const photometry::Table& table, const PyScene& scene, const std::string& spec,
                    const std::string& precision, std::optional<int> device, bool cache)
{
    Rendered x = renderWith(table, scene, spec, precision, device, std::nullopt, 1, cache);
    auto err = x.r.extraImages.find("err");
    if (err == x.r.extraImages.end())
        throw InputError(fmt::format("spec: expected a reference method (one with an error estimate), got '{}'", spec));
    const bool dbl = x.precision == methods::Precision::Double;
    nb::object info = infoOf(table, x);
    return nb::make_tuple(toNumpy(std::move(x.r.image), dbl), toNumpy(std::move(err->second), dbl), info);
}

const char* kRenderDoc = R"(Renders `scene` lit by `luminaire` with the method SPEC `spec` ('name' or
'name:key=value,...', e.g. 'mc:n=24') as `lumibench render` does: the image
(res x res, E in lux, row 0 at the top) as a C-contiguous numpy array,
float32 for precision 'float', float64 for 'double', and the dict `render
--json` prints (method, spec, params, scene, device, time_ms with the
profiled kernel times, build_s, nonfinite, stats, ...) plus wall_ms, the
library call's wall time. seed: the method's `seed` parameter (mc). The GIL
is released while the device works. ValueError (lumibench.InputError) for bad
input, RuntimeError (lumibench.Error) for device failures.)";

const char* kReferenceDoc = R"(The converged reference (docs/design.md section 4) with its per-pixel error
estimate (what `lumibench render --method reference` writes as FILE.err.exr),
cached on disk like the CLI's ($LUMIBENCH_CACHE, else ~/.cache/lumibench).)";

}  // namespace

void bindRender(nb::module_& m)
{
    m.def(
        "devices", [] { return toPython(cli::devicesJson()); },
        "The OpenCL devices as `lumibench devices --json` lists them; `index` is what "
        "device= takes, `default` marks the device used when device=None.");
    m.def(
        "methods", [] { return toPython(methodsJson()); },
        "Every method of the registry: name, summary, scenes, shapes, kernel, and its "
        "params (name, kind, default, min / max / scale or choices, allowed, meaning, tunable): docs/methods.md.");
    m.def("render", &render, nb::arg("luminaire"), nb::arg("scene"), nb::arg("spec"), nb::kw_only(),
          nb::arg("precision") = "float", nb::arg("device") = nb::none(), nb::arg("seed") = nb::none(),
          nb::arg("reps") = 5, nb::arg("cache") = true, kRenderDoc);
    m.def("reference", &reference, nb::arg("luminaire"), nb::arg("scene"), nb::kw_only(), nb::arg("spec") = "reference",
          nb::arg("precision") = "float", nb::arg("device") = nb::none(), nb::arg("cache") = true, kReferenceDoc);
}

}  // namespace lb::py
