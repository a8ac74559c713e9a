#include "experiments/report_bounds.h"

#include "experiments/runner.h"
#include "metrics/image.h"
#include "metrics/png.h"
#include "metrics/colour_bar.h"
#include "metrics/tonemap.h"
#include "photometry/names.h"
#include "util/error.h"
#include "util/fileio.h"
#include "util/json_file.h"

#include <filesystem>
#include <memory>
#include <vector>

namespace lb::experiments {

namespace fs = std::filesystem;
using nlohmann::json;

std::string jsonText(const json& j, const std::string& key, const std::string& def)
{
    return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : def;
}

std::string cellRole(const results::Record& r)
{
    return r.equal_time_to ? "equal_time" : jsonText(r.extra, "role", "method");
}

namespace {

struct Cell {
    fs::path stem;
    std::unique_ptr<Image> img;
    bool setsBound = true;
};

// The cells of one scene whose EXR is there and of the reference's size.
std::vector<Cell> sceneCells(const fs::path& idir, const std::vector<const results::Record*>& recs, const Image& ref)
{
    std::vector<Cell> cells;
    for (const auto* r : recs) {
        fs::path stem = idir / cellStem(*r);
        if (!fs::is_regular_file(stem.string() + ".exr")) continue;
        auto img = std::make_unique<Image>(readExr(stem.string() + ".exr"));
        if (img->width != ref.width || img->height != ref.height) continue;
        cells.push_back({stem, std::move(img), cellRole(*r) != "mci_curve"});
    }
    return cells;
}

// Rewrites a cell's error picture at `s` and adds the scale to its JSON.
void redraw(const Cell& c, const Image& ref, const SceneScale& s)
{
    const std::string jpath = c.stem.string() + ".json";
    json j = json::object();
    if (fs::is_regular_file(jpath)) {
        try {
            j = util::readJsonObject(jpath, "a picture's metrics (JSON)", size_t(1) << 20);
        } catch (const InputError&) {
            j = json::object();  // damaged: written again below
        }
    }
    j["bound"] = s.bound;
    j["mean_ref"] = s.meanRef;
    j["colour_bar"] = tonemap::colourBar(33);
    util::writeFilesAtomic(
        {{c.stem.string() + "_err.png", encodePng(tonemap::errorPicture(ref, *c.img, s.bound, s.bound))},
         {jpath, j.dump() + '\n'}});
}

}  // namespace

std::string cellStem(const results::Record& r)
{
    const std::string role = cellRole(r);
    const std::string spec =
        r.equal_time_to ? (r.equalTime ? r.equalTime->label : *r.equal_time_to) : jsonText(r.extra, "spec", r.method);
    return cellImageName(role, spec, r.baseline ? r.baseline->label : "");
}

void nameLuminaires(results::Results& doc)
{
    const fs::path dir = jsonText(doc.context, "luminaire_dir");
    std::map<std::string, std::string> names;  // luminaire -> its name
    for (auto& r : doc.records) {
        if (!r.extra.is_object() || r.extra.contains("luminaire_name")) continue;
        auto it = names.find(r.luminaire);
        if (it == names.end()) {
            const fs::path p = fs::path(r.luminaire).is_absolute() ? fs::path(r.luminaire) : dir / r.luminaire;
            it = names.emplace(r.luminaire, photometry::displayName(p.string())).first;
        }
        r.extra["luminaire_name"] = it->second;
    }
}

std::map<std::string, SceneScale> shareErrorBounds(const std::string& dir, const std::vector<results::Record>& recs)
{
    std::map<std::string, std::vector<const results::Record*>> byScene;
    for (const auto& r : recs) {
        const std::string s = jsonText(r.extra, "scene");
        if (!s.empty()) byScene[s].push_back(&r);
    }
    std::map<std::string, SceneScale> out;
    for (const auto& [scene, rs] : byScene) {
        const fs::path idir = fs::path(dir) / "images" / scene;
        if (!fs::is_regular_file(idir / "reference.exr")) continue;
        const Image ref = readExr((idir / "reference.exr").string());
        const std::vector<Cell> cells = sceneCells(idir, rs, ref);
        std::vector<const Image*> setting;
        for (const auto& c : cells)
            if (c.setsBound) setting.push_back(c.img.get());
        SceneScale s;
        s.bound = tonemap::sharedBound(ref, setting);
        double sum = 0;
        for (double v : ref.px) sum += v;
        s.meanRef = ref.px.empty() ? 0 : sum / double(ref.px.size());
        for (const auto& c : cells) redraw(c, ref, s);
        out[scene] = s;
    }
    return out;
}

}  // namespace lb::experiments
