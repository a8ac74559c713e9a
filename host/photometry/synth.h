// synth.h -- the suite's own luminaires (luminaires/, `lumibench luminaire synth`).
// Exact-answer profiles (rotational, fine gamma grid):
//   lambert  I = I0 cos(gamma) for gamma <= 90, 0 beyond; flux = pi I0
//   phong    I = I0 cos^n(gamma) for gamma <= 90, 0 beyond; flux = 2 pi I0 / (n + 1)
// with I0 chosen so the flux is exactly `flux` lm (default 1000).
// Profiles with the characters of the published set (24 planes x 15 deg,
// gamma 0..180 x 2.5 deg like the Zumtobel files), analytic shapes scaled to
// `flux` lm by the table's own integrated flux:
//   spot, downlight, linear, diffuse, batwing, sideways, updown.
#pragma once

#include "photometry/table.h"

#include <string>
#include <vector>

namespace lb::photometry {

struct SynthParams {
    double flux = 1000;  // lm
    double n = 10;  // phong exponent
    double gammaStep = 0.5;  // degrees, exact-answer profiles
};

std::vector<std::string> synthKinds();
// One line per kind, for --help and luminaires/README.md.
std::string synthDescription(const std::string& kind);
// Throws InputError for an unknown kind or bad parameters.
Table synth(const std::string& kind, const SynthParams& p = {});

}  // namespace lb::photometry
