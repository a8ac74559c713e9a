#include "scene/scene_keys.h"

#include "util/check.h"
#include "util/error.h"

#include <fmt/format.h>

namespace lb {

using nlohmann::json;

const std::vector<std::string>& SceneKindKeys::keys()
{
    static const std::vector<std::string> k = {"scene", "alpha", "eye", "albedo"};
    return k;
}

SceneKindKeys SceneKindKeys::read(const json& j, const std::string& path)
{
    auto name = [&](const std::string& key) { return fmt::format("{}: key \"{}\"", path, key); };
    auto fail = [&](const std::string& key, const std::string& what) {
        throw InputError(fmt::format("{}: {}", name(key), what));
    };
    SceneKindKeys k;
    if (j.contains("scene")) {
        if (!j["scene"].is_string()) fail("scene", fmt::format("expected a string, found {}", j["scene"].dump()));
        try {
            k.kind = parseSceneKind(j["scene"].get<std::string>());
        } catch (const InputError& e) {
            fail("scene", e.what());
        }
    }
    const bool spec = k.kind == SceneKind::Specular, ind = k.kind == SceneKind::Indirect;
    for (const char* key : {"alpha", "eye"})
        if (j.contains(key) && !spec) fail(key, "only the specular scene has it (\"scene\": \"specular\")");
    if (j.contains("albedo") && !ind) fail("albedo", "only the indirect scene has it (\"scene\": \"indirect\")");
    if (j.contains("alpha")) {
        const json& a = j["alpha"];
        k.alphas.clear();
        for (const json& x : a.is_array() ? a : json::array({a})) {
            if (!x.is_number())
                fail("alpha", fmt::format("expected a number or a list of numbers, found {}", a.dump()));
            k.alphas.push_back(util::checkRange(name("alpha"), x.get<double>(), kMinAlpha, kMaxAlpha));
        }
        if (k.alphas.empty()) fail("alpha", "expected a non-empty list");
    }
    if (j.contains("eye")) {
        const json& e = j["eye"];
        if (!e.is_array() || e.size() != 3 || !e[0].is_number() || !e[1].is_number() || !e[2].is_number())
            fail("eye", fmt::format("expected [x, y, z] in metres, found {}", e.dump()));
        for (int i = 0; i < 3; ++i)
            k.eye[i] = util::checkRange(name("eye"), e[i].get<double>(), -kMaxSceneLength, kMaxSceneLength, "m");
        if (!(k.eye.z > 0)) fail("eye", "the eye must be above the floor (z > 0)");
    }
    if (j.contains("albedo")) {
        if (!j["albedo"].is_number()) fail("albedo", fmt::format("expected a number, found {}", j["albedo"].dump()));
        k.albedo = util::checkRange(name("albedo"), j["albedo"].get<double>(), 0.0, 1.0);
    }
    return k;
}

Scene SceneKindKeys::applied(Scene s, double alpha) const
{
    s.kind = kind;
    s.alpha = alpha;
    s.eye = eye;
    s.albedo = albedo;
    return s;
}

json SceneKindKeys::recordKeys(const Scene& s)
{
    json j = json::object();
    if (s.shape != LightShape::Rect || s.width != 1 || s.length != 1) {
        j["shape"] = lightShapeName(s.shape);
        j["size"] = {s.width, s.length};
    }
    switch (s.kind) {
    case SceneKind::Diffuse:
        break;
    case SceneKind::Specular:
        j.update(json{{"scene_kind", sceneKindName(s.kind)}, {"alpha", s.alpha}, {"eye", {s.eye.x, s.eye.y, s.eye.z}}});
        break;
    case SceneKind::Indirect:
        j.update(json{{"scene_kind", sceneKindName(s.kind)}, {"albedo", s.albedo}});
        break;
    }
    return j;
}

}  // namespace lb
