// spec.h -- SPEC strings `name:key=value,key=value` (docs/design.md section 7).
#pragma once

#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace lb::methods {

struct MethodSpec {
    std::string name;
    SceneKind kind = SceneKind::Diffuse;  // the scene its family renders (family(name, kind))
    std::map<std::string, std::string> values;  // every parameter, canonical text, defaults filled in
    std::set<std::string> given;  // the keys the SPEC named

    double num(const std::string& key) const;  // Real / Int parameters
    long integer(const std::string& key) const;
    const std::string& str(const std::string& key) const;  // Choice parameters
    std::vector<std::string> list(const std::string& key) const;  // List parameters
    bool has(const std::string& key) const { return values.count(key) != 0; }
    // A copy with `key` set to `value` (the keys given stay given), checked
    // as parseSpec checks a SPEC: InputError for a key the family lacks or a
    // bad value.
    MethodSpec with(const std::string& key, const std::string& value) const;

    // name:key=value,... with every parameter, keys sorted (cache keys, logs).
    std::string canonical() const;
    // {key: value}, numbers as JSON numbers (result files).
    nlohmann::json paramsJson() const;
};

// Parses and validates against the registry's family of that name for scenes
// of `kind`; throws InputError on an unknown method (or one that does not
// render that scene), an unknown key (listing the valid ones), a repeated key
// or a bad value.
MethodSpec parseSpec(const std::string& text, SceneKind kind = SceneKind::Diffuse);

// Per-luminaire presets: a family with a Text parameter "preset" (cubature,
// robust) takes its spec from a presets file, a JSON object mapping a
// luminaire file's name (e.g. "lambert.ldt") to a SPEC of the same family
// (`lumibench tune` writes one with "presets": true).
//
// The file's entries as name -> SPEC, each checked (parseSpec, same family,
// no preset of its own); InputError naming the file otherwise.
std::map<std::string, std::string> readPresets(const std::string& file, const std::string& family,
                                               SceneKind kind = SceneKind::Diffuse);
// s itself when it has no preset (or "none"); else the entry of the
// luminaire file `luminaireSource` (its name: the path's last part) with the
// keys s gave besides preset on top, preset reset to none. InputError naming
// the file, the luminaire and the entries it has when there is no entry.
MethodSpec resolvePreset(const MethodSpec& s, const std::string& luminaireSource);

}  // namespace lb::methods
