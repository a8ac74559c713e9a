// Voronoi-cell weights of thesis 5.1 (kernels/common/voronoi.h).
#include "math/kmath.h"

#include <gtest/gtest.h>

#include <random>

namespace {
using namespace lb::f64;

// With p at the barycentre of a unit square the cells are closed forms: the
// centre's cell is the diamond |x| + |y| <= 1/2 (area 1/2), shared by the
// two coincident samples (1/4 each), each corner 1/8.
TEST(Voronoi, CentreOfSquareClosedForm)
{
    real f[LB_VOR_SITES];
    lb_voronoi_fractions(real2(0, 0), 1, 1, f);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(f[i], 0.125, 1e-14);
    EXPECT_NEAR(f[4], 0.25, 1e-14);
    EXPECT_NEAR(f[5], 0.25, 1e-14);
}

// p on corner 0 of a 2 x 1 light: the corner's cell is its quadrant box
// [-1, 0] x [-0.5, 0] (area 1/2) less the trapezoid beyond the bisector with
// the centre, x + y/2 > -5/8 (widths 5/8 at y = 0 and 3/8 at y = -1/2: area
// 1/4), so 1/4 of the light's 2: fraction 1/8, shared with p: 1/16 each.
// And mirrored positions of p give mirrored weights.
TEST(Voronoi, SymmetryAndSharing)
{
    real f[LB_VOR_SITES], g[LB_VOR_SITES];
    lb_voronoi_fractions(real2(-1, -0.5), 2, 1, f);
    EXPECT_NEAR(f[0], 1.0 / 16, 1e-14);
    EXPECT_NEAR(f[5], 1.0 / 16, 1e-14);
    std::mt19937 r(3);
    std::uniform_real_distribution<double> U(-1, 1);
    for (int it = 0; it < 200; ++it) {
        real2 p(U(r), 0.5 * U(r));
        lb_voronoi_fractions(p, 2, 1, f);
        lb_voronoi_fractions(real2(-p.x, p.y), 2, 1, g);  // mirror at x = 0: corners 0<->1, 2<->3
        EXPECT_NEAR(f[0], g[1], 1e-12);
        EXPECT_NEAR(f[3], g[2], 1e-12);
        EXPECT_NEAR(f[4], g[4], 1e-12);
        EXPECT_NEAR(f[5], g[5], 1e-12);
    }
}

// The cells partition the light: fractions sum to 1, none negative, for p
// anywhere on it (interior, edges, corners, near the barycentre).
TEST(Voronoi, FractionsPartitionTheLight)
{
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 40; ++j) {
            real2 p(-0.5 + i / 40.0, -0.75 + 1.5 * j / 40.0);
            real f[LB_VOR_SITES];
            lb_voronoi_fractions(p, 1, 1.5, f);
            double sum = 0;
            for (double x : f) {
                EXPECT_GE(x, 0);
                sum += x;
            }
            // exact partition up to rounding of the clipped areas
            EXPECT_NEAR(sum, 1, 1e-12) << p.x << " " << p.y;
        }
}

}  // namespace

#include "kernel_args.h"
#include "methods/voronoi_table.h"
#include "photometry/table.h"
#include "scene/scene.h"
#include "testutil.h"

namespace {

// At the table's nodes the lookup returns the fractions (float-rounded: 1e-7).
TEST(Voronoi, TableLookupAtNodes)
{
    using namespace lb::f64;
    const int res = 9;
    auto tab = lb::methods::voronoiTable(res, 1, 1);
    for (int jb = 0; jb < res; ++jb)
        for (int ia = 0; ia < res; ++ia) {
            real f[LB_VOR_SITES], g[LB_VOR_SITES];
            real a = double(ia) / (res - 1), b = double(jb) / (res - 1);
            lb_voronoi_lookup(tab.data(), res, a, b, f);
            lb_voronoi_fractions(real2(a - 0.5, b - 0.5), 1, 1, g);
            for (int k = 0; k < LB_VOR_SITES; ++k) EXPECT_NEAR(f[k], g[k], 1e-7);
        }
}

// A Lambertian emitter seen from afar (the light spans < 20 degrees from
// 3.6 m): six samples with area fractions integrate the nearly constant
// L G within 1%.
TEST(Voronoi, LambertianFar)
{
    using namespace lb::f64;
    auto lum = lb::photometry::tabulate(
                   [](double, double g) { return g <= 90 ? 1000 * std::cos(g * M_PI / 180) : 0.0; }, 2, 2881)
                   .packed();
    auto tab = lb::methods::voronoiTable(33, 1, 1);
    lb::Scene s;
    s.height = 3.1;
    s.rotation = M_PI;
    auto P = s.params();
    lb_light L = lb_scene_light(P.data());
    for (double xx : {0.0, 1.0, 2.5}) {
        real3 x(xx, 0.3, 0), nx(0, 0, 1);
        real3 poly[LB_MAXV];
        lb_light_corners(L, poly);
        for (int i = 0; i < 4; ++i) poly[i] -= x;
        double exact = 1000 / (L.w * L.l) * lb_polygon_irradiance_lambert(poly, 4, nx);
        double e = lb_voronoi_irradiance(lum.data(), tab.data(), 33, L, x, nx, 1e-3);
        EXPECT_NEAR(e, exact, 1e-2 * exact) << xx;
    }
}

// voronoi.cl on the device equals the host code (float, 32 x 32, h = 1,
// R = 3pi/4): 1e-4 relative, as for the cubature kernel.
TEST(Voronoi, KernelMatchesHost)
{
    using namespace lb;
    LB_REQUIRE_RUNTIME(rt);
    auto lum =
        photometry::tabulate(
            [](double c, double g) {
                return 600 + 400 * std::cos(g * M_PI / 180) + 150 * std::sin(g * M_PI / 180) * std::cos(c * M_PI / 180);
            },
            73, 181)
            .packed();
    const int res = 33;
    auto tab = methods::voronoiTable(res, 1, 1);
    Scene s;
    s.height = 1.0;
    s.rotation = 3 * M_PI / 4;
    s.res = 32;
    auto P64 = s.params();
    std::vector<float> P(P64.begin(), P64.end());
    const int N = s.res;
    cl::Buffer bP(rt->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, P.size() * 4, P.data());
    cl::Buffer bl(rt->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, lum.size() * 4, lum.data());
    cl::Buffer bt(rt->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, tab.size() * 4, tab.data());
    cl::Buffer bo(rt->context(), CL_MEM_WRITE_ONLY, N * N * 4);
    cl::Kernel k = rt->kernel("voronoi.cl", "render");
    test::KernelArgs::of(k, methods::family("voronoi"), false)
        .set("P", bP)
        .set("lum", bl)
        .set("out", bo)
        .set("row0", 0)
        .set("tab", bt)
        .set("tres", res)
        .real("plane_eps", 1e-3);
    rt->launch2D(k, N, N).wait();
    std::vector<float> out(N * N);
    rt->queue().enqueueReadBuffer(bo, CL_TRUE, 0, N * N * 4, out.data());
    namespace F = lb::f32;
    F::lb_light L = F::lb_scene_light(P.data());
    for (int r = 0; r < N; ++r)
        for (int c = 0; c < N; ++c) {
            float e = F::lb_voronoi_irradiance(lum.data(), tab.data(), res, L, F::lb_pixel_position(P.data(), r, c),
                                               glm::vec3(0, 0, 1), 1e-3f);
            EXPECT_NEAR(out[r * N + c], e, 1e-4 * std::fabs(e) + 1e-6) << r << " " << c;
        }
}

}  // namespace
