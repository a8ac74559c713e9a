#include "photometry/lut.h"

#include "math/kmath.h"

#include <algorithm>
#include <cmath>

namespace lb::photometry {

namespace {
constexpr double kDeg = 180.0 / M_PI;
}

double pseudoGamma(double gammaDeg)
{
    double g = gammaDeg / kDeg;
    return f64::lb_lut_q(std::sin(g), std::cos(g));
}

double gammaOfPseudo(double q)
{
    // q <= 1: tan(gamma) = t / (1 - t) with t = q; q > 1: mirrored about 90 deg.
    if (q <= 1) return std::atan2(q, 1 - q) * kDeg;
    double t = 2 - q;
    return 180 - std::atan2(t, 1 - t) * kDeg;
}

double pseudoAzimuth(double cDeg)
{
    double c = cDeg / kDeg;
    return f64::lb_lut_a(std::cos(c), std::sin(c));
}

double azimuthOfPseudo(double a)
{
    // Quadrant k, fraction f: C = 90 k + atan2(f, 1 - f).
    double k = std::min(3.0, std::floor(a));
    double f = a - k;
    return 90 * k + std::atan2(f, 1 - f) * kDeg;
}

bool isRotational(const Table& t)
{
    double tol = 1e-9 * std::max(t.maxCd(), 1e-300);
    for (size_t ic = 1; ic < t.nc(); ++ic)
        for (size_t ig = 0; ig < t.ng(); ++ig)
            if (std::fabs(t.at(ic, ig) - t.at(0, ig)) > tol) return false;
    return true;
}

bool emitsNoBack(const Table& t)
{
    for (size_t ic = 0; ic < t.nc(); ++ic)
        for (size_t ig = 0; ig < t.ng(); ++ig)
            if (t.gamma[ig] >= 90 && t.at(ic, ig) != 0) return false;
    return true;
}

Lut buildLut(const Table& t, int ng, int na)
{
    t.validate();
    Lut L;
    L.ng = ng;
    L.na = na;
    L.q0 = pseudoGamma(t.gamma.front());
    L.q1 = pseudoGamma(t.gamma.back());
    L.rotational = isRotational(t);
    // A single measured gamma (degenerate range): one cell of zero width.
    double dq = L.q1 > L.q0 ? L.q1 - L.q0 : 0;
    L.packed.assign(LB_LUT_HEADER + static_cast<size_t>(na + 1) * (ng + 1), 0.0f);
    float* h = L.packed.data();
    const auto exact = t.packed();  // Table::intensity packs per call: once here
    h[0] = static_cast<float>(ng);
    h[1] = static_cast<float>(na);
    h[2] = static_cast<float>(L.q0);
    h[3] = static_cast<float>(L.q1);
    h[4] = dq > 0 ? static_cast<float>(ng / dq) : 0.0f;
    h[5] = static_cast<float>(na / 4.0);
    for (int ia = 0; ia <= na; ++ia) {
        double c = ia == na ? 0.0 : azimuthOfPseudo(4.0 * ia / na);
        for (int ig = 0; ig <= ng; ++ig) {
            // The range's ends exactly at the file's first / last gamma.
            double g = ig == 0 ? t.gamma.front()
                : ig == ng     ? t.gamma.back()
                               : std::clamp(gammaOfPseudo(L.q0 + dq * ig / ng), t.gamma.front(), t.gamma.back());
            h[LB_LUT_HEADER + ia * (ng + 1) + ig] = static_cast<float>(f64::lb_intensity_cg(exact.data(), c, g));
        }
    }
    // Lipschitz constants of the exact lookup (cd per radian).
    double sc = 0, sg = 0;
    for (size_t ic = 0; ic + 1 < t.nc(); ++ic)
        for (size_t ig = 0; ig < t.ng(); ++ig) {
            double d = (t.c[ic + 1] - t.c[ic]) / kDeg;
            if (d > 0) sc = std::max(sc, std::fabs(t.at(ic + 1, ig) - t.at(ic, ig)) / d);
        }
    for (size_t ic = 0; ic < t.nc(); ++ic)
        for (size_t ig = 0; ig + 1 < t.ng(); ++ig) {
            double d = (t.gamma[ig + 1] - t.gamma[ig]) / kDeg;
            if (d > 0) sg = std::max(sg, std::fabs(t.at(ic, ig + 1) - t.at(ic, ig)) / d);
        }
    L.errorBound = sc * 8.0 / na + sg * 2.0 * dq / ng;
    return L;
}

}  // namespace lb::photometry
