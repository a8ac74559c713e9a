// bind_scene.cpp -- lb.Luminaire and lb.Scene (scene_args.h).
#include "scene_args.h"

#include "methods/analytic.h"
#include "util/check.h"
#include "util/error.h"

#include <fmt/format.h>
#include <nanobind/stl/array.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>

#include <cmath>

namespace lb::py {

Scene PyScene::resolve(const photometry::Table& table) const
{
    Scene s = scene;
    if (sizeFromFile) {
        const LightShape given = s.shape;
        methods::sizeFromFile(table, s, "size='file'");
        if (shapeGiven) s.shape = given;
    }
    s.validate();
    return s;
}

namespace {

double rotationArg(nb::handle r)
{
    if (nb::isinstance<nb::str>(r)) return util::parseAngle("rotation", nb::cast<std::string>(r));
    double v = 0;
    if (nb::isinstance<nb::bool_>(r) || !nb::try_cast(r, v))
        throw InputError(fmt::format("rotation: expected radians as a number or text such as '3pi/4', got {}",
                                     nb::type_name(r.type()).c_str()));
    return util::checkRange("rotation", v, 0, util::kTwoPi);
}

void sizeArg(nb::handle size, PyScene& p)
{
    if (nb::isinstance<nb::str>(size)) {
        if (nb::cast<std::string>(size) != "file")
            throw InputError(
                fmt::format("size: expected (W, L) in metres or 'file', got '{}'", nb::cast<std::string>(size)));
        p.sizeFromFile = true;
        return;
    }
    std::array<double, 2> wl{};
    if (!nb::try_cast(size, wl))
        throw InputError(fmt::format("size: expected (W, L) in metres or 'file', got {}", pyStr(size)));
    p.scene.width = util::checkRange("size W", wl[0], 0, kMaxSceneLength, "m");
    p.scene.length = util::checkRange("size L", wl[1], 0, kMaxSceneLength, "m");
    if (!(wl[0] > 0 && wl[1] > 0)) throw InputError(fmt::format("size: expected W, L > 0, got ({}, {})", wl[0], wl[1]));
}

// The kind's own values; one of another kind is an error, as on the command line.
void kindArgs(PyScene& p, const std::string& kind, std::optional<double> alpha,
              std::optional<std::array<double, 3>> eye, std::optional<double> albedo)
{
    try {
        p.scene.kind = parseSceneKind(kind);
    } catch (const InputError&) {
        throw InputError(fmt::format("kind: expected diffuse, specular or indirect, got '{}'", kind));
    }
    const bool spec = p.scene.kind == SceneKind::Specular, ind = p.scene.kind == SceneKind::Indirect;
    if ((alpha || eye) && !spec)
        throw InputError(fmt::format("{}: only the specular scene has it (kind='specular')", alpha ? "alpha" : "eye"));
    if (albedo && !ind) throw InputError("albedo: only the indirect scene has it (kind='indirect')");
    if (alpha) p.scene.alpha = util::checkRange("alpha", *alpha, kMinAlpha, kMaxAlpha);
    if (albedo) p.scene.albedo = util::checkRange("albedo", *albedo, 0.0, 1.0);
    if (eye) {
        for (int k = 0; k < 3; ++k)
            p.scene.eye[k] = util::checkRange("eye", (*eye)[k], -kMaxSceneLength, kMaxSceneLength, "m");
        if (!(p.scene.eye.z > 0))
            throw InputError(fmt::format("eye: the eye must be above the floor (Z > 0), got ({}, {}, {})", (*eye)[0],
                                         (*eye)[1], (*eye)[2]));
    }
}

PyScene makeScene(double height, nb::handle rotation, nb::handle size, std::optional<std::string> shape, int res,
                  double extent, const std::string& kind, std::optional<double> alpha,
                  std::optional<std::array<double, 3>> eye, std::optional<double> albedo)
{
    PyScene p;
    p.scene.height = util::checkRange("height", height, 0, kMaxSceneLength, "m");
    p.scene.rotation = rotationArg(rotation);
    sizeArg(size, p);
    p.scene.extent = util::checkRange("extent", extent, 0, kMaxSceneLength, "m");
    if (!(p.scene.extent > 0)) throw InputError(fmt::format("extent: expected a number > 0, got {}", extent));
    p.scene.res = util::checkRange("res", res, 1, kMaxRes);
    kindArgs(p, kind, alpha, eye, albedo);
    if (shape) {
        try {
            p.scene.shape = parseLightShape(*shape);
        } catch (const InputError&) {
            throw InputError(fmt::format("shape: expected rect or disk, got '{}'", *shape));
        }
        p.shapeGiven = true;
    }
    if (!p.sizeFromFile) p.scene.validate();
    return p;
}

const char* kSceneDoc = R"(The normalized evaluation scene (docs/design.md section 2), as `lumibench
render` takes it: the light of size W x L at height `height` (m) and rotation
`rotation` (radians, a number or text such as '3pi/4'), imaged top-down over a
square of side `extent` (m) at res x res pixels.

size: (W, L) in metres, or 'file' for the luminous opening the luminaire file
declares (resolved when rendering); shape: 'rect' or 'disk' (default rect, or
the file's with size='file'); kind: 'diffuse', 'specular' (alpha, eye) or
'indirect' (albedo). Raises ValueError naming the keyword for a bad value.)";

}  // namespace

void bindScene(nb::module_& m)
{
    nb::class_<PyScene>(m, "Scene", kSceneDoc)
        .def(nb::new_(&makeScene), nb::kw_only(), nb::arg("height"), nb::arg("rotation"),
             nb::arg("size") = nb::make_tuple(1.0, 1.0), nb::arg("shape") = nb::none(), nb::arg("res") = 256,
             nb::arg("extent") = 5.0, nb::arg("kind") = "diffuse", nb::arg("alpha") = nb::none(),
             nb::arg("eye") = nb::none(), nb::arg("albedo") = nb::none())
        .def_prop_ro(
            "height", [](const PyScene& p) { return p.scene.height; }, "Height h of the light (m).")
        .def_prop_ro(
            "rotation", [](const PyScene& p) { return p.scene.rotation; }, "Rotation R (radians).")
        .def_prop_ro(
            "size",
            [](const PyScene& p) -> nb::object {
                if (p.sizeFromFile) return nb::str("file");
                return nb::make_tuple(p.scene.width, p.scene.length);
            },
            "(W, L) in metres, or 'file'.")
        .def_prop_ro(
            "shape", [](const PyScene& p) { return lightShapeName(p.scene.shape); }, "'rect' or 'disk'.")
        .def_prop_ro(
            "res", [](const PyScene& p) { return p.scene.res; }, "Pixels per side.")
        .def_prop_ro(
            "extent", [](const PyScene& p) { return p.scene.extent; }, "Side of the imaged square (m).")
        .def_prop_ro(
            "kind", [](const PyScene& p) { return sceneKindName(p.scene.kind); }, "What the image shows.")
        .def("__repr__", [](const PyScene& p) {
            return fmt::format("lumibench.Scene(height={}, rotation={}, size={}, shape='{}', res={}, extent={}, "
                               "kind='{}')",
                               p.scene.height, p.scene.rotation,
                               p.sizeFromFile ? std::string("'file'")
                                              : fmt::format("({}, {})", p.scene.width, p.scene.length),
                               lightShapeName(p.scene.shape), p.scene.res, p.scene.extent, sceneKindName(p.scene.kind));
        });
}

}  // namespace lb::py
