// table.h -- a luminaire as one unfolded intensity table (docs/design.md section 3):
// C in [0, 360] (the 360 plane repeats 0), gamma over the measured range,
// absolute candela. The readers (ldt, ies) and the synthesiser produce it;
// kernels receive packed() (layout: kernels/common/photometry.h).
#pragma once

#include "photometry/opening.h"

#include <functional>
#include <string>
#include <vector>

namespace lb::photometry {

struct Table {
    std::vector<double> c;  // C angles, degrees, ascending, c.front() == 0, c.back() == 360
    std::vector<double> gamma;  // gamma angles, degrees, ascending, within [0, 180]
    std::vector<double> cd;  // absolute candela, cd[ic * gamma.size() + ig]

    // What the file said (for `luminaire info`); empty / negative when unknown.
    std::string source;  // path of the file read, "" if synthesised
    std::string format;  // "ldt", "ies", "synth"
    int isym = -1;  // EULUMDAT symmetry indicator 0..4, or the IES equivalent
    std::string symmetry;  // "none", "rotational", "C0-C180", "C90-C270", "quadrant"
    double declaredFluxLm = -1;  // luminaire flux the file declares (LDT: lamp flux x LOR), < 0 if none
    // The luminous opening the file declares (a point if none). The scene
    // does not use it yet: every light is the rectangle of DESIGN section 2.
    Opening opening;
    Tilt tilt;  // IES TILT=INCLUDE (kept; a scene refuses a non-trivial one, see load.h)

    size_t nc() const { return c.size(); }
    size_t ng() const { return gamma.size(); }
    double at(size_t ic, size_t ig) const { return cd[ic * gamma.size() + ig]; }

    // Throws lb::Error if the invariants above do not hold.
    void validate() const;
    // Bilinear intensity (the kernels' lookup, double precision host copy).
    double intensity(double cDeg, double gammaDeg) const;
    // Luminous flux by integration of the interpolated table over the sphere (lm).
    double fluxLm() const;
    double maxCd() const;
    // The float buffer kernels take (kernels/common/photometry.h).
    std::vector<float> packed() const;
};

// A table sampled from a function I(C, gamma) (degrees -> cd) on a uniform grid
// of nc C planes over [0, 360] and ng gammas over [g0, g1].
Table tabulate(const std::function<double(double cDeg, double gammaDeg)>& f, int nc, int ng, double g0 = 0,
               double g1 = 180);

}  // namespace lb::photometry
