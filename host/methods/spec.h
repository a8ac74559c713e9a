// spec.h -- SPEC strings `name:key=value,key=value` (docs/design.md section 7):
// the parser, the one place a method's family is looked up by name
// (methods/registry.h); everything after it takes the MethodSpec it returns
// (methods/family.h).
#pragma once

#include "methods/family.h"
#include "scene/scene.h"

#include <map>
#include <string>

namespace lb::methods {

// Parses and validates against the registry's family of that name for scenes
// of `kind`, and returns the method resolved to that family; throws InputError on an unknown method (or one that does not
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
