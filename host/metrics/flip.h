// flip.h -- mean HDR-FLIP (Andersson et al. 2021) of a test image against a
// reference (docs/design.md section 5), as computed by NVIDIA's `flip-evaluator`
// package (PyPI; scripts/install-deps.sh installs it into the project's
// .venv). There is no FLIP of our own: the package is the definition.
//
// The first call starts one Python co-process (host/metrics/flip_server.py)
// that lives as long as this process; every later call writes the two images
// as float32 files into a private temporary directory and asks it for the
// mean over a socket, so no image pays a Python start-up. The directory,
// lumibench-flip-PID-XXXXXX, is removed when the process ends, and one left by
// a killed process by the next that starts FLIP. A co-process that dies is
// started again once per image. The Python is
// $LUMIBENCH_FLIP_PYTHON when set, else <source dir>/.venv/bin/python (not
// $LUMIBENCH_PYTHON: that one picks the plotting Python, default the Debian
// /usr/bin/python3, which has no flip-evaluator).
//
// The Y image is given as R = G = B with the package's HDR defaults. A
// non-finite test pixel is left out of the mean (it takes the reference's
// value inside FLIP, so it adds no error to its neighbours either);
// negative lux is clamped to 0, since FLIP takes non-negative HDR input.
//
// Where the package cannot be imported (or the co-process fails), flip()
// returns NaN (null in JSON) and says why on stderr once per process: never
// a made-up 0, never an exception.
#pragma once

#include "metrics/image.h"

#include <string>

namespace lb::metrics {

// Mean HDR-FLIP of `test` against `reference` in [0, 1]; NaN when FLIP is not
// available or every test pixel is non-finite. Throws lb::InputError when the
// sizes differ or the reference has a non-finite pixel (as compare() does).
double flip(const Image& reference, const Image& test);

// Whether FLIP can be computed (starts the co-process); `why` gets the reason
// when it cannot, or the package and version ("flip-evaluator 1.7") when it can.
bool flipAvailable(std::string* why = nullptr);

// The Python the co-process runs with: $LUMIBENCH_FLIP_PYTHON, else the source
// tree's .venv/bin/python.
std::string flipPython();

}  // namespace lb::metrics
