// quality.cpp -- how well a table's LTCs follow the GGX lobe where the
// kernels read them (ltc.h): at the nodes and between them.
#include "ltc/ltc.h"

#include "math/kmath.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lb::ltc {

void lookup(const std::vector<float>& packedTable, double alpha, double theta, double* c)
{
    f64::lb_ltc_lookup(packedTable.data(), alpha, std::cos(theta), c);
}

namespace {

struct RangeQuality {
    double nodes = 0, mids = 0, below = 0;  // means
    double excess = 0;  // largest L1(midpoint) - max(L1 of its two nodes)
};

// Over theta_o in [lo, hi] degrees at alpha: the table's theta_o nodes there
// and the midpoints between two such nodes.
RangeQuality rangeQuality(const Table& t, const std::vector<float>& buf, double alpha, double lo, double hi, int ns)
{
    int n = t.options.size;
    std::vector<int> js;
    for (int j = 0; j < n; ++j) {
        double deg = 90.0 * j / (n - 1);
        if (deg >= lo - 1e-9 && deg <= hi + 1e-9) js.push_back(j);
    }
    RangeQuality q;
    std::vector<double> l1(js.size());
    double c[5];
    for (size_t k = 0; k < js.size(); ++k) {
        lookup(buf, alpha, t.theta(js[k]), c);
        l1[k] = l1Distance(c, alpha, t.theta(js[k]), ns);
        q.nodes += l1[k] / js.size();
        q.below += massBelowHorizon(c) / js.size();
    }
    for (size_t k = 0; k + 1 < js.size(); ++k) {
        double th = 0.5 * (t.theta(js[k]) + t.theta(js[k + 1]));
        lookup(buf, alpha, th, c);
        double mid = l1Distance(c, alpha, th, ns);
        q.mids += mid / (js.size() - 1);
        q.excess = std::max(q.excess, mid - std::max(l1[k], l1[k + 1]));
    }
    return q;
}

}  // namespace

std::string qualitySummary(const Table& t, const Table* against, int ns)
{
    static const double alphas[] = {0.05, 0.1, 0.25, 0.5, 1.0};
    static const double ranges[][2] = {{0, 20}, {29, 46}, {54, 63}, {69, 77}, {83, 90}};
    std::vector<float> a = packed(t), b = against ? packed(*against) : std::vector<float>{};
    std::string s = "| alpha | theta_o (deg) | L1 nodes | L1 midpoints | midpoint excess | mass below horizon |";
    s += against ? " against: L1 nodes | L1 midpoints | midpoint excess | mass below horizon |\n" : "\n";
    s += against ? "|---|---|---|---|---|---|---|---|---|---|\n" : "|---|---|---|---|---|---|\n";
    for (double alpha : alphas)
        for (const auto& r : ranges) {
            RangeQuality q = rangeQuality(t, a, alpha, r[0], r[1], ns);
            s += fmt::format("| {} | {:g}-{:g} | {:.3f} | {:.3f} | {:.3f} | {:.4f} |", alpha, r[0], r[1], q.nodes,
                             q.mids, q.excess, q.below);
            if (against) {
                RangeQuality p = rangeQuality(*against, b, alpha, r[0], r[1], ns);
                s += fmt::format(" {:.3f} | {:.3f} | {:.3f} | {:.4f} |", p.nodes, p.mids, p.excess, p.below);
            }
            s += "\n";
        }
    return s;
}

}  // namespace lb::ltc
