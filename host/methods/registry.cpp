#include "methods/registry.h"

#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>

namespace lb::methods {

// One line per family (host/methods/family_*.cpp).
void registerReference(Registry& r);
void registerDynamic(Registry& r);
void registerStructured(Registry& r);
void registerMc(Registry& r);
void registerCubature(Registry& r);
void registerVoronoi(Registry& r);
void registerIndirect(Registry& r);
void registerSpecular(Registry& r);
void registerRobust(Registry& r);
void registerEngine(Registry& r);
void registerSh(Registry& r);

namespace {
Registry builtinFamilies()
{
    Registry r;
    registerReference(r);
    registerDynamic(r);  // point, cp, np, mrp
    registerStructured(r);
    registerMc(r);
    registerCubature(r);
    registerVoronoi(r);
    registerIndirect(r);  // reference (indirect), vpl, kmeans, acrsm (and mc: VPLs)
    registerSpecular(r);  // reference, mc, ltc of the specular scene
    registerRobust(r);
    registerEngine(r);
    registerSh(r);
    return r;
}
}  // namespace

void Registry::add(Family f)
{
    for (SceneKind k : f.scenes)
        if (find(f.name, k))
            throw Error(fmt::format("method {} registered twice for the {} scene", f.name, sceneKindName(k)));
    families_.push_back(std::move(f));
}

const Family* Registry::find(const std::string& name, SceneKind kind) const
{
    for (auto& f : families_)
        if (f.name == name && renders(f, kind)) return &f;
    return nullptr;
}

std::string Registry::names(SceneKind kind) const
{
    std::vector<std::string> n;
    for (auto& f : families_)
        if (renders(f, kind)) n.push_back(f.name);
    return fmt::format("{}", fmt::join(n, "|"));
}

const Registry& registry()
{
    static const Registry r = builtinFamilies();
    return r;
}

const Family& family(const std::string& name, SceneKind kind)
{
    const Family* f = registry().find(name, kind);
    if (f) return *f;
    if (kind != SceneKind::Diffuse || registry().find(name, SceneKind::Specular) ||
        registry().find(name, SceneKind::Indirect)) {
        bool known = false;
        for (auto& g : registry().all()) known = known || g.name == name;
        if (known)
            throw InputError(fmt::format("method '{}' does not render the {} scene (methods that do: {})", name,
                                         sceneKindName(kind), registry().names(kind)));
    }
    throw InputError(fmt::format("unknown method '{}'; valid methods{}: {}", name,
                                 kind == SceneKind::Diffuse ? "" : " for the " + sceneKindName(kind) + " scene",
                                 registry().names(kind)));
}

void checkShape(const Family& f, const Scene& scene)
{
    if (std::find(f.shapes.begin(), f.shapes.end(), scene.shape) != f.shapes.end()) return;
    std::string names;
    for (const auto& g : registry().all())
        if (renders(g, scene.kind) && std::find(g.shapes.begin(), g.shapes.end(), scene.shape) != g.shapes.end())
            names += (names.empty() ? "" : ", ") + g.name;
    throw InputError(fmt::format("method {}: renders a rectangular light only, not shape={}; methods for it: {}",
                                 f.name, lightShapeName(scene.shape), names));
}

std::vector<TunableRow> tunables()
{
    std::vector<TunableRow> rows;
    for (auto& f : registry().all())
        for (auto& p : f.params) rows.push_back({f.name, p});
    return rows;
}

}  // namespace lb::methods
