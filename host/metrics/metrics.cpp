#include "metrics/metrics.h"

#include "util/error.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lb::metrics {

void checkComparable(const Image& R, const Image& A)
{
    if (R.width != A.width || R.height != A.height)
        throw InputError(
            fmt::format("image sizes differ: reference is {}x{}, test is {}x{}", R.width, R.height, A.width, A.height));
    if (R.px.empty()) throw InputError("images are empty (0 pixels)");
    for (size_t i = 0; i < R.px.size(); ++i)
        if (!std::isfinite(R.px[i]))
            throw InputError(fmt::format("reference pixel (row {}, column {}) is {}: a reference must be finite",
                                         i / R.width, i % R.width, R.px[i]));
}

Metrics compare(const Image& R, const Image& A)
{
    checkComparable(R, A);
    Metrics m;
    m.pixels = static_cast<int64_t>(R.px.size());

    // First pass: the means over the pixels where the test image is finite.
    double sumR = 0, sumA = 0;
    for (size_t i = 0; i < R.px.size(); ++i) {
        if (!std::isfinite(A.px[i])) {
            ++m.nonfinite;
            continue;
        }
        sumR += R.px[i];
        sumA += A.px[i];
    }
    const double n = static_cast<double>(m.pixels - m.nonfinite);  // 0 gives NaN below, on purpose
    m.mean_ref = sumR / n;
    m.mean_test = sumA / n;

    // Second pass: squared errors and the signed extremes of A - R.
    const double relEps = 1e-2 * m.mean_ref * m.mean_ref;
    double sse = 0, rel = 0, maxOver = 0, maxUnder = 0;
    for (size_t i = 0; i < R.px.size(); ++i) {
        if (!std::isfinite(A.px[i])) continue;
        const double d = A.px[i] - R.px[i];
        sse += d * d;
        rel += d * d / (R.px[i] * R.px[i] + relEps);
        maxOver = std::max(maxOver, d);
        maxUnder = std::min(maxUnder, d);
    }
    const double mse = sse / n;
    m.nmse = mse / (m.mean_ref * m.mean_test);
    m.nrmse = std::sqrt(mse) / m.mean_ref;
    m.relmse = rel / n;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    m.ueb = n > 0 ? maxOver : nan;
    m.leb = n > 0 ? maxUnder : nan;

    // Third pass: differences of the neighbouring pairs, right and down.
    double sgd = 0;
    auto pair = [&](size_t i, size_t j) {
        if (!std::isfinite(A.px[i]) || !std::isfinite(A.px[j])) return;
        const double g = (R.px[j] - R.px[i]) - (A.px[j] - A.px[i]);
        sgd += g * g;
        ++m.grad_pairs;
    };
    const size_t w = static_cast<size_t>(R.width), h = static_cast<size_t>(R.height);
    for (size_t y = 0; y < h; ++y)
        for (size_t x = 0; x < w; ++x) {
            if (x + 1 < w) pair(y * w + x, y * w + x + 1);
            if (y + 1 < h) pair(y * w + x, (y + 1) * w + x);
        }
    // No pair (a 1x1 image, or every pair touches a non-finite pixel): NaN, not 0.
    m.grad_nmse = m.grad_pairs > 0 ? sgd / double(m.grad_pairs) / (m.mean_ref * m.mean_test) : nan;
    return m;
}

Metrics pooled(const std::vector<Metrics>& parts)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Metrics o;
    o.ueb = parts.empty() ? nan : 0;
    o.leb = parts.empty() ? nan : 0;
    double p = 0, sr = 0, st = 0, sse = 0, pairs = 0, gsse = 0, fsum = 0, fp = 0;
    for (const auto& m : parts) {
        const double pi = double(m.pixels - m.nonfinite);
        o.pixels += m.pixels;
        o.nonfinite += m.nonfinite;
        o.grad_pairs += m.grad_pairs;
        p += pi;
        sr += pi * m.mean_ref;
        st += pi * m.mean_test;
        sse += m.nmse * pi * m.mean_ref * m.mean_test;
        gsse += m.grad_nmse * double(m.grad_pairs) * m.mean_ref * m.mean_test;
        pairs += double(m.grad_pairs);
        fsum += m.flip * pi;  // NaN in any part: NaN (not available)
        fp += pi;
        o.ueb = std::isnan(m.ueb) ? nan : std::max(o.ueb, m.ueb);
        o.leb = std::isnan(m.leb) ? nan : std::min(o.leb, m.leb);
    }
    o.mean_ref = sr / p;
    o.mean_test = st / p;
    o.nmse = sse / p / (o.mean_ref * o.mean_test);
    o.nrmse = std::sqrt(sse / p) / o.mean_ref;
    o.relmse = nan;
    o.grad_nmse = gsse / pairs / (o.mean_ref * o.mean_test);
    o.flip = fsum / fp;
    return o;
}

const std::vector<std::string>& minimisableMetrics()
{
    static const std::vector<std::string> keys = {"nmse", "nrmse", "relmse", "grad_nmse", "flip", "ueb", "leb"};
    return keys;
}

double minimisable(const Metrics& m, const std::string& key)
{
    if (key == "nmse") return m.nmse;
    if (key == "nrmse") return m.nrmse;
    if (key == "relmse") return m.relmse;
    if (key == "grad_nmse") return m.grad_nmse;
    if (key == "flip") return m.flip;
    if (key == "ueb") return m.ueb;
    if (key == "leb") return -m.leb;
    throw InputError(
        fmt::format("unknown metric '{}' (expected one of {})", key, fmt::join(minimisableMetrics(), ", ")));
}

namespace {
// nlohmann writes NaN and infinity as null; say so explicitly, and read null back as NaN.
nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
double num(const nlohmann::json& j, const char* key)
{
    const auto& v = j.at(key);
    return v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>();
}
// A key that older files do not have: missing reads as NaN.
double newerNum(const nlohmann::json& j, const char* key)
{
    return j.contains(key) ? num(j, key) : std::numeric_limits<double>::quiet_NaN();
}
}  // namespace

void to_json(nlohmann::json& j, const Metrics& m)
{
    j = nlohmann::json{{"nmse", num(m.nmse)},
                       {"nrmse", num(m.nrmse)},
                       {"relmse", num(m.relmse)},
                       {"ueb", num(m.ueb)},
                       {"leb", num(m.leb)},
                       {"nonfinite", m.nonfinite},
                       {"pixels", m.pixels},
                       {"mean_ref", num(m.mean_ref)},
                       {"mean_test", num(m.mean_test)},
                       {"grad_nmse", num(m.grad_nmse)},
                       {"grad_pairs", m.grad_pairs},
                       {"flip", num(m.flip)}};
}

void from_json(const nlohmann::json& j, Metrics& m)
{
    m.nmse = num(j, "nmse");
    m.nrmse = num(j, "nrmse");
    m.relmse = num(j, "relmse");
    m.ueb = num(j, "ueb");
    m.leb = num(j, "leb");
    m.nonfinite = j.at("nonfinite").get<int64_t>();
    m.pixels = j.at("pixels").get<int64_t>();
    m.mean_ref = num(j, "mean_ref");
    m.mean_test = num(j, "mean_test");
    m.grad_nmse = newerNum(j, "grad_nmse");
    m.grad_pairs = j.contains("grad_pairs") ? j.at("grad_pairs").get<int64_t>() : 0;
    m.flip = newerNum(j, "flip");
}

double studentT975(int dof)
{
    // Abramowitz and Stegun, Table 26.10 (97.5 % points).
    static const double t[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                               2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                               2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
    if (dof < 1) throw InputError("studentT975: degrees of freedom must be >= 1");
    if (dof <= 30) return t[dof - 1];
    if (dof <= 40) return 2.042 + (2.021 - 2.042) * (dof - 30) / 10.0;
    if (dof <= 60) return 2.021 + (2.000 - 2.021) * (dof - 40) / 20.0;
    if (dof <= 120) return 2.000 + (1.980 - 2.000) * (dof - 60) / 60.0;
    return 1.960;
}

SeedSummary overSeeds(const std::vector<Metrics>& draws)
{
    if (draws.empty()) throw InputError("overSeeds: no draws");
    static const std::pair<const char*, double Metrics::*> kReal[] = {{"nmse", &Metrics::nmse},
                                                                      {"nrmse", &Metrics::nrmse},
                                                                      {"relmse", &Metrics::relmse},
                                                                      {"ueb", &Metrics::ueb},
                                                                      {"leb", &Metrics::leb},
                                                                      {"mean_test", &Metrics::mean_test},
                                                                      {"grad_nmse", &Metrics::grad_nmse},
                                                                      {"flip", &Metrics::flip}};
    SeedSummary out;
    out.seeds = static_cast<int>(draws.size());
    out.mean = draws[0];
    const double r = static_cast<double>(draws.size());
    for (const auto& [key, field] : kReal) {
        double sum = 0;
        for (const auto& d : draws) sum += d.*field;
        const double mean = sum / r;
        out.mean.*field = mean;
        if (draws.size() < 2 || !std::isfinite(mean)) continue;
        double ss = 0;
        for (const auto& d : draws) ss += (d.*field - mean) * (d.*field - mean);
        const double half = studentT975(out.seeds - 1) * std::sqrt(ss / (r - 1) / r);
        out.ci95[key] = {mean - half, mean + half};
    }
    for (const auto& d : draws) {
        out.mean.nonfinite = std::max(out.mean.nonfinite, d.nonfinite);
        out.mean.grad_pairs = std::min(out.mean.grad_pairs, d.grad_pairs);
    }
    return out;
}

}  // namespace lb::metrics
