// The shared math run on the device equals the same code run on the host.
#include "kernel_args.h"
#include "math/kmath.h"
#include "scene/scene.h"
#include "testutil.h"

#include <random>

namespace lb {
namespace {

template <class T>
cl::Buffer upload(ocl::Runtime& rt, const std::vector<T>& v)
{
    return cl::Buffer(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, v.size() * sizeof(T),
                      const_cast<T*>(v.data()));
}

template <class T>
std::vector<T> download(ocl::Runtime& rt, cl::Buffer& b, size_t n)
{
    std::vector<T> v(n);
    rt.queue().enqueueReadBuffer(b, CL_TRUE, 0, n * sizeof(T), v.data());
    return v;
}

// Runs selftest.cl:clip_and_measure on random receiver points of the scene at
// h = 0.1, R = 3pi/4, raised to z in [0, 1] so that the horizon cuts the light
// for many of them, and repeats the
// computation with the host copy of the same header in namespace NS.
#define LB_DEFINE_CLIP_COMPARE(FN, NS, T)                                                                     \
    void FN(ocl::Runtime& rt, const std::string& opts, double tol)                                            \
    {                                                                                                         \
        using namespace NS;                                                                                   \
        Scene s;                                                                                              \
        s.height = 0.1;                                                                                       \
        s.rotation = 3 * 3.14159265358979 / 4;                                                                \
        auto P64 = s.params();                                                                                \
        std::vector<T> P(P64.begin(), P64.end());                                                             \
        std::vector<T> q;                                                                                     \
        std::mt19937 g(7);                                                                                    \
        std::uniform_real_distribution<double> U(-2.5, 2.5);                                                  \
        int n = 500;                                                                                          \
        for (int i = 0; i < n; ++i) q.insert(q.end(), {T(U(g)), T(U(g)), T(0.2 * (U(g) + 2.5))});             \
        cl::Buffer bP = upload(rt, P), bq = upload(rt, q);                                                    \
        cl::Buffer bo(rt.context(), CL_MEM_WRITE_ONLY, 4 * n * sizeof(T));                                    \
        cl::Kernel k = rt.kernel("selftest.cl", "clip_and_measure", opts + " " + test::KernelArgs::kArgInfo); \
        test::KernelArgs::reported(k).set("P", bP).set("q", bq).set("out", bo).set("n", n);                   \
        rt.launch1D(k, n, 8).wait();                                                                          \
        auto out = download<T>(rt, bo, 4 * n);                                                                \
        int clipped = 0;                                                                                      \
        for (int i = 0; i < n; ++i) {                                                                         \
            lb_light L = lb_scene_light(P.data());                                                            \
            real3 x(q[3 * i], q[3 * i + 1], q[3 * i + 2]);                                                    \
            real3 p[LB_MAXV];                                                                                 \
            lb_light_corners(L, p);                                                                           \
            for (int c = 0; c < 4; ++c) p[c] -= x;                                                            \
            int m = lb_clip_polygon(p, 4, real3(0, 0, 1), T(0));                                              \
            clipped += (m != 4);                                                                              \
            double sa = lb_polygon_solid_angle(p, m);                                                         \
            double E = lb_polygon_irradiance_lambert(p, m, real3(0, 0, 1));                                   \
            EXPECT_NEAR(out[4 * i], sa, tol*(1 + sa)) << i;                                                   \
            EXPECT_NEAR(out[4 * i + 1], E, tol*(1 + E)) << i;                                                 \
            if (m >= 1) {                                                                                     \
                int where;                                                                                    \
                real3 cp = lb_closest_point_polygon(p, m, L.n, real3(0, 0, 0), &where);                       \
                EXPECT_NEAR(out[4 * i + 2], length(cp), tol*(1 + length(cp))) << i;                           \
                EXPECT_EQ(static_cast<int>(out[4 * i + 3]), where) << i;                                      \
            }                                                                                                 \
        }                                                                                                     \
        EXPECT_GT(clipped, 20);                                                                               \
    }

LB_DEFINE_CLIP_COMPARE(compareClipFloat, lb::f32, float)
LB_DEFINE_CLIP_COMPARE(compareClipDouble, lb::f64, double)

// Tolerances: device and host run the same operations, but OpenCL C may
// contract a*b+c into fma and has its own atan2/sqrt (<= 4 ulp in float), so
// results agree to a few ulp of O(1) quantities, not bit for bit.
TEST(KernelMath, ClipSolidAngleClosestPointFloat)
{
    LB_REQUIRE_RUNTIME(rt);
    compareClipFloat(*rt, "", 2e-6);
}

TEST(KernelMath, ClipSolidAngleClosestPointDouble)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "device has no fp64";
    compareClipDouble(*rt, "-DLB_DOUBLE", 1e-13);
}

TEST(KernelMath, IntensityLookupMatchesHost)
{
    LB_REQUIRE_RUNTIME(rt);
    std::vector<float> lum = {3, 4, 0, 90, 360, 0, 10, 45, 90};
    for (int i = 0; i < 12; ++i) lum.push_back(static_cast<float>((i * 37) % 11));
    std::vector<float> cg;
    std::mt19937 g(3);
    std::uniform_real_distribution<float> C(0, 360), G(-5, 95);
    int n = 256;
    for (int i = 0; i < n; ++i) cg.insert(cg.end(), {C(g), G(g)});
    cl::Buffer bl = upload(*rt, lum), bc = upload(*rt, cg), bo(rt->context(), CL_MEM_WRITE_ONLY, n * 4);
    cl::Kernel k = rt->kernel("selftest.cl", "intensity", test::KernelArgs::kArgInfo);
    test::KernelArgs::reported(k).set("lum", bl).set("cg", bc).set("out", bo).set("n", n);
    rt->launch1D(k, n, 8).wait();
    auto out = download<float>(*rt, bo, n);
    for (int i = 0; i < n; ++i)
        EXPECT_NEAR(out[i], lb::f32::lb_intensity_cg(lum.data(), cg[2 * i], cg[2 * i + 1]), 1e-5) << i;
}

}  // namespace
}  // namespace lb

namespace lb {
namespace {

// Corner versus edge in float, on the device and the host alike: receivers
// whose projection onto the light's plane lies 0.5 m outside an edge and
// 1e-4 of the edge's length before (-> case 1, edge) or beyond (-> case 2,
// vertex) a corner, 2 m in front of the light (no horizon clip). Squared
// distances cannot decide these in float (|x - CP| ~ 2 m: a vertex and an
// edge point closer than 2 sqrt(1.2e-7) = 7e-4 look equal); the linear tests
// of lb_closest_point_polygon must.
TEST(KernelMath, ClosestPointCornerVersusEdgeFloat)
{
    LB_REQUIRE_RUNTIME(rt);
    Scene s;
    s.height = 0.1;
    s.rotation = 3 * M_PI / 4;
    auto P64 = s.params();
    std::vector<float> P(P64.begin(), P64.end());
    auto c = s.corners();
    glm::dvec3 n = s.n();
    std::vector<float> q;
    std::vector<int> expect;
    for (int k = 0; k < 4; ++k)
        for (int side : {-1, 1}) {  // the edge to the previous / next corner
            glm::dvec3 other = c[(k + (side > 0 ? 1 : 3)) % 4];
            glm::dvec3 e = other - c[k];  // along the edge, away from the corner
            glm::dvec3 out = glm::normalize(c[k] - c[(k + 2) % 4]);  // roughly outward at the corner
            glm::dvec3 o = glm::normalize(out - e * (glm::dot(out, e) / glm::dot(e, e)));  // outward normal of the edge
            for (double t : {1e-4, -1e-4}) {
                glm::dvec3 x = c[k] + e * t + o * 0.5 + n * 2.0;
                q.insert(q.end(), {float(x.x), float(x.y), float(x.z)});
                expect.push_back(t > 0 ? 1 : 2);
            }
        }
    int m = static_cast<int>(expect.size());
    cl::Buffer bP = upload(*rt, P), bq = upload(*rt, q);
    cl::Buffer bo(rt->context(), CL_MEM_WRITE_ONLY, 4 * m * sizeof(float));
    cl::Kernel k = rt->kernel("selftest.cl", "clip_and_measure", test::KernelArgs::kArgInfo);
    test::KernelArgs::reported(k).set("P", bP).set("q", bq).set("out", bo).set("n", m);
    rt->launch1D(k, m, 8).wait();
    auto out = download<float>(*rt, bo, 4 * m);
    namespace F = lb::f32;
    F::lb_light L = F::lb_scene_light(P.data());
    for (int i = 0; i < m; ++i) {
        F::real3 p[LB_MAXV];
        F::lb_light_corners(L, p);
        for (int j = 0; j < 4; ++j) p[j] -= F::real3(q[3 * i], q[3 * i + 1], q[3 * i + 2]);
        ASSERT_EQ(F::lb_clip_polygon(p, 4, F::real3(0, 0, 1), 0.0f), 4) << i;
        int where = -1;
        F::lb_closest_point_polygon(p, 4, L.n, F::real3(0, 0, 0), &where);
        EXPECT_EQ(where, expect[i]) << "host, receiver " << i;
        EXPECT_EQ(static_cast<int>(out[4 * i + 3]), expect[i]) << "device, receiver " << i;
    }
}

}  // namespace
}  // namespace lb
