#include "photometry/table.h"

#include "math/kmath.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lb::photometry {

void Table::validate() const
{
    auto bad = [&](const std::string& m) {
        throw Error(fmt::format("luminaire table{}: {}", source.empty() ? "" : " of " + source, m));
    };
    if (c.size() < 2) bad("needs at least 2 C planes (0 and 360)");
    if (gamma.size() < 2) bad("needs at least 2 gamma angles");
    if (c.front() != 0.0 || c.back() != 360.0) bad("C must run from 0 to 360");
    for (size_t i = 1; i < c.size(); ++i)
        if (!(c[i] > c[i - 1])) bad("C angles must ascend strictly");
    for (size_t i = 1; i < gamma.size(); ++i)
        if (!(gamma[i] > gamma[i - 1])) bad("gamma angles must ascend strictly");
    if (gamma.front() < 0 || gamma.back() > 180) bad("gamma must lie in [0, 180]");
    if (cd.size() != c.size() * gamma.size()) bad("candela count is not nc * ng");
    for (double v : cd)
        if (!std::isfinite(v) || v < 0) bad("candela values must be finite and >= 0");
}

std::vector<float> Table::packed() const
{
    std::vector<float> p;
    p.reserve(2 + nc() + ng() + cd.size());
    p.push_back(static_cast<float>(nc()));
    p.push_back(static_cast<float>(ng()));
    for (double v : c) p.push_back(static_cast<float>(v));
    for (double v : gamma) p.push_back(static_cast<float>(v));
    for (double v : cd) p.push_back(static_cast<float>(v));
    return p;
}

double Table::intensity(double cDeg, double gammaDeg) const
{
    // The same code the kernels run, on the packed copy (float storage, double
    // math). Packing per call keeps this simple; it is not on any hot path.
    auto p = packed();
    return f64::lb_intensity_cg(p.data(), cDeg, gammaDeg);
}

double Table::maxCd() const { return cd.empty() ? 0.0 : *std::max_element(cd.begin(), cd.end()); }

double Table::fluxLm() const
{
    // Integrate I(C, gamma) sin(gamma) dgamma dC over the measured range with a
    // fine midpoint rule on the interpolated table: within each table cell the
    // integrand is smooth, and 0.25 x 0.1 degree steps make the rule's error
    // < 1e-5 relative for tables of 1-degree spacing or coarser.
    const double dC = 0.25, dG = 0.1, deg = 3.14159265358979323846 / 180.0;
    auto packedT = packed();
    double g0 = gamma.front(), g1 = gamma.back();
    int nG = std::max(1, static_cast<int>(std::ceil((g1 - g0) / dG)));
    double hG = (g1 - g0) / nG;
    int nC = static_cast<int>(360.0 / dC);
    double sum = 0;
    for (int j = 0; j < nG; ++j) {
        double g = g0 + (j + 0.5) * hG;
        double row = 0;
        for (int i = 0; i < nC; ++i) row += f64::lb_intensity_cg(packedT.data(), (i + 0.5) * dC, g);
        sum += row * std::sin(g * deg);
    }
    return sum * (dC * deg) * (hG * deg);
}

Table tabulate(const std::function<double(double, double)>& f, int nc, int ng, double g0, double g1)
{
    Table t;
    t.format = "synth";
    for (int i = 0; i < nc; ++i) t.c.push_back(i == nc - 1 ? 360.0 : 360.0 * i / (nc - 1));
    for (int j = 0; j < ng; ++j) t.gamma.push_back(j == ng - 1 ? g1 : g0 + (g1 - g0) * j / (ng - 1));
    for (int i = 0; i < nc; ++i)
        for (int j = 0; j < ng; ++j) t.cd.push_back(f(t.c[i], t.gamma[j]));
    t.validate();
    return t;
}

}  // namespace lb::photometry
