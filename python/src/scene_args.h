// scene_args.h -- lb.Scene and lb.Luminaire of the Python module: the
// scene as `lumibench render`'s flags give it (cli/cmd_render.cpp), each
// value checked with the CLI's message naming the keyword instead of the flag.
#pragma once

#include "common.h"

#include "photometry/table.h"
#include "scene/scene.h"

namespace lb::py {

// A scene as given: size "file" takes the luminaire's declared opening at
// render time (methods::sizeFromFile); an explicit shape wins over it.
struct PyScene {
    Scene scene;
    bool sizeFromFile = false;
    bool shapeGiven = false;
    // The scene for `table` (size "file" resolved), validated.
    Scene resolve(const photometry::Table& table) const;
};

void bindScene(nb::module_& m);

}  // namespace lb::py
