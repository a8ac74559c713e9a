// lanes_helpers.h -- shared by the tests that hold the specular scene's
// straight-line forms (ltc, mc) to their general kernels: the scene list, the
// per-pixel relative difference with a floor, and the comparison itself.
#pragma once

#include "kernel_args.h"
#include "methods/render_helpers.h"
#include "photometry/table.h"
#include "testutil.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace lb::test {

inline Scene specular(double h, double R, double alpha, glm::dvec3 eye = {0, 4, 2})
{
    Scene s = test::scene(h, R, 45);  // odd: a column of pixels on x = 0
    s.kind = SceneKind::Specular;
    s.alpha = alpha;
    s.eye = eye;
    return s;
}

// Worst per-pixel difference of `test` from `ref`, relative to the pixel (floor
// 1e-9 of the image's peak: pixels where the lobe misses the light are 0 in
// both up to rounding); EXPECTs it within `bound`.
inline double worstRel(const Image& ref, const Image& test, double bound, const std::string& what, double floor = 1e-9)
{
    double peak = 0, worst = 0;
    for (double v : ref.px) peak = std::max(peak, std::fabs(v));
    EXPECT_GT(peak, 0) << what;
    for (size_t i = 0; i < ref.px.size(); ++i) {
        double d = std::fabs(ref.px[i] - test.px[i]) / std::max(std::fabs(ref.px[i]), floor * peak);
        worst = std::max(worst, d);
        EXPECT_LE(d, bound) << what << " pixel " << i << ": " << ref.px[i] << " vs " << test.px[i];
        if (d > bound) break;
    }
    return worst;
}

// Scenes: light close to and far from the floor, every published rotation's
// kind (facing down, tilted, edge-on at R = pi/2), a grazing eye (the lobe
// leans towards the horizon: the transformed quad crosses z = 0), an eye above
// the centre pixel (w_o along n there: lb_view_frame's fallback frame), and
// alpha from narrow to Lambert-like.
inline std::vector<Scene> straightLineScenes()
{
    std::vector<Scene> v;
    for (double alpha : {0.05, 0.25, 1.0}) {
        v.push_back(specular(1.1, 3 * M_PI / 4, alpha));
        v.push_back(specular(0.1, M_PI / 2, alpha));
        v.push_back(specular(2.5, M_PI, alpha));
    }
    v.push_back(specular(0.5, 5 * M_PI / 8, 0.1, {0, 4, 0.05}));
    v.push_back(specular(1.1, 7 * M_PI / 8, 0.5, {0, 0, 3}));
    v.push_back(specular(-0.2, 5 * M_PI / 8, 0.25));  // the light crosses the floor: the fan's clip along u
    v.push_back(specular(0.0, M_PI, 0.25));  // the light lying on the floor: the plane shift
    return v;
}

// Bounds of a straight-line form against its general kernel, per pixel and
// relative, each with a floor (a fraction of the image's peak): double within
// `dbl` (floor `dblFloor`); float within twice the general float kernel's own
// error against double, at least 1e-5 (floor `fltFloor`).
struct LanesBounds {
    double dbl, dblFloor, fltFloor;
};

// Holds `spec` (the straight-line form: its scene defines must
// contain `define`) to `spec` with specialize=none on every
// straightLineScenes() scene, in double and in float at 1 and 8 lanes.
inline void expectStraightLineEqualsGeneral(ocl::Runtime& rt, const photometry::Table& t, const std::string& spec,
                                            const char* define, LanesBounds b)
{
    using methods::Precision;
    const bool fp64 = rt.fp64();
    const std::string sep = spec.find(':') == std::string::npos ? ":" : ",";
    const std::string general = spec + sep + "specialize=none";
    double worstF = 0, worstD = 0;
    for (const Scene& s : straightLineScenes()) {
        const std::string what = spec + " " + s.describe();
        ASSERT_NE(planDefines(methods::parseSpec(spec, SceneKind::Specular), s, t).find(define), std::string::npos)
            << what;
        Image ref = run(rt, t, s, general, fp64 ? Precision::Double : Precision::Float).image;
        double bound = 1e-5;
        if (fp64) {
            Image genF = run(rt, t, s, general, Precision::Float).image;
            bound = std::max(bound, 2 * worstRel(ref, genF, 1.0, what + " general float", b.fltFloor));
            Image d = run(rt, t, s, spec, Precision::Double).image;
            worstD = std::max(worstD, worstRel(ref, d, b.dbl, what + " double", b.dblFloor));
        }
        for (const char* lanes : {"lanes=1", "lanes=8"}) {
            Image f = run(rt, t, s, spec + sep + lanes, Precision::Float).image;
            worstF = std::max(worstF, worstRel(ref, f, bound, what + " float " + lanes, b.fltFloor));
        }
        if (::testing::Test::HasFailure()) return;
    }
    std::cout << spec << ": straight-line form against the general kernel: float " << worstF << ", double " << worstD
              << "\n";
}

}  // namespace lb::test
