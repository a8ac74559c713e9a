// table.cpp -- the LTC table file (ltc.h): JSON with the fit's options and
// one row of numbers per cell, doubles in round-trip precision.
#include "ltc/ltc.h"

#include "util/error.h"
#include "util/fileio.h"
#include "util/json_file.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <mutex>
#include "lb_build_config.h"

namespace lb::ltc {

namespace {
constexpr const char* kFormat = "lumibench-ltc-ggx";
constexpr int kVersion = 2;  // 1: no frame, objective, phi (Heitz's fit: fixed, l3)

const char* frameName(Frame f) { return f == Frame::Fixed ? "fixed" : "free"; }
const char* objectiveName(Objective o) { return o == Objective::L3 ? "l3" : "l1"; }
}  // namespace

std::string toJson(const Table& t)
{
    nlohmann::json j;
    j["format"] = kFormat;
    j["version"] = kVersion;
    j["brdf"] = "GGX, height-correlated Smith G2, F = 1 (DESIGN section 8)";
    j["grid"] = "cell (i, j) at index j * size + i: sqrt(alpha) = i / (size - 1) (alpha >= alpha_min), "
                "theta_o = min(j / (size - 1) * pi / 2, theta_max)";
    j["size"] = t.options.size;
    j["samples"] = t.options.samples;
    j["norm_panels"] = t.options.normPanels;
    j["alpha_min"] = t.options.alphaMin;
    j["theta_max"] = t.options.thetaMax;
    j["max_eval"] = t.options.maxEval;
    j["frame"] = frameName(t.options.frame);
    j["objective"] = objectiveName(t.options.objective);
    j["columns"] = {"m00", "m02", "m20", "m22", "norm", "error", "l1", "m11", "m22p", "m13", "phi"};
    nlohmann::json cells = nlohmann::json::array();
    for (const Cell& c : t.cells)
        cells.push_back({c.m00, c.m02, c.m20, c.m22, c.norm, c.error, c.l1, c.m11, c.m22p, c.m13, c.phi});
    j["cells"] = std::move(cells);
    // one cell per line: diffable, and the numbers round-trip exactly
    std::string s = "{\n";
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
        if (it.key() == "cells") continue;
        s += fmt::format("{}  {}: {}", first ? "" : ",\n", nlohmann::json(it.key()).dump(), it.value().dump());
        first = false;
    }
    s += ",\n  \"cells\": [\n";
    for (size_t i = 0; i < j["cells"].size(); ++i)
        s += "    " + j["cells"][i].dump() + (i + 1 < j["cells"].size() ? ",\n" : "\n");
    s += "  ]\n}\n";
    return s;
}

void write(const Table& t, const std::string& path) { util::writeFileAtomic(path, toJson(t)); }

namespace {

// The options of a version 1 or 2 file (version 1: Heitz's fixed frame, l3).
FitOptions readOptions(const std::function<const nlohmann::json&(const char*)>& need, int version,
                       const std::string& path)
{
    FitOptions o;
    o.size = need("size").get<int>();
    o.samples = need("samples").get<int>();
    o.normPanels = need("norm_panels").get<int>();
    o.alphaMin = need("alpha_min").get<double>();
    o.thetaMax = need("theta_max").get<double>();
    o.maxEval = need("max_eval").get<int>();
    o.frame = Frame::Fixed;
    o.objective = Objective::L3;
    if (version == 1) return o;
    std::string f = need("frame").get<std::string>(), ob = need("objective").get<std::string>();
    if (f != "fixed" && f != "free")
        throw InputError(fmt::format("{}: frame \"{}\" (expected \"fixed\" or \"free\")", path, f));
    if (ob != "l3" && ob != "l1")
        throw InputError(fmt::format("{}: objective \"{}\" (expected \"l3\" or \"l1\")", path, ob));
    o.frame = f == "fixed" ? Frame::Fixed : Frame::Free;
    o.objective = ob == "l3" ? Objective::L3 : Objective::L1;
    return o;
}

// Cell k: 10 numbers (version 1; phi from M^-1: M's first column is m11 X,
// X = (cos phi, 0, -sin phi)) or 11 (version 2).
Cell readCell(const nlohmann::json& r, int version, size_t k, const std::string& path)
{
    size_t want = version == 1 ? 10 : 11;
    if (!r.is_array() || r.size() != want)
        throw InputError(fmt::format("{}: cell {}: expected {} numbers", path, k, want));
    Cell c;
    double* f[11] = {&c.m00, &c.m02, &c.m20, &c.m22, &c.norm, &c.error, &c.l1, &c.m11, &c.m22p, &c.m13, &c.phi};
    for (size_t q = 0; q < want; ++q) {
        *f[q] = r[q].get<double>();
        if (!std::isfinite(*f[q])) throw InputError(fmt::format("{}: cell {}: non-finite value", path, k));
    }
    if (version == 1) c.phi = std::atan2(c.m20, c.m22);
    // A fitted LTC's M^-1 keeps the hemisphere's orientation (m00 > 0, the
    // determinant of its 2 x 2 part positive: ~1e-10 at the smoothest cells of
    // data/ltc/); an all-zero or negated matrix renders black or garbage.
    const double det = c.m00 * c.m22 - c.m02 * c.m20;
    if (!(c.m00 > 0 && det > 0))
        throw InputError(fmt::format("{}: cell {}: M^-1 [[{}, {}], [{}, {}]] is not an invertible matrix that keeps "
                                     "the hemisphere's orientation (expected m00 > 0 and m00 m22 - m02 m20 > 0, got "
                                     "{})",
                                     path, k, c.m00, c.m02, c.m20, c.m22, det));
    if (!(c.norm > 0 && c.norm <= 1.0 + 1e-9))
        throw InputError(fmt::format("{}: cell {}: norm {} outside (0, 1]", path, k, c.norm));
    return c;
}

}  // namespace

Table read(const std::string& path)
{
    std::string text = util::readFile(path, "LTC table file", 64u << 20);
    const nlohmann::json j = util::parseJson(text, path);
    auto need = [&](const char* k) -> const nlohmann::json& {
        if (!j.is_object() || !j.contains(k))
            throw InputError(fmt::format("{}: LTC table lacks the key \"{}\"", path, k));
        return j.at(k);
    };
    try {
        int version = need("version").get<int>();
        if (need("format").get<std::string>() != kFormat || version < 1 || version > kVersion)
            throw InputError(fmt::format("{}: expected format \"{}\" version 1..{}", path, kFormat, kVersion));
        Table t;
        t.options = readOptions(need, version, path);
        int n = t.options.size;
        const auto& cells = need("cells");
        if (n < 2 || n > 1024 || !cells.is_array() || cells.size() != static_cast<size_t>(n) * n)
            throw InputError(fmt::format("{}: expected size in 2..1024 and size^2 cells, got size {} and {} cells",
                                         path, n, cells.is_array() ? cells.size() : 0));
        for (size_t k = 0; k < cells.size(); ++k) t.cells.push_back(readCell(cells[k], version, k, path));
        return t;
    } catch (const nlohmann::json::exception& e) {
        throw InputError(fmt::format("{}: malformed LTC table: {}", path, e.what()));
    }
}

std::vector<float> packed(const Table& t)
{
    std::vector<float> v;
    v.reserve(1 + 5 * t.cells.size());
    v.push_back(static_cast<float>(t.options.size));
    for (const Cell& c : t.cells)
        for (double x : {c.m00, c.m02, c.m20, c.m22, c.norm}) v.push_back(static_cast<float>(x));
    return v;
}

std::string dataDir()
{
    if (const char* env = std::getenv("LUMIBENCH_DATA_DIR"); env && *env) return env;
    return std::string(LB_SOURCE_DIR) + "/data";
}

std::string defaultTablePath() { return dataDir() + "/ltc/ggx.json"; }

const Table& defaultTable()
{
    static std::once_flag once;
    static Table t;
    std::call_once(once, [] { t = read(defaultTablePath()); });
    return t;
}

}  // namespace lb::ltc
