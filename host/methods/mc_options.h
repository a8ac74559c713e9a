// mc_options.h -- the Monte Carlo family's sampling choices (kernels/mc.cl,
// common/mc_sample.h): domain, sequence, the paper's preset, and the -D
// options and kernel arguments they give.
#pragma once

#include "methods/spec.h"
#include "photometry/table.h"
#include "scene/scene.h"

#include <string>

namespace lb::methods {

struct McOptions {
    std::string domain = "area";  // area | solid | projected | mis | table | mis_table | mis_table_solid
    std::string sequence = "shared";  // shared | random | sobol | zsobol
    std::string pattern = "poisson";  // the shared set (methods/samples.h)
    bool shift = false;  // shared set: per-pixel Cranley-Patterson rotation
    bool cosineWarp = false;  // solid: Hart et al.'s bilinear cosine warp
    double minSolid = 1e-3;  // solid: area sampling below this solid angle (sr)
    double misSplit = 0.5;  // mis, mis_table(_solid): share of the N samples that are projected (solid)
    std::string denoise = "none";  // none | gauss16 | atrous
    double gaussSigma = 0;  // gauss16: sigma in pixels (0: the default footprint, methods/mc_denoise.h)
    int gaussRadius = 0;  // gauss16: taps -radius .. radius (0: from sigma)
    // Whether the kernel takes its extended path (anything but today's MCI).
    bool extended() const;
    // The projected (mis_table_solid: solid-angle) samples of the mis domains out of n.
    int projectedOf(int n) const;
};

// The options of spec s (family mc); paper=1 resolves to the paper's MC: solid
// angle, Halton points shared by the pixels with a per-pixel random shift,
// area sampling below 1e-3 sr. InputError when paper=1 meets a key it sets.
McOptions mcOptions(const MethodSpec& s);
void validateMc(const MethodSpec& s);

// The structural -D options of the options (" -DLB_MC_EXT ..." or "").
std::string mcDefines(const McOptions& o);
// The per-scene ones: the horizon clip along v; InputError where the domain
// needs it and the scene has no such clip, or zsobol's index would not fit.
std::string mcSceneDefines(const McOptions& o, const Scene& scene, int n);

// Whether the extended path runs in its straight-line form (kernels/mc.cl,
// LB_MC_STRAIGHT): domain area, solid (also with the warp), projected or
// mis, every sequence, the rectangle, the trig-free table, specialize=auto.
// The table domains and the disk keep the general path.
bool mcStraight(const McOptions& o, const Scene& scene, bool lut, bool specialize);

// log2 of the samples per pixel, rounded up (zsobol's digit count, sobol's bits).
int mcLog2(int samples);

}  // namespace lb::methods
