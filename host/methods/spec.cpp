#include "methods/spec.h"

#include "methods/registry.h"
#include "util/error.h"
#include "util/json_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace lb::methods {

MethodSpec parseSpec(const std::string& text, SceneKind kind)
{
    MethodSpec s;
    size_t colon = text.find(':');
    s.name = text.substr(0, colon);
    s.kind = kind;
    const Family& f = family(s.name, kind);
    s.fam = &f;
    for (auto& p : f.params) s.values[p.name] = p.def;
    std::string rest = colon == std::string::npos ? std::string() : text.substr(colon + 1);
    size_t b = 0;
    while (!rest.empty()) {
        size_t e = rest.find(',', b);
        std::string kv = rest.substr(b, e == std::string::npos ? std::string::npos : e - b);
        size_t eq = kv.find('=');
        if (eq == std::string::npos || eq == 0)
            throw InputError(fmt::format("method spec '{}': expected key=value, got '{}'", text, kv));
        std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
        const Param& p = f.param(key);
        if (s.given.count(key)) throw InputError(fmt::format("method spec '{}': {} given twice", text, key));
        s.values[key] = p.canonical(f.name, value);
        s.given.insert(key);
        if (e == std::string::npos) break;
        b = e + 1;
    }
    f.validate(s);
    return s;
}

namespace {

// The presets files being read, outermost first: parsing an entry validates
// it, and a cubature entry's validation reads its own preset file, so a file
// naming itself (or two naming each other) would recurse until the stack ran
// out. A preset may not name another preset: a second level is refused at
// once, naming the chain.
struct PresetChain {
    static std::vector<std::string>& files()
    {
        static thread_local std::vector<std::string> f;
        return f;
    }
    explicit PresetChain(const std::string& file)
    {
        auto& f = files();
        if (!f.empty()) {
            const bool cycle = std::find(f.begin(), f.end(), file) != f.end();
            throw InputError(fmt::format("{}: presets nested ({} -> {}{}): a preset may not name another preset",
                                         f.front(), fmt::join(f, " -> "), file, cycle ? ", a cycle" : ""));
        }
        f.push_back(file);
    }
    ~PresetChain() { files().pop_back(); }
    PresetChain(const PresetChain&) = delete;
    PresetChain& operator=(const PresetChain&) = delete;
};

}  // namespace

std::map<std::string, std::string> readPresets(const std::string& file, const std::string& family, SceneKind kind)
{
    const PresetChain chain(file);
    // A presets file holds one SPEC per luminaire: 1 MiB is thousands.
    const nlohmann::json j = util::readJsonObject(file, "a presets file (JSON: luminaire file name -> SPEC)", 1u << 20);
    std::map<std::string, std::string> out;
    for (const auto& [lum, v] : j.items()) {
        if (!v.is_string())
            throw InputError(fmt::format("{}: entry '{}': expected a SPEC string, found {}", file, lum, v.dump()));
        MethodSpec e;
        try {
            e = parseSpec(v.get<std::string>(), kind);
        } catch (const InputError& err) {
            throw InputError(fmt::format("{}: entry '{}': {}", file, lum, err.what()));
        }
        if (e.name != family)
            throw InputError(
                fmt::format("{}: entry '{}': a {} SPEC where method {} is preset", file, lum, e.name, family));
        if (e.given.count("preset"))
            throw InputError(fmt::format("{}: entry '{}': a preset may not name another preset", file, lum));
        out[lum] = v.get<std::string>();
    }
    return out;
}

MethodSpec resolvePreset(const MethodSpec& s, const std::string& luminaireSource)
{
    auto it = s.values.find("preset");
    if (it == s.values.end() || it->second == "none") return s;
    const std::string file = it->second;
    const auto entries = readPresets(file, s.name, s.kind);
    const std::string lum = std::filesystem::path(luminaireSource).filename().string();
    auto e = entries.find(lum);
    if (e == entries.end()) {
        std::vector<std::string> names;
        for (const auto& [k, v] : entries) names.push_back(k);
        throw InputError(fmt::format("method {}: preset file '{}' has no entry for luminaire '{}' (entries: {})",
                                     s.name, file, lum.empty() ? "(no file)" : lum,
                                     names.empty() ? std::string("none") : fmt::format("{}", fmt::join(names, ", "))));
    }
    MethodSpec r = parseSpec(e->second, s.kind);
    for (const auto& k : s.given)
        if (k != "preset") {
            r.values[k] = s.values.at(k);
            r.given.insert(k);
        }
    s.family().validate(r);
    return r;
}

}  // namespace lb::methods
