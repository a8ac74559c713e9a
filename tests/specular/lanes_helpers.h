// lanes_helpers.h -- shared by the tests that hold the specular scene's
// straight-line forms (ltc, mc) to their general kernels: the scene list and
// the per-pixel relative difference with a floor.
#pragma once

#include "methods/render_helpers.h"
#include "testutil.h"

#include <algorithm>
#include <cmath>
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

}  // namespace lb::test
