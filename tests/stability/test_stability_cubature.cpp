// The stability catalogue through several structural variants of `cubature`
// and through `voronoi` (lumibench stability itself runs each registered
// method with its defaults only). Float and double on every non-degenerate
// case: no non-finite pixel, exactly zero where nothing reaches the receiver,
// the point-light limit in the far field, float within 5 % (of the
// reference's max) of double.
#include "methods/render.h"
#include "stability/stability.h"
#include "testutil.h"

#include <cmath>
#include <cstdlib>

namespace lb {
namespace {

TEST(StabilityCubature, CatalogueThroughTheKernel)
{
    LB_REQUIRE_RUNTIME(rt);
    // fan/delaunay, the three weightings, the form-factor normalisation, one,
    // two and four dynamic points; and voronoi.
    const char* variants[] = {"cubature", "cubature:triangulation=delaunay,weighting=sample,normalize=formfactor",
                              "cubature:triangulation=delaunay,weighting=dotout,dynamic=cp+np+mrp+barycentre",
                              "cubature:triangulation=delaunay,dynamic=cp+barycentre,normalize=formfactor", "voronoi"};
    methods::RenderOptions ro;
    ro.reps = 1;
    for (auto& c : stability::catalogue()) {
        if (c.expect == stability::Expect::Rejected) continue;
        if (c.kind != SceneKind::Diffuse) continue;  // the cubature renders the diffuse scene
        if (!stability::missingLuminaire(c).empty()) continue;  // a ../shared file that is absent
        if (c.shape != LightShape::Rect) continue;  // these variants are the rectangle's (disk.h: the fan)
        // Odd: a pixel row at y = 0 in every case. LUMIBENCH_STABILITY_RES
        // (odd) runs it finer by hand; CI keeps 9.
        const char* env = std::getenv("LUMIBENCH_STABILITY_RES");
        Scene s = stability::sceneOf(c, env ? std::atoi(env) : 9);
        auto table = stability::luminaire(c.luminaire);
        Image ref =
            methods::render(*rt, table, s, methods::parseSpec("reference"), methods::Precision::Double, ro).image;
        double rmax = 0;
        for (double v : ref.px) rmax = std::max(rmax, v);
        for (std::string v : variants) {
            auto spec = methods::parseSpec(v);
            Image d = methods::render(*rt, table, s, spec, methods::Precision::Double, ro).image;
            Image f = methods::render(*rt, table, s, spec, methods::Precision::Float, ro).image;
            for (auto* img : {&d, &f}) {
                bool dbl = img == &d;
                auto e = stability::measure(ref, *img);
                EXPECT_EQ(e.nonfinite, 0) << c.name << " " << v << (dbl ? " double" : " float");
                if (c.expect == stability::Expect::Zero) {
                    for (double x : img->px) ASSERT_EQ(x, 0.0) << c.name << " " << v;
                }
                // The reference meets the point light to 6 (a/d)^2, far below
                // the first-order bound every method must meet.
                if (c.expect == stability::Expect::PointLimit) {
                    EXPECT_LE(stability::maxDiffRel(*img, ref, rmax), stability::pointBound(s, dbl))
                        << c.name << " " << v << (dbl ? " double" : " float");
                }
            }
            // Float vs double on the scale of the answer, as lumibench stability.
            EXPECT_LE(stability::maxDiffRel(f, d, rmax), 0.05) << c.name << " " << v;
        }
    }
}

}  // namespace
}  // namespace lb
