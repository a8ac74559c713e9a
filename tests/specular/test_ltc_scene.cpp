// The LTC table on the specular scene with a Lambertian luminaire: there
// Cubature + LTC is exactly (I0 / A) x the LTC integral of the light
// (SpecularMethods.LtcOfALambertianEmitterIsItsRadianceTimesTheLtcIntegral),
// so every error left is the table's. On the host: the reference
// (specref.h) and the LTC (ltc.h), as the kernels compute them.
#include "ltc/ltc.h"
#include "math/kmath.h"
#include "methods/analytic.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lb {
namespace {

struct Images {
    std::vector<double> ref, fixed, free;
};

// Lambertian luminaire (I = 1000 cd cos gamma), alpha, eye (0, 4, 2), the
// light at h, R; res^2 pixels over 5 x 5 m: the reference (tol 1e-5) and the
// LTC image of each table.
Images render(double alpha, double h, double R, int res, const ltc::Table& fixed, const ltc::Table& free)
{
    Scene sc;
    sc.kind = SceneKind::Specular;
    sc.alpha = alpha;
    sc.height = h;
    sc.rotation = R;
    sc.res = res;
    auto P = sc.params();
    auto lum = methods::loadLuminaire("analytic:cos1").packed();
    f64::lb_light L = f64::lb_scene_light(P.data());
    std::vector<float> tf = ltc::packed(fixed), tn = ltc::packed(free);
    const double le = 1000 / (sc.width * sc.length);  // I0 / A
    Images im;
    for (int row = 0; row < res; ++row)
        for (int col = 0; col < res; ++col) {
            glm::dvec3 x = f64::lb_pixel_position(P.data(), row, col);
            f64::lb_adapt_report rep;
            im.ref.push_back(f64::lb_specular_reference(lum.data(), L, x, {0, 0, 1}, sc.eye, alpha,
                                                        f64::lb_adapt_goal_of(1e-5, 160), &rep));
            f64::real3 q[4];
            f64::lb_light_corners(L, q);
            for (auto& v : q) v -= x;
            bool front = glm::dot(x - L.c, L.n) > 0;
            glm::dvec3 wo = glm::normalize(sc.eye - x);
            im.fixed.push_back(front ? le * f64::lb_ltc_brdf_polygon(tf.data(), q, 4, {0, 0, 1}, wo, alpha) : 0.0);
            im.free.push_back(front ? le * f64::lb_ltc_brdf_polygon(tn.data(), q, 4, {0, 0, 1}, wo, alpha) : 0.0);
        }
    return im;
}

// DESIGN section 5: (1/P) sum (R - A)^2 / (mean(R) mean(A)).
double nmse(const std::vector<double>& r, const std::vector<double>& a)
{
    double mr = 0, ma = 0, s = 0;
    for (size_t k = 0; k < r.size(); ++k) {
        mr += r[k] / r.size();
        ma += a[k] / r.size();
        s += (r[k] - a[k]) * (r[k] - a[k]) / r.size();
    }
    return s / (mr * ma);
}

TEST(LtcScene, FreeFrameTableOnTheLambertianScene)
{
    // alpha 0.3, h 0.6, R 3pi/4, 16 x 16 pixels: NMSE measured 0.0054 with
    // the committed (free-frame, L1) table, 0.0468 with the fixed-frame one
    // (0.0467 on the device at 32 x 32; the reference's own error, 1e-5
    // relative, adds < 1e-9): asserted below 1e-2. For every alpha of the
    // sweep the committed table is not worse than the fixed-frame one,
    // measured 0.0056 -> 0.00079 (alpha 0.05), 0.022 -> 0.0037 (0.1), 0.053 ->
    // 0.0067 (0.25), 0.025 -> 0.0023 (0.5), 0.00249 -> 0.00231 (1): asserted
    // with no slack. (At alpha 1 the lobe is wide, both frames fit it alike
    // and the L1 fit is not the NMSE's optimum: over other heights and
    // rotations the two tables differ there by -8 % to +7 %, docs/specular.md.)
    ltc::Table fixed = ltc::read(ltc::dataDir() + "/ltc/ggx-fixed.json");
    const ltc::Table& free = ltc::defaultTable();
    Images im = render(0.3, 0.6, 3 * M_PI / 4, 16, fixed, free);
    double nf = nmse(im.ref, im.fixed), nn = nmse(im.ref, im.free);
    std::printf("alpha 0.3: NMSE fixed-frame table %.4g, committed table %.4g\n", nf, nn);
    EXPECT_LT(nn, 1e-2);
    for (double alpha : {0.05, 0.1, 0.25, 0.5, 1.0}) {
        Images s = render(alpha, 0.6, 3 * M_PI / 4, 16, fixed, free);
        double a = nmse(s.ref, s.fixed), b = nmse(s.ref, s.free);
        std::printf("alpha %.2f: NMSE fixed-frame table %.4g, committed table %.4g\n", alpha, a, b);
        EXPECT_LE(b, a) << "alpha " << alpha;
    }
}

}  // namespace
}  // namespace lb
