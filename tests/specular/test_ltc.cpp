// The LTC of kernels/common/ltc.h: the polygon integral against brute force,
// the fitted table against the BRDF, and `ltc fit` reproducing the committed
// tables.
#include "ltc/ltc.h"
#include "math/kmath.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <random>

namespace lb {
namespace {

const double x8[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                      0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
const double w8[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                      0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

// int over the planar polygon {a + s e1 + t e2 (parallelogram) or a + s e1 +
// s t (e2 - e1) (triangle, Duffy)} of g(w) dw, dw = |n . p| / |p|^3 dA, by
// composite 8-point Gauss-Legendre on `panels`^2 panels of [0,1]^2.
double polygonIntegral(glm::dvec3 a, glm::dvec3 e1, glm::dvec3 e2, bool triangle, int panels,
                       const std::function<double(glm::dvec3)>& g)
{
    glm::dvec3 nA = glm::cross(e1, e2);  // |nA| = parallelogram area
    double sum = 0;
    for (int ps = 0; ps < panels; ++ps)
        for (int is = 0; is < 8; ++is) {
            double s = (ps + 0.5 + 0.5 * x8[is]) / panels, ws = 0.5 * w8[is] / panels;
            for (int pt = 0; pt < panels; ++pt)
                for (int it = 0; it < 8; ++it) {
                    double t = (pt + 0.5 + 0.5 * x8[it]) / panels, wt = 0.5 * w8[it] / panels;
                    glm::dvec3 p = triangle ? a + s * e1 + s * t * (e2 - e1) : a + s * e1 + t * e2;
                    double jac = triangle ? s : 1.0;
                    double r = glm::length(p);
                    sum += ws * wt * jac * std::fabs(glm::dot(nA, p)) / (r * r * r) * g(p / r);
                }
        }
    return sum;
}

struct Poly {
    glm::dvec3 a, e1, e2;
    bool triangle;
    int n() const { return triangle ? 3 : 4; }
    void vertices(f64::real3* p) const
    {
        p[0] = a;
        p[1] = a + e1;
        p[2] = a + e1 + (triangle ? e2 - e1 : e2);
        p[3] = a + e2;
    }
};

// Random triangles and parallelograms of size ~0.3..1.5 at distance ~1, in
// random orientations; a third cross the horizon z = 0.
Poly randomPoly(std::mt19937_64& g)
{
    std::uniform_real_distribution<double> u(-1, 1);
    glm::dvec3 c(u(g), u(g), 0.2 + 0.9 * (u(g) + 1) / 2);
    if (u(g) < -0.33) c.z = 0.15 * u(g);
    glm::dvec3 e1(u(g), u(g), u(g)), e2(u(g), u(g), u(g));
    double s = 0.3 + 0.6 * (u(g) + 1);
    e1 *= s / glm::length(e1);
    e2 *= s / glm::length(e2);
    Poly p{c - 0.5 * (e1 + e2), e1, e2, u(g) < 0};
    return p;
}

// The LTC density of an inverse matrix (m00, m02, m20, m22), as ltc.h defines it.
double ltcD(const double* m, glm::dvec3 w)
{
    glm::dvec3 o(m[0] * w.x + m[1] * w.z, w.y, m[2] * w.x + m[3] * w.z);
    double det = std::fabs(m[0] * m[3] - m[1] * m[2]);
    double l = glm::length(o);
    return std::max(0.0, o.z / l) / M_PI * det / (l * l * l);
}

TEST(Ltc, PolygonIntegralIsTheTransformedCosineIntegral)
{
    // Exact identity, no fit involved: lb_ltc_polygon (transform, clip at the
    // cosine's horizon, Lambert's formula) equals the integral of the LTC
    // density D over the polygon. The brute force (composite GL, 48^2 panels
    // x 64 nodes) has an error from the kink of max(0, z) where the clipped
    // part starts, O(h^2) of the derivative jump: measured < 2e-6 absolute on
    // integrals in [0, 1]; asserted 2e-5. Matrices: from the committed-size
    // range (m00, m22 in [0.05, 2], |m02|, |m20| <= 1).
    std::mt19937_64 g(11);
    std::uniform_real_distribution<double> u(0, 1);
    for (int k = 0; k < 40; ++k) {
        Poly P = randomPoly(g);
        double m[4] = {0.05 + 1.95 * u(g), 2 * u(g) - 1, 2 * u(g) - 1, 0.05 + 1.95 * u(g)};
        if (m[0] * m[3] - m[1] * m[2] <= 0.05) m[1] = m[2] = 0;
        f64::real3 v[LB_MAXV];
        P.vertices(v);
        double got = f64::lb_ltc_polygon(v, P.n(), m[0], m[1], m[2], m[3]);
        double want = polygonIntegral(P.a, P.e1, P.e2, P.triangle, 48, [&](glm::dvec3 w) { return ltcD(m, w); });
        EXPECT_NEAR(got, want, 2e-5) << "case " << k;
        EXPECT_GE(got, 0.0);
        EXPECT_LE(got, 1.0);
    }
}

TEST(Ltc, LookupIsExactAtNodesAndBilinearBetween)
{
    const ltc::Table& t = ltc::defaultTable();
    std::vector<float> buf = ltc::packed(t);
    int n = t.options.size;
    for (int i : {8, 20, n - 1})
        for (int j : {0, 17, n - 2}) {
            double a = double(i) / (n - 1);
            double c[5];
            f64::lb_ltc_lookup(buf.data(), a * a, std::cos(double(j) / (n - 1) * M_PI / 2), c);
            const ltc::Cell& cell = t.at(i, j);
            EXPECT_NEAR(c[0], float(cell.m00), 1e-5 * std::fabs(cell.m00) + 1e-6);
            EXPECT_NEAR(c[4], float(cell.norm), 1e-6);
        }
}

// int over the whole sphere of |norm D - f_r cos| for the LTC at (alpha,
// theta) as the kernels interpolate it: the bound of any polygon's error.
// Balance-heuristic estimate from two 256^2 midpoint grids, one through the
// VNDF sampler, one through the LTC's own cosine sampling.
double l1Bound(const double* c, double alpha, double theta)
{
    glm::dvec3 V(std::sin(theta), 0, std::cos(theta));
    glm::dmat3 inv(glm::dvec3(c[0], 0, c[2]), glm::dvec3(0, 1, 0), glm::dvec3(c[1], 0, c[3]));  // columns
    glm::dmat3 M = glm::inverse(inv);
    auto fcos = [&](glm::dvec3 L) { return f64::lb_ggx_brdf_cos(L.x, L.y, L.z, V.x, V.y, V.z, alpha); };
    auto pb = [&](glm::dvec3 L) { return f64::lb_ggx_vndf_pdf(L.x, L.y, L.z, V.x, V.y, V.z, alpha); };
    const int ns = 256;
    double sum = 0;
    for (int j = 0; j < ns; ++j)
        for (int i = 0; i < ns; ++i) {
            double u1 = (i + 0.5) / ns, u2 = (j + 0.5) / ns;
            glm::dvec3 m = f64::lb_ggx_sample_vndf(V.x, V.y, V.z, alpha, u1, u2);
            glm::dvec3 L1 = 2 * glm::dot(V, m) * m - V;
            double ct = std::sqrt(u1), st = std::sqrt(1 - u1), phi = 2 * M_PI * u2;
            glm::dvec3 L2 = glm::normalize(M * glm::dvec3(st * std::cos(phi), st * std::sin(phi), ct));
            for (glm::dvec3 L : {L1, L2}) {
                double d = ltcD(c, L), p = d + pb(L);
                if (p > 0) sum += std::fabs(c[4] * d - fcos(L)) / p;
            }
        }
    return sum / (double(ns) * ns);
}

TEST(Ltc, PolygonErrorWithinTheFitsL1Distance)
{
    // |norm int_P D - int_P f_r cos| <= int_S2 |norm D - f_r cos| =: B(alpha,
    // theta_o) for every polygon P: the derived tolerance. B is computed here
    // for the interpolated LTC the kernels use (a 256^2 two-sampler estimate,
    // ~1 % accurate: asserted against 1.1 B), plus the brute force's own error
    // (GL on 64^2 panels: resolves lobes of alpha >= 0.05 to < 1e-5 of the
    // polygon integrals; 1e-4 added).
    const ltc::Table& t = ltc::defaultTable();
    std::vector<float> buf = ltc::packed(t);
    std::mt19937_64 g(5);
    std::uniform_real_distribution<double> u(0, 1);
    int k = 0;
    for (double alpha : {0.05, 0.1, 0.3, 0.6, 1.0})
        for (double theta : {0.1, 0.7, 1.2, 1.45}) {
            double c[5];
            f64::lb_ltc_lookup(buf.data(), alpha, std::cos(theta), c);
            double B = l1Bound(c, alpha, theta);
            // the fit is a fit up to 70 degrees (L1 < 0.5 norm); towards grazing
            // the horizon cuts the GGX lobe, which no LTC follows (L1 -> norm)
            if (theta < 1.25) {
                EXPECT_LT(B, 0.5 * c[4]) << "alpha " << alpha << " theta " << theta;
            }
            for (int r = 0; r < 3; ++r, ++k) {
                Poly P = randomPoly(g);
                // aim a third of them at the specular lobe
                if (r == 0) P.a += glm::dvec3(-std::sin(theta), 0, std::cos(theta)) - (P.a + 0.5 * (P.e1 + P.e2));
                double phi = 2 * M_PI * u(g);  // view azimuth: the world frame is rotated
                glm::dvec3 wo(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
                glm::dmat3 rot(glm::dvec3(std::cos(phi), std::sin(phi), 0),
                               glm::dvec3(-std::sin(phi), std::cos(phi), 0), glm::dvec3(0, 0, 1));
                Poly W{rot * P.a, rot * P.e1, rot * P.e2, P.triangle};
                f64::real3 v[LB_MAXV];
                W.vertices(v);
                double got = f64::lb_ltc_brdf_polygon(buf.data(), v, W.n(), {0, 0, 1}, wo, alpha);
                double want = polygonIntegral(W.a, W.e1, W.e2, W.triangle, 64, [&](glm::dvec3 w) {
                    return f64::lb_ggx_brdf_cos(w.x, w.y, w.z, wo.x, wo.y, wo.z, alpha);
                });
                EXPECT_LE(std::fabs(got - want), 1.1 * B + 1e-4)
                    << "alpha " << alpha << " theta " << theta << " case " << k << " got " << got << " want " << want;
            }
        }
}

TEST(Ltc, FitReproducesTheCommittedSmallTable)
{
    // `lumibench ltc fit --size 8` is deterministic: the same cells, bit for
    // bit, as data/ltc/ggx-8.json (regenerate both with scripts in
    // data/ltc/README.md when the fit changes).
    std::string path = ltc::dataDir() + "/ltc/ggx-8.json";
    ltc::Table ref = ltc::read(path);
    ltc::Table t = ltc::fit(ref.options);
    ASSERT_EQ(t.cells.size(), ref.cells.size());
    for (size_t k = 0; k < t.cells.size(); ++k) {
        EXPECT_EQ(t.cells[k].m00, ref.cells[k].m00) << k;
        EXPECT_EQ(t.cells[k].m02, ref.cells[k].m02) << k;
        EXPECT_EQ(t.cells[k].m20, ref.cells[k].m20) << k;
        EXPECT_EQ(t.cells[k].m22, ref.cells[k].m22) << k;
        EXPECT_EQ(t.cells[k].norm, ref.cells[k].norm) << k;
    }
}

}  // namespace
}  // namespace lb

namespace lb {
namespace {

TEST(Ltc, SmallTableNodesAreTheCommittedTablesNodes)
{
    // The 8 x 8 grid's nodes are every 9th node of the 64 x 64 grid (i / 7 =
    // 9 i / 63): the same alpha and theta_o up to rounding, so the same albedo
    // (the quadrature is not warm-started: 1e-12); the matrices come from
    // other warm starts, so they are compared through the LTC's density at the
    // lobe's mirror direction: Nelder-Mead lands on the same minimum from both
    // (measured 8e-5 relative up to theta_o = 1 rad); asserted 1e-3.
    const ltc::Table& big = ltc::defaultTable();
    ltc::Table small = ltc::read(ltc::dataDir() + "/ltc/ggx-8.json");
    ASSERT_EQ(big.options.size, 64);
    ASSERT_EQ(small.options.size, 8);
    for (int i = 1; i < 8; ++i)
        for (int j = 0; j < 7; ++j) {
            const ltc::Cell &a = small.at(i, j), &b = big.at(9 * i, 9 * j);
            EXPECT_NEAR(a.norm, b.norm, 1e-12) << i << "," << j;
            double th = small.theta(j);
            glm::dvec3 mirror(-std::sin(th), 0, std::cos(th));
            double da = ltc::ltcDensity(a, mirror.x, mirror.y, mirror.z);
            double db = ltc::ltcDensity(b, mirror.x, mirror.y, mirror.z);
            if (th < 1.0) {
                EXPECT_NEAR(da, db, 1e-3 * db) << i << "," << j;
            }
        }
}

}  // namespace
}  // namespace lb
