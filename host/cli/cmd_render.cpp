// lumibench render: one method on the normalized scene (DESIGN sections 2, 7).
#include "cli/commands.h"

#include "methods/analytic.h"
#include "methods/render.h"
#include "util/error.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace lb::cli {

namespace {

double parseNumber(const std::string& what, const std::string& s)
{
    char* end = nullptr;
    double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end || !std::isfinite(v))
        throw InputError(fmt::format("{}: expected a number, got '{}'", what, s));
    return v;
}

} // namespace

// An angle in radians: a number, or an expression like pi, 3pi/4, 3*pi/4, pi/2, 0.75pi.
double parseAngle(const std::string& text)
{
    std::string s;
    for (char ch : text)
        if (ch != ' ') s += ch;
    auto bad = [&] {
        throw InputError(fmt::format("--rotation: expected radians or an expression like 3pi/4, got '{}'", text));
    };
    if (s.empty()) bad();
    std::string num = s, den;
    if (auto sl = s.find('/'); sl != std::string::npos) {
        num = s.substr(0, sl);
        den = s.substr(sl + 1);
        if (den.empty()) bad();
    }
    double v;
    if (auto p = num.find("pi"); p != std::string::npos) {
        if (p + 2 != num.size()) bad();
        std::string coef = num.substr(0, p);
        if (!coef.empty() && coef.back() == '*') coef.pop_back();
        v = (coef.empty() ? 1.0 : parseNumber("--rotation", coef)) * 3.14159265358979323846;
    } else {
        v = parseNumber("--rotation", num);
    }
    if (!den.empty()) {
        double d = parseNumber("--rotation", den);
        if (d == 0) bad();
        v /= d;
    }
    return v;
}

void addRenderCommand(CLI::App& app)
{
    struct Opts {
        std::string luminaire, method, rotation, size = "1x1", precision = "float", out;
        double height = 0, extent = 5;
        int res = 256, device = -1, reps = 5;
        bool json = false, noCache = false;
    };
    auto o = std::make_shared<Opts>();
    auto* cmd = app.add_subcommand("render", "Render the normalized evaluation scene with one method to OpenEXR");
    cmd->add_option("--luminaire", o->luminaire, "IES or LDT file (or analytic:cos<n>[:two])")->required();
    cmd->add_option("--method", o->method,
                    "Method SPEC name:key=value,..., e.g. mc:n=24; methods: " + methods::registry().names())
        ->required();
    cmd->add_option("--height", o->height, "Height h of the light (m)")->required();
    cmd->add_option("--rotation", o->rotation, "Rotation R in radians (pi/2 .. pi), e.g. 2.356 or 3pi/4")->required();
    cmd->add_option("--size", o->size, "Light size WxL in metres")->capture_default_str();
    cmd->add_option("--res", o->res, "Image resolution N (N x N pixels)")->capture_default_str();
    cmd->add_option("--extent", o->extent, "Side S of the imaged square (m)")->capture_default_str();
    cmd->add_option("--precision", o->precision, "float or double")->capture_default_str();
    cmd->add_option("--device", o->device, "OpenCL device index (lumibench devices)");
    cmd->add_option("--out", o->out, "Output .exr (channel Y, lux); the reference also writes FILE.err.exr")
        ->required();
    cmd->add_option("--reps", o->reps, "Timed runs after one warm-up")->capture_default_str();
    cmd->add_flag("--json", o->json, "Print one JSON object describing the result");
    cmd->add_flag("--no-cache", o->noCache, "Do not read or write the reference cache ($LUMIBENCH_CACHE)");
    cmd->callback([o] {
        methods::MethodSpec spec = methods::parseSpec(o->method);
        methods::Precision prec = methods::parsePrecision(o->precision);
        Scene scene;
        scene.height = o->height;
        scene.rotation = parseAngle(o->rotation);
        auto x = o->size.find_first_of("xX");
        if (x == std::string::npos) throw InputError(fmt::format("--size: expected WxL, got '{}'", o->size));
        scene.width = parseNumber("--size", o->size.substr(0, x));
        scene.length = parseNumber("--size", o->size.substr(x + 1));
        scene.extent = o->extent;
        scene.res = o->res;
        if (!(scene.width > 0 && scene.length > 0)) throw InputError("--size: W and L must be > 0");
        if (!(scene.extent > 0)) throw InputError("--extent must be > 0");
        if (!(scene.height >= 0)) throw InputError("--height must be >= 0");
        if (o->res < 1 || o->res > 16384) throw InputError(fmt::format("--res must be in [1, 16384], got {}", o->res));
        if (o->reps < 1) throw InputError("--reps must be >= 1");

        photometry::Table table = methods::loadLuminaire(o->luminaire);
        ocl::Runtime rt(o->device);
        methods::RenderOptions ropt;
        ropt.reps = o->reps;
        ropt.useCache = !o->noCache;
        ropt.progress = true;
        auto r = methods::render(rt, table, scene, spec, prec, ropt);

        writeExr(o->out, r.image);
        std::string stem = o->out;
        if (stem.size() > 4 && stem.substr(stem.size() - 4) == ".exr") stem.resize(stem.size() - 4);
        nlohmann::json extra = nlohmann::json::object();
        for (auto& [name, img] : r.extraImages) {
            std::string p = stem + "." + name + ".exr";
            writeExr(p, img);
            extra[name] = p;
        }
        if (r.nonfinite > 0) std::cerr << fmt::format("lumibench: warning: {} non-finite pixels\n", r.nonfinite);
        if (o->json) {
            nlohmann::json j = {
                {"method", spec.name},
                {"spec", spec.canonical()},
                {"params", spec.paramsJson()},
                {"luminaire", o->luminaire},
                {"scene",
                 {{"height", scene.height}, {"rotation", scene.rotation}, {"width", scene.width},
                  {"length", scene.length}, {"extent", scene.extent}, {"res", scene.res}}},
                {"device", rt.info().name},
                {"driver", rt.info().driver},
                {"platform", rt.info().platform},
                {"precision", methods::precisionName(prec)},
                {"time_ms",
                 {{"median", r.timing.median_ms}, {"min", r.timing.min_ms}, {"max", r.timing.max_ms},
                  {"reps", r.timing.reps}}},
                {"build_s", r.buildSeconds},
                {"nonfinite", r.nonfinite},
                {"cached", r.cached},
                {"stats", r.stats},
                {"out", o->out},
                {"extra_images", extra},
            };
            std::cout << j.dump() << std::endl;
        }
    });
}

} // namespace lb::cli
