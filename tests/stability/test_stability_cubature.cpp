// The stability catalogue through kernels/cubature.cl and kernels/voronoi.cl
// directly, for as long as `cubature` and `voronoi` are not registered methods (then `lumibench stability` covers it
// by itself). Every structural variant the kernel lists, float and double, on
// every non-degenerate case: no non-finite pixel, exactly zero where nothing
// reaches the receiver, the point-light limit in the far field, float within
// 5 % (of the reference's max) of double.
#include "methods/render.h"
#include "methods/voronoi_table.h"
#include "stability/stability.h"
#include "testutil.h"

#include <cmath>
#include <cstdlib>

namespace lb {
namespace {

template <class T>
Image cubatureImage(ocl::Runtime* rt, const Scene& s, const std::vector<float>& lum, const std::string& opts, bool dbl)
{
    auto P64 = s.params();
    std::vector<T> P(P64.begin(), P64.end());
    const int N = s.res;
    cl::Buffer bP(rt->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, P.size() * sizeof(T), P.data());
    cl::Buffer bl(rt->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, lum.size() * 4,
                  const_cast<float*>(lum.data()));
    cl::Buffer bo(rt->context(), CL_MEM_WRITE_ONLY, N * N * sizeof(T));
    cl::Buffer bs(rt->context(), CL_MEM_WRITE_ONLY, 2 * N * N * 4);
    cl::Kernel k = rt->kernel("cubature.cl", "cubature", opts + (dbl ? " -DLB_DOUBLE" : ""));
    k.setArg(0, bP);
    k.setArg(1, bl);
    k.setArg(2, bo);
    k.setArg(3, bs);
    k.setArg(4, 0);
    ocl::setReal(k, 5, 1e-3, dbl);  // plane_eps: the method's default (cubature_options.h)
    ocl::setReal(k, 6, 0.0, dbl);   // horizon_eps
    rt->launch2D(k, N, N).wait();
    std::vector<T> out(N * N);
    rt->queue().enqueueReadBuffer(bo, CL_TRUE, 0, N * N * sizeof(T), out.data());
    Image img(N, N);
    img.px.assign(out.begin(), out.end());
    return img;
}

// kernels/voronoi.cl (thesis 5.1) with a 32 x 32 cell-fraction table.
template <class T>
Image voronoiImage(ocl::Runtime* rt, const Scene& s, const std::vector<float>& lum, bool dbl)
{
    auto P64 = s.params();
    std::vector<T> P(P64.begin(), P64.end());
    const int N = s.res, tres = 32;
    auto tab = methods::voronoiTable(tres, s.width, s.length);
    cl::Buffer bP(rt->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, P.size() * sizeof(T), P.data());
    cl::Buffer bl(rt->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, lum.size() * 4,
                  const_cast<float*>(lum.data()));
    cl::Buffer bt(rt->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, tab.size() * 4, tab.data());
    cl::Buffer bo(rt->context(), CL_MEM_WRITE_ONLY, N * N * sizeof(T));
    cl::Kernel k = rt->kernel("voronoi.cl", "voronoi", dbl ? "-DLB_DOUBLE" : "");
    k.setArg(0, bP);
    k.setArg(1, bl);
    k.setArg(2, bt);
    k.setArg(3, tres);
    k.setArg(4, bo);
    ocl::setReal(k, 5, 1e-3, dbl);
    rt->launch2D(k, N, N).wait();
    std::vector<T> out(N * N);
    rt->queue().enqueueReadBuffer(bo, CL_TRUE, 0, N * N * sizeof(T), out.data());
    Image img(N, N);
    img.px.assign(out.begin(), out.end());
    return img;
}

TEST(StabilityCubature, CatalogueThroughTheKernel)
{
    LB_REQUIRE_RUNTIME(rt);
    // The kernel's @variants: fan/delaunay, the three weightings, the
    // form-factor normalisation, one and four dynamic points; and voronoi.cl.
    const char* variants[] = {"", "-DLB_CUB_TRI=1 -DLB_CUB_WEIGHT=0 -DLB_CUB_NORMALIZE=1",
                              "-DLB_CUB_WEIGHT=2 -DLB_CUB_DYNAMIC=15", "-DLB_CUB_TRI=1 -DLB_CUB_DYNAMIC=9 -DLB_CUB_NORMALIZE=1", "voronoi"};
    methods::RenderOptions ro;
    ro.reps = 1;
    for (auto& c : stability::catalogue()) {
        if (c.expect == stability::Expect::Rejected) continue;
        // Odd: a pixel row at y = 0 in every case. LUMIBENCH_STABILITY_RES
        // (odd) runs it finer by hand; CI keeps 9.
        const char* env = std::getenv("LUMIBENCH_STABILITY_RES");
        Scene s = stability::sceneOf(c, env ? std::atoi(env) : 9);
        auto table = stability::luminaire(c.luminaire);
        auto lum = table.packed();
        Image ref = methods::render(*rt, table, s, methods::parseSpec("reference"), methods::Precision::Double, ro).image;
        double rmax = 0;
        for (double v : ref.px) rmax = std::max(rmax, v);
        for (std::string v : variants) {
            bool vor = v == "voronoi";
            Image d = vor ? voronoiImage<double>(rt, s, lum, true) : cubatureImage<double>(rt, s, lum, v, true);
            Image f = vor ? voronoiImage<float>(rt, s, lum, false) : cubatureImage<float>(rt, s, lum, v, false);
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

} // namespace
} // namespace lb
