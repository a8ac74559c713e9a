// The converged reference (kernels/reference.cl) against closed forms.
#include "closed_form.h"
#include "math/kmath.h"
#include "methods/analytic.h"
#include "methods/render.h"
#include "testutil.h"

#include <cmath>

namespace lb {
namespace {

using methods::Precision;

methods::RenderResult renderRef(ocl::Runtime& rt, const photometry::Table& t, const Scene& sc, Precision p,
                                const std::string& spec = "reference")
{
    methods::RenderOptions opt;
    opt.useCache = false;
    return methods::render(rt, t, sc, methods::parseSpec(spec), p, opt);
}

// Lambert's polygon formula (kernels/common/spherical.h) for I = I0 cos(gamma):
// constant radiance I0 / A on the emitting side.
double lambertClosedForm(const Scene& sc, double i0, glm::dvec3 x)
{
    auto P = sc.params();
    f64::lb_light L = f64::lb_scene_light(P.data());
    if (glm::dot(x - L.c, L.n) <= 0) return 0.0;
    f64::real3 p[LB_MAXV];
    int m = f64::lb_clipped_light(L, x, {0, 0, 1}, p);
    return i0 / (sc.width * sc.length) * f64::lb_polygon_irradiance_lambert(p, m, {0, 0, 1});
}

TEST(ClosedForm, CosnOracleMatchesLambertPolygonFormula)
{
    // Two independent closed forms of the same quantity (n = 1): they must
    // agree to the oracle's 1D quadrature tolerance (1e-13) plus rounding.
    Scene sc;
    for (double h : {0.01, 1.1})
        for (double R : {M_PI / 2, 3 * M_PI / 4, M_PI}) {
            sc.height = h;
            sc.rotation = R;
            for (auto x : {glm::dvec3(0.1, 0.2, 0), glm::dvec3(-1.3, -0.4, 0), glm::dvec3(2, 2.3, 0)}) {
                double a = test::cosnIrradiance(sc, 1, 1000, x), b = lambertClosedForm(sc, 1000, x);
                EXPECT_NEAR(a, b, 1e-10 * std::max(b, 1e-3)) << "h=" << h << " R=" << R << " x=" << x.x << "," << x.y;
            }
        }
}

struct RefCase {
    int n;
    Precision p;
    double tol;  // allowed relative error per pixel
};

// Max relative error of the reference image against the cos^n closed form.
void checkScene(ocl::Runtime& rt, const RefCase& c, double h, double R, int res, double* worst)
{
    Scene sc;
    sc.height = h;
    sc.rotation = R;
    sc.res = res;
    // A 0.01-degree table: its bilinear error (analytic.h) is 4e-9 n^2
    // (1 + tan^2 gamma) relative, below 1e-5 for n = 4 up to gamma ~ 88 deg.
    auto table = methods::cosineTable(c.n, 1000.0, false, 0.01);
    auto r = renderRef(rt, table, sc, c.p);
    ASSERT_EQ(r.nonfinite, 0);
    const Image& err = r.extraImages.at("err");
    double emax = 0;
    for (int row = 0; row < res; ++row)
        for (int col = 0; col < res; ++col)
            emax = std::max(emax, test::cosnIrradiance(sc, c.n, 1000.0, sc.pixel(row, col)));
    for (int row = 0; row < res; ++row)
        for (int col = 0; col < res; ++col) {
            double e = test::cosnIrradiance(sc, c.n, 1000.0, sc.pixel(row, col));
            double got = r.image.at(row, col);
            if (e == 0) {
                // Behind the light: the integrand is exactly 0 everywhere.
                EXPECT_EQ(got, 0.0) << "row " << row << " col " << col;
                continue;
            }
            // Pixels that see the light only at grazing angles (E < 1e-6 of
            // the image's peak: cos^n itself is tiny there) test the table's
            // interpolation, not the integration: there only the absolute
            // error is held to 1e-4 x 1e-6 of the peak.
            double rel = std::fabs(got - e) / std::max(e, 1e-6 * emax);
            *worst = std::max(*worst, rel);
            EXPECT_LE(rel, c.tol) << "n=" << c.n << " h=" << h << " R=" << R << " px " << row << "," << col << " got "
                                  << got << " want " << e << " est " << err.at(row, col);
        }
}

TEST(Reference, DoubleMatchesClosedFormsNearMidFar)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "no fp64";
    // docs/design.md: <= 1e-4 relative per pixel in double. The kernel aims
    // at its default tol = 1e-5; the table's own error is < 1e-5 where it
    // matters (see checkScene): 1e-4 leaves a margin of 5.
    double worst = 0;
    for (int n : {1, 4})
        for (double h : {0.01, 0.1, 1.1, 5.1})
            for (double R : {M_PI / 2, 5 * M_PI / 8, 3 * M_PI / 4, M_PI})
                checkScene(*rt, {n, Precision::Double, 1e-4}, h, R, 12, &worst);
    std::printf("reference double: worst relative error %.3g\n", worst);
}

TEST(Reference, FloatMatchesClosedForms)
{
    LB_REQUIRE_RUNTIME(rt);
    // Float: each of the ~10^3 integrand values carries ~1e-7 relative
    // rounding (more in the 1/r^3 near the light), summed over the cells; 1e-3
    // is what a float reference can promise, and the test shows it holds.
    double worst = 0;
    for (double h : {0.01, 0.1, 2.5})
        for (double R : {M_PI / 2, 3 * M_PI / 4, M_PI}) checkScene(*rt, {1, Precision::Float, 1e-3}, h, R, 12, &worst);
    std::printf("reference float: worst relative error %.3g\n", worst);
}

TEST(Reference, ErrorEstimateIsSmallAndHonest)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "no fp64";
    // Near field, a peaked integrand: the estimate must stay below the
    // requested 1e-6 relative (the loop stops there unless the budget ends)
    // and the true error must stay within twice the estimate (it estimates
    // the coarser rule's error; measured ratio up to 1.2 at h = 0.01) plus the
    // table's interpolation error (3.8e-9 relative for n = 1 at 0.01 deg,
    // analytic.h) -- an estimate that claims convergence it does not have
    // fails here.
    Scene sc;
    sc.height = 0.01;
    sc.rotation = M_PI / 2;
    sc.res = 12;
    auto table = methods::cosineTable(1, 1000.0, false, 0.01);
    auto r = renderRef(*rt, table, sc, Precision::Double, "reference:tol=1e-6");
    EXPECT_EQ(r.stats.at("pixels_at_budget").get<long>(), 0);
    const Image& err = r.extraImages.at("err");
    for (int row = 0; row < sc.res; ++row)
        for (int col = 0; col < sc.res; ++col) {
            double e = test::cosnIrradiance(sc, 1, 1000.0, sc.pixel(row, col));
            if (e == 0) continue;
            EXPECT_LE(err.at(row, col), 1e-6 * e * 1.0000001);
            EXPECT_LE(std::fabs(r.image.at(row, col) - e), 2 * err.at(row, col) + 1e-8 * e);
        }
}

}  // namespace
}  // namespace lb

namespace lb {
namespace {

// Not part of the suite (minutes of CPU): the 512^2 timing and accuracy the
// issue asks to report. Run with --gtest_also_run_disabled_tests
// --gtest_filter=*Report512*.
TEST(Reference, DISABLED_Report512)
{
    LB_REQUIRE_RUNTIME(rt);
    for (int n : {1, 4})
        for (double R : {M_PI, 3 * M_PI / 4}) {
            Scene sc;
            sc.height = 0.1;
            sc.rotation = R;
            sc.res = 512;
            auto table = methods::cosineTable(n, 1000.0, false, 0.01);
            methods::RenderOptions opt;
            opt.useCache = false;
            auto r = methods::render(*rt, table, sc, methods::parseSpec("reference"), methods::Precision::Double, opt);
            double emax = 0, worst = 0, worstAll = 0;
            std::vector<double> e(r.image.px.size());
            for (int row = 0; row < sc.res; ++row)
                for (int col = 0; col < sc.res; ++col) {
                    e[row * sc.res + col] = test::cosnIrradiance(sc, n, 1000.0, sc.pixel(row, col));
                    emax = std::max(emax, e[row * sc.res + col]);
                }
            for (size_t i = 0; i < e.size(); ++i) {
                if (e[i] == 0) continue;
                double d = std::fabs(r.image.px[i] - e[i]);
                worstAll = std::max(worstAll, d / e[i]);
                worst = std::max(worst, d / std::max(e[i], 1e-6 * emax));
            }
            std::printf(
                "512^2 h=0.1 R=%.4f cos^%d: %.2f s, splits %ld, worst rel %.3g (E >= 1e-6 peak), %.3g (all lit)\n", R,
                n, r.timing.median_ms / 1e3, r.stats.at("splits_total").get<long>(), worst, worstAll);
        }
}

}  // namespace
}  // namespace lb

namespace lb {
namespace {

TEST(Reference, KinkedTableConvergesWithinBudget)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!rt->fp64()) GTEST_SKIP() << "no fp64";
    // A coarse table (10-degree gamma, 30-degree C steps, C-dependent): the
    // bilinear integrand has derivative jumps along curves on the light. The
    // global worst-cell-first refinement must still reach the requested 1e-5
    // on every pixel within the split budget (near field, tilted light).
    const double d = M_PI / 180;
    auto t = photometry::tabulate(
        [&](double c, double g) { return 600 + 400 * std::cos(g * d) * (1 + 0.5 * std::cos(2 * c * d)); }, 13, 19);
    Scene sc;
    sc.height = 0.1;
    sc.rotation = 3 * M_PI / 4;
    sc.res = 8;
    auto r = renderRef(*rt, t, sc, Precision::Double, "reference:tol=1e-5");
    EXPECT_EQ(r.stats.at("pixels_at_budget").get<long>(), 0);
    const Image& err = r.extraImages.at("err");
    for (size_t i = 0; i < err.px.size(); ++i) EXPECT_LE(err.px[i], 1e-5 * r.image.px[i] * 1.0000001) << i;
    std::printf("kinked table: splits max %d, total %ld\n", r.stats.at("splits_max").get<int>(),
                r.stats.at("splits_total").get<long>());
}

}  // namespace
}  // namespace lb
