// scene_keys.h -- the keys that choose what a scene shows, shared by
// experiment and tune files and by result records:
//
//   "scene": "diffuse" | "specular" | "indirect"     (default diffuse, docs/design.md sections 2, 8, 9)
//   "alpha": 0.25 or [0.05, 0.1, ...]                 specular: GGX roughness, swept like heights
//   "eye": [0, 4, 2]                                  specular: the eye point (m)
//   "albedo": 0.5                                     indirect: albedo of walls and ceiling
//
// A key of another kind (alpha in an indirect file) is refused, so a typo
// cannot pass silently.
#pragma once

#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace lb {

struct SceneKindKeys {
    SceneKind kind = SceneKind::Diffuse;
    std::vector<double> alphas{Scene{}.alpha};
    glm::dvec3 eye = Scene{}.eye;
    double albedo = Scene{}.albedo;

    static const std::vector<std::string>& keys();  // scene, alpha, eye, albedo
    // Reads the keys from the object j of file `path`; InputError
    // "PATH: key \"K\": ..." for a bad value or a key of another kind.
    static SceneKindKeys read(const nlohmann::json& j, const std::string& path);
    // s with this kind, its values and the given alpha (one of alphas).
    Scene applied(Scene s, double alpha) const;
    // What a result record carries of a scene's kind and light, flat: {} for
    // the diffuse scene's 1 x 1 rectangle (so its records keep their keys);
    // shape and size [W, L] for any other light; scene_kind plus alpha and
    // eye, or albedo, for the other kinds.
    static nlohmann::json recordKeys(const Scene& s);
};

}  // namespace lb
