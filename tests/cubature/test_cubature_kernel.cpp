// kernels/cubature.cl on the device equals the same header run on the host.
#include "kernel_args.h"
#include "math/kmath.h"
#include "methods/cubature_options.h"
#include "methods/registry.h"
#include "photometry/table.h"
#include "scene/scene.h"
#include "testutil.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace lb {
namespace {

// Binds cubature.cl's render arguments by their names (the family's
// Family::args after P, lum, out, row0), statistics on, every tunable at the
// cubature's default (the plain method: no blend, no inset, no static samples).
void bindCubature(cl::Kernel& k, const cl::Buffer& P, const cl::Buffer& lum, const cl::Buffer& out,
                  const cl::Buffer& stats, bool dbl)
{
    auto a = test::KernelArgs::of(k, methods::family("cubature"), dbl);
    a.set("P", P).set("lum", lum).set("out", out).set("row0", 0).set("stats", stats).set("want_stats", 1);
    const auto tun = methods::CubatureOptions().tunables;
#define LB_BIND_DEFAULT(name) a.real(#name, tun.name);
    LB_CUB_TUNABLES(LB_BIND_DEFAULT)
#undef LB_BIND_DEFAULT
}

struct KernelCase {
    const char* opts;
    int tri, wt, ff, dyn;
    // The same variant as the host's lb_cub_options (lb::f32 or lb::f64).
    template <class Options>
    Options options() const
    {
        Options o;
        o.triangulation = tri;
        o.weighting = wt;
        o.formfactor = ff;
        o.dynamic = dyn;
        return o;
    }
};

// Renders a 32 x 32 image of the scene h = 1, R = 3pi/4 with each variant on
// the device (float) and compares with lb::f32 on the host, pixel by pixel.
// Tolerance: OpenCL C may contract to fma and has its own atan2 / sqrt
// (<= 4 ulp), so values agree to ~1e-6 relative, not bit for bit; 1e-4
// relative leaves room for sums of ~10 terms. A triangulation decision made
// differently on the two sides (a sample within rounding of a tolerance band)
// could change a pixel more: at most 1% of the pixels may do so.
// The host side of matchesHost in one precision.
struct HostF32 {
    static lb::f32::lb_light light(const float* P) { return lb::f32::lb_scene_light(P); }
    static float eval(const float* lum, const lb::f32::lb_light& L, const float* P, int r, int c, const KernelCase& kc,
                      int* nt, int* nf)
    {
        return lb::f32::lb_cubature_irradiance(lum, L, lb::f32::lb_pixel_position(P, r, c), glm::vec3(0, 0, 1),
                                               kc.options<lb::f32::lb_cub_options>(),
                                               lb::f32::lb_cub_plain_tunables(1e-3f, 0.0f), nt, nf);
    }
};
struct HostF64 {
    static lb::f64::lb_light light(const double* P) { return lb::f64::lb_scene_light(P); }
    static double eval(const float* lum, const lb::f64::lb_light& L, const double* P, int r, int c,
                       const KernelCase& kc, int* nt, int* nf)
    {
        return lb::f64::lb_cubature_irradiance(lum, L, lb::f64::lb_pixel_position(P, r, c), glm::dvec3(0, 0, 1),
                                               kc.options<lb::f64::lb_cub_options>(),
                                               lb::f64::lb_cub_plain_tunables(1e-3, 0.0), nt, nf);
    }
};

template <class T, class NSL>
void matchesHost(ocl::Runtime* rt, bool dbl, double tol)
{
    auto lum = photometry::tabulate(
                   [](double c, double g) {
                       double gr = g * M_PI / 180, cr = c * M_PI / 180;
                       return 600 + 400 * std::cos(gr) + 150 * std::sin(gr) * std::cos(cr);
                   },
                   73, 181)
                   .packed();
    Scene s;
    s.height = 1.0;
    s.rotation = 3 * M_PI / 4;
    s.res = 32;
    auto P64 = s.params();
    std::vector<T> P(P64.begin(), P64.end());
    const int N = s.res;
    const KernelCase cases[] = {{"", 0, 1, 0, 1},
                                {"-DLB_CUB_TRI=1 -DLB_CUB_WEIGHT=0 -DLB_CUB_NORMALIZE=1", 1, 0, 1, 1},
                                {"-DLB_CUB_TRI=1 -DLB_CUB_WEIGHT=2 -DLB_CUB_DYNAMIC=15", 1, 2, 0, 15}};
    for (const auto& kc : cases) {
        cl::Buffer bP(rt->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, P.size() * sizeof(T), P.data());
        cl::Buffer bl(rt->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, lum.size() * 4, lum.data());
        cl::Buffer bo(rt->context(), CL_MEM_WRITE_ONLY, N * N * sizeof(T));
        cl::Buffer bs(rt->context(), CL_MEM_WRITE_ONLY, 2 * N * N * 4);
        cl::Kernel k = rt->kernel("cubature.cl", "render", std::string(kc.opts) + (dbl ? " -DLB_DOUBLE" : ""));
        bindCubature(k, bP, bl, bo, bs, dbl);
        rt->launch2D(k, N, N).wait();
        std::vector<T> out(N * N);
        std::vector<int> st(2 * N * N);
        rt->queue().enqueueReadBuffer(bo, CL_TRUE, 0, N * N * sizeof(T), out.data());
        rt->queue().enqueueReadBuffer(bs, CL_TRUE, 0, 2 * N * N * 4, st.data());
        auto L = NSL::light(P.data());
        int off = 0;
        for (int r = 0; r < N; ++r)
            for (int c = 0; c < N; ++c) {
                int nt, nf;
                T e = NSL::eval(lum.data(), L, P.data(), r, c, kc, &nt, &nf);
                ASSERT_TRUE(std::isfinite(out[r * N + c])) << kc.opts;
                if (std::fabs(out[r * N + c] - e) > tol * std::fabs(e) + tol * 1e-2 || st[2 * (r * N + c)] != nt) ++off;
            }
        EXPECT_LE(off, N * N / 100) << kc.opts;
        if (off)
            std::printf("[ cubature.cl %s%s ] %d of %d pixels differ from the host\n", kc.opts, dbl ? " double" : "",
                        off, N * N);
    }
}

TEST(CubatureKernel, MatchesHostFloat)
{
    LB_REQUIRE_RUNTIME(rt);
    matchesHost<float, HostF32>(rt, false, 1e-4);
}

// Double: the device's double atan2 / sqrt are within a few ulp: 1e-9.
TEST(CubatureKernel, MatchesHostDouble)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "device has no fp64";
    matchesHost<double, HostF64>(rt, true, 1e-9);
}

}  // namespace
}  // namespace lb

namespace lb {
namespace {

// Device time (median of 5 after a warm-up, docs/design.md section 6), triangles and flips
// per pixel of each variant on a 64 x 64 image of h = 1, R = 3pi/4, printed
// for the record. Asserts only what must hold: every pixel has between 1
// and LB_CUB_MAXT triangles, no more flips than the guard allows, and the fan
// never flips.
TEST(CubatureKernel, TimingsTrianglesFlips)
{
    LB_REQUIRE_RUNTIME(rt);
    auto lum =
        photometry::tabulate([](double, double g) { return g <= 90 ? 1000 * std::cos(g * M_PI / 180) : 0.0; }, 2, 181)
            .packed();
    Scene s;
    s.height = 1.0;
    s.rotation = 3 * M_PI / 4;
    s.res = 64;
    auto P64 = s.params();
    std::vector<float> P(P64.begin(), P64.end());
    const int N = s.res;
    const char* variants[] = {"", "-DLB_CUB_TRI=1", "-DLB_CUB_TRI=1 -DLB_CUB_DYNAMIC=9",
                              "-DLB_CUB_TRI=1 -DLB_CUB_DYNAMIC=15", "-DLB_CUB_DYNAMIC=15"};
    cl::Buffer bP(rt->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, P.size() * 4, P.data());
    cl::Buffer bl(rt->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, lum.size() * 4, lum.data());
    cl::Buffer bo(rt->context(), CL_MEM_WRITE_ONLY, N * N * 4);
    cl::Buffer bs(rt->context(), CL_MEM_WRITE_ONLY, 2 * N * N * 4);
    for (const char* v : variants) {
        cl::Kernel k = rt->kernel("cubature.cl", "render", v);
        bindCubature(k, bP, bl, bo, bs, false);
        auto t = rt->time([&] { return rt->launch2D(k, N, N); }, 5, 1);
        std::vector<int> st(2 * N * N);
        rt->queue().enqueueReadBuffer(bs, CL_TRUE, 0, st.size() * 4, st.data());
        double tris = 0, flips = 0;
        for (int i = 0; i < N * N; ++i) {
            EXPECT_GE(st[2 * i], 1);
            EXPECT_LE(st[2 * i], LB_CUB_MAXT);
            EXPECT_LE(st[2 * i + 1], LB_CUB_MAXFLIPS);
            tris += st[2 * i];
            flips += st[2 * i + 1];
        }
        if (std::string(v).find("TRI=1") == std::string::npos) {
            EXPECT_EQ(flips, 0) << v;
        }
        std::printf("[ cubature.cl %-36s ] %s, %dx%d: median %.3f ms (min %.3f), %.3f triangles/pixel, %.4f "
                    "flips/pixel\n",
                    v[0] ? v : "(default: fan, average, cp)", rt->info().name.c_str(), N, N, t.median_ms, t.min_ms,
                    tris / (N * N), flips / (N * N));
    }
}

}  // namespace
}  // namespace lb
