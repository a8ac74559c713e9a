// lumibench render: one method on the normalized scene (docs/design.md sections 2, 7).
#include "cli/commands.h"

#include "methods/analytic.h"
#include "methods/render.h"
#include "util/check.h"
#include "util/error.h"
#include "util/fileio.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace lb::cli {

nlohmann::json sceneJson(const Scene& scene)
{
    nlohmann::json j = {{"kind", sceneKindName(scene.kind)},
                        {"height", scene.height},
                        {"rotation", scene.rotation},
                        {"width", scene.width},
                        {"length", scene.length},
                        {"shape", lightShapeName(scene.shape)},
                        {"extent", scene.extent},
                        {"res", scene.res}};
    if (scene.kind == SceneKind::Specular) {
        j["alpha"] = scene.alpha;
        j["eye"] = {scene.eye.x, scene.eye.y, scene.eye.z};
    }
    if (scene.kind == SceneKind::Indirect) j["albedo"] = scene.albedo;
    return j;
}

Scene sceneFromFlags(double height, const std::string& rotation, const std::string& size, double extent, int res)
{
    Scene scene;
    scene.height = util::checkRange("--height", height, 0, kMaxSceneLength, "m");
    scene.rotation = util::parseAngle("--rotation", rotation);
    if (size != "file") {  // "file": methods::sizeFromFile, once the luminaire is read
        auto x = size.find_first_of("xX");
        if (x == std::string::npos)
            throw InputError(fmt::format("--size: expected WxL in metres or 'file', got '{}'", size));
        scene.width =
            util::checkRange("--size W", util::parseReal("--size W", size.substr(0, x)), 0, kMaxSceneLength, "m");
        scene.length =
            util::checkRange("--size L", util::parseReal("--size L", size.substr(x + 1)), 0, kMaxSceneLength, "m");
        if (!(scene.width > 0 && scene.length > 0))
            throw InputError(fmt::format("--size: expected W, L > 0, got '{}'", size));
    }
    scene.extent = util::checkRange("--extent", extent, 0, kMaxSceneLength, "m");
    if (!(scene.extent > 0)) throw InputError(fmt::format("--extent: expected a number > 0, got {}", extent));
    scene.res = util::checkRange("--res", res, 1, kMaxRes);
    return scene;
}

void sceneKindFromFlags(const CLI::App& cmd, const std::string& kind, double alpha, const std::string& eye,
                        double albedo, Scene& scene)
{
    try {
        scene.kind = parseSceneKind(kind);
    } catch (const InputError&) {
        throw InputError(fmt::format("--scene: expected diffuse, specular or indirect, got '{}'", kind));
    }
    const bool spec = scene.kind == SceneKind::Specular, ind = scene.kind == SceneKind::Indirect;
    for (const char* f : {"--alpha", "--eye"})
        if (cmd.count(f) && !spec)
            throw InputError(fmt::format("{}: only the specular scene has it (--scene specular)", f));
    if (cmd.count("--albedo") && !ind) throw InputError("--albedo: only the indirect scene has it (--scene indirect)");
    scene.alpha = util::checkRange("--alpha", alpha, kMinAlpha, kMaxAlpha);
    scene.albedo = util::checkRange("--albedo", albedo, 0.0, 1.0);
    if (cmd.count("--eye")) {
        std::vector<double> v;
        size_t b = 0;
        while (true) {
            size_t c = eye.find(',', b);
            v.push_back(util::parseReal("--eye", eye.substr(b, c == std::string::npos ? c : c - b)));
            if (c == std::string::npos) break;
            b = c + 1;
        }
        if (v.size() != 3) throw InputError(fmt::format("--eye: expected X,Y,Z in metres, got '{}'", eye));
        for (int k = 0; k < 3; ++k)
            scene.eye[k] = util::checkRange("--eye", v[k], -kMaxSceneLength, kMaxSceneLength, "m");
        if (!(scene.eye.z > 0))
            throw InputError(fmt::format("--eye: the eye must be above the floor (Z > 0), got '{}'", eye));
    }
}

int deviceFlag(const CLI::App& cmd, int device)
{
    // -1 is "not given" (the default device); an explicit index must exist,
    // which ocl::chooseDevice checks against the device list.
    return cmd.count("--device") ? util::checkRange("--device", device, 0, 4095) : -1;
}

methods::Precision precisionFlag(const std::string& text)
{
    try {
        return methods::parsePrecision(text);
    } catch (const InputError& e) {
        throw InputError(fmt::format("--precision: {}", e.what()));
    }
}

namespace {

struct RenderOpts {
    std::string luminaire, method, rotation, size = "1x1", precision = "float", out, scene = "diffuse", eye, shape;
    double height = 0, extent = 5, alpha = Scene{}.alpha, albedo = Scene{}.albedo;
    int res = 256, device = -1, reps = 5;
    bool json = false, noCache = false;
};

void addRenderOptions(CLI::App* cmd, RenderOpts& o)
{
    cmd->add_option("--luminaire", o.luminaire, "IES or LDT file (or analytic:cos<n>[:two])")->required();
    std::string methodHelp = "Method SPEC name:key=value,..., e.g. mc:n=24; methods: " + methods::registry().names();
    for (SceneKind k : {SceneKind::Specular, SceneKind::Indirect})
        if (!methods::registry().names(k).empty())
            methodHelp += "; --scene " + sceneKindName(k) + ": " + methods::registry().names(k);
    cmd->add_option("--method", o.method, methodHelp)->required();
    cmd->add_option("--scene", o.scene,
                    "What the image shows: diffuse (direct irradiance on the floor, lux), specular (luminance of a "
                    "glossy GGX floor towards --eye, cd/m^2), indirect (one-bounce irradiance from the walls and "
                    "ceiling of a 5 x 5 x 3 m room, lux)")
        ->capture_default_str();
    cmd->add_option("--alpha", o.alpha, "Specular scene: GGX roughness alpha (0.01 .. 1)")->capture_default_str();
    cmd->add_option("--eye", o.eye, "Specular scene: eye point X,Y,Z in metres (Z > 0; default 0,4,2)");
    cmd->add_option("--albedo", o.albedo, "Indirect scene: albedo of walls and ceiling (0 .. 1)")
        ->capture_default_str();
    cmd->add_option("--height", o.height, "Height h of the light (m, 0 .. 1e4)")->required();
    cmd->add_option("--rotation", o.rotation,
                    "Rotation R in radians (0 .. 2pi; pi/2 .. pi in the papers), e.g. 2.356 "
                    "or 3pi/4")
        ->required();
    cmd->add_option("--size", o.size,
                    "Light size WxL in metres (each > 0, <= 1e4), or 'file': the luminous opening the file declares "
                    "(W its length along C0-C180, L its width; a round one a disk)")
        ->capture_default_str();
    cmd->add_option("--shape", o.shape,
                    "Light shape: rect, or disk (the ellipse inscribed in W x L: a disk of diameter D is --size DxD; "
                    "diffuse scene). Default rect, or the file's with --size file");
    cmd->add_option("--res", o.res, "Image resolution N (N x N pixels, 1 .. 16384)")->capture_default_str();
    cmd->add_option("--extent", o.extent, "Side S of the imaged square (m, > 0, <= 1e4)")->capture_default_str();
    cmd->add_option("--precision", o.precision, "float or double")->capture_default_str();
    cmd->add_option("--device", o.device, "OpenCL device index >= 0 (lumibench devices)");
    cmd->add_option("--out", o.out, "Output .exr (channel Y, lux); the reference also writes FILE.err.exr")
        ->required()
        ->check(outFilePath());
    cmd->add_option("--reps", o.reps, "Timed runs after one warm-up (1 .. 1000)")->capture_default_str();
    cmd->add_flag("--json", o.json, "Print one JSON object describing the result");
    cmd->add_flag("--no-cache", o.noCache, "Do not read or write the reference cache ($LUMIBENCH_CACHE)");
}

// The image and its side images (the reference's FILE.err.exr) as one
// group: if any cannot be written, none is left behind. Returns the side
// images' paths by name.
nlohmann::json writeImages(const std::string& out, const methods::RenderResult& r)
{
    std::vector<std::pair<std::string, std::string>> files = {{out, encodeExr(r.image)}};
    std::string stem = out;
    if (stem.size() > 4 && stem.substr(stem.size() - 4) == ".exr") stem.resize(stem.size() - 4);
    nlohmann::json extra = nlohmann::json::object();
    for (auto& [name, img] : r.extraImages) {
        std::string p = stem + "." + name + ".exr";
        files.emplace_back(p, encodeExr(img));
        extra[name] = p;
    }
    util::writeFilesAtomic(files);
    return extra;
}

nlohmann::json renderJson(const RenderOpts& o, const methods::MethodSpec& spec, const Scene& scene,
                          const ocl::Runtime& rt, methods::Precision prec, const methods::RenderResult& r,
                          const nlohmann::json& extra)
{
    return {
        {"method", spec.name},
        {"spec", spec.canonical()},
        {"params", spec.paramsJson()},
        {"luminaire", o.luminaire},
        {"scene", sceneJson(scene)},
        {"device", rt.info().name},
        {"driver", rt.info().driver},
        {"platform", rt.info().platform},
        {"precision", methods::precisionName(prec)},
        {"time_ms",
         {{"median", r.timing.median_ms}, {"min", r.timing.min_ms}, {"max", r.timing.max_ms}, {"reps", r.timing.reps}}},
        {"build_s", r.buildSeconds},
        {"nonfinite", r.nonfinite},
        {"cached", r.cached},
        {"stats", r.stats},
        {"out", o.out},
        {"extra_images", extra},
    };
}

}  // namespace

void addRenderCommand(CLI::App& app)
{
    auto o = std::make_shared<RenderOpts>();
    auto* cmd = app.add_subcommand("render", "Render the normalized evaluation scene with one method to OpenEXR");
    addRenderOptions(cmd, *o);
    cmd->callback([o, cmd] {
        if (o->method.empty()) throw InputError("--method: expected a SPEC such as mc:n=24, got an empty value");
        Scene scene = sceneFromFlags(o->height, o->rotation, o->size, o->extent, o->res);
        sceneKindFromFlags(*cmd, o->scene, o->alpha, o->eye, o->albedo, scene);
        methods::MethodSpec spec = methods::parseSpec(o->method, scene.kind);
        methods::Precision prec = precisionFlag(o->precision);
        util::checkRange("--reps", o->reps, 1, ocl::kMaxReps);
        const int device = deviceFlag(*cmd, o->device);

        photometry::Table table = methods::loadLuminaire(o->luminaire);
        if (o->size == "file") methods::sizeFromFile(table, scene, "--size file");
        if (cmd->count("--shape")) try {
                scene.shape = parseLightShape(o->shape);
            } catch (const InputError&) {
                throw InputError(fmt::format("--shape: expected rect or disk, got '{}'", o->shape));
            }
        ocl::Runtime rt(device);
        methods::RenderOptions ropt;
        ropt.reps = o->reps;
        ropt.useCache = !o->noCache;
        ropt.progress = true;
        auto r = methods::render(rt, table, scene, spec, prec, ropt);
        nlohmann::json extra = writeImages(o->out, r);
        if (r.nonfinite > 0) std::cerr << fmt::format("lumibench: warning: {} non-finite pixels\n", r.nonfinite);
        if (o->json) std::cout << renderJson(*o, spec, scene, rt, prec, r, extra).dump() << std::endl;
    });
}

}  // namespace lb::cli
