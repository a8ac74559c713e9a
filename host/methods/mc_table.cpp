#include "methods/mc_table.h"

#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lb::methods {

namespace {

// Strictly ascending float nodes from ascending doubles (nodes that round
// together are merged).
std::vector<float> floatNodes(const std::vector<double>& x)
{
    std::vector<float> f;
    for (double d : x) {
        auto v = static_cast<float>(d);
        if (f.empty() || v > f.back()) f.push_back(v);
    }
    return f;
}

// The cell weights (solid angle x (largest corner intensity + floor)) over
// the C nodes c (radians) and v nodes v, row-major per C cell.
std::vector<double> cellWeights(const photometry::Table& t, const std::vector<float>& c, const std::vector<float>& v)
{
    const size_t nc = c.size() - 1, nv = v.size() - 1;
    const double deg = 180 / M_PI;
    std::vector<double> cd(c.size() * v.size());
    for (size_t i = 0; i < c.size(); ++i)
        for (size_t j = 0; j < v.size(); ++j)
            cd[i * v.size() + j] =
                t.intensity(std::min(360.0, c[i] * deg), std::acos(std::clamp(1.0 - v[j], -1.0, 1.0)) * deg);
    std::vector<double> w(nc * nv);
    double top = 0;
    for (size_t i = 0; i < nc; ++i)
        for (size_t j = 0; j < nv; ++j) {
            const double* a = &cd[i * v.size() + j];
            const double* b = a + v.size();
            w[i * nv + j] = std::max({a[0], a[1], b[0], b[1]});
            top = std::max(top, w[i * nv + j]);
        }
    const double floor = top > 0 ? kMcTableFloor * top : 1;
    for (size_t i = 0; i < nc; ++i)
        for (size_t j = 0; j < nv; ++j)
            w[i * nv + j] = (w[i * nv + j] + floor) * (double(c[i + 1]) - c[i]) * (double(v[j + 1]) - v[j]);
    return w;
}

// Ascending angles (degrees) with every step longer than kMcTableStep split
// evenly.
std::vector<double> refine(const std::vector<double>& x)
{
    std::vector<double> r = {x.front()};
    for (size_t i = 1; i < x.size(); ++i) {
        const int k = std::max(1, static_cast<int>(std::ceil((x[i] - x[i - 1]) / kMcTableStep - 1e-9)));
        for (int j = 1; j <= k; ++j) r.push_back(j == k ? x[i] : x[i - 1] + (x[i] - x[i - 1]) * j / k);
    }
    return r;
}

}  // namespace

std::vector<float> mcTableSampler(const photometry::Table& t)
{
    // C nodes over [0, 2 pi] (the 360 plane as 2 pi), v = 1 - cos(gamma)
    // nodes with 0 and 180 degrees added; the table's steps subdivided to
    // at most kMcTableStep (a rotationally symmetric table has one C step of
    // 360 degrees: its window would be every azimuth)
    std::vector<double> cr, vr;
    for (double c : refine(t.c)) cr.push_back(c * M_PI / 180);
    std::vector<double> g = {0.0};
    for (double x : t.gamma)
        if (x > 0 && x < 180) g.push_back(x);
    g.push_back(180.0);
    for (double x : refine(g)) vr.push_back(2 * std::pow(std::sin(x * M_PI / 360), 2));
    const std::vector<float> c1 = floatNodes(cr), v = floatNodes(vr);
    const std::vector<double> w = cellWeights(t, c1, v);
    const size_t nc1 = c1.size() - 1, nv = v.size() - 1;
    if (2 * nc1 * nv > (size_t{1} << 22))
        throw Error(
            fmt::format("table sampler: {} x {} cells, more than its 2^21 (a coarser table is needed)", nc1, nv));
    // integer weights >= 1, the doubled table's total <= 2^24 (exact in float)
    double sum = 0;
    for (double x : w) sum += x;
    const double scale = (double(1 << 23) - double(nc1 * nv)) / sum;
    std::vector<double> q(w.size());
    for (size_t k = 0; k < w.size(); ++k) q[k] = std::max(1.0, std::ceil(w[k] * scale));
    // the C axis twice: [0, 2 pi] then (2 pi, 4 pi]
    std::vector<float> c = c1;
    for (size_t i = 1; i < c1.size(); ++i) c.push_back(static_cast<float>(2 * M_PI + double(c1[i])));
    const size_t ncn = c.size(), nvn = v.size();
    std::vector<float> tab = {static_cast<float>(ncn), static_cast<float>(nvn)};
    tab.insert(tab.end(), c.begin(), c.end());
    tab.insert(tab.end(), v.begin(), v.end());
    std::vector<double> s(ncn * nvn, 0.0);
    for (size_t i = 1; i < ncn; ++i)
        for (size_t j = 1; j < nvn; ++j)
            s[i * nvn + j] = q[((i - 1) % nc1) * nv + (j - 1)] + s[(i - 1) * nvn + j] + s[i * nvn + j - 1] -
                s[(i - 1) * nvn + j - 1];
    for (double x : s) tab.push_back(static_cast<float>(x));
    return tab;
}

}  // namespace lb::methods
