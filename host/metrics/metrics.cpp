#include "metrics/metrics.h"

#include "util/error.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lb::metrics {

Metrics compare(const Image& R, const Image& A)
{
    if (R.width != A.width || R.height != A.height)
        throw InputError(fmt::format("image sizes differ: reference is {}x{}, test is {}x{}", R.width, R.height,
                                     A.width, A.height));
    if (R.px.empty()) throw InputError("images are empty (0 pixels)");
    for (size_t i = 0; i < R.px.size(); ++i)
        if (!std::isfinite(R.px[i]))
            throw InputError(fmt::format("reference pixel (row {}, column {}) is {}: a reference must be finite",
                                         i / R.width, i % R.width, R.px[i]));

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
    return m;
}

namespace {
// nlohmann writes NaN and infinity as null; say so explicitly, and read null back as NaN.
nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
double num(const nlohmann::json& j, const char* key)
{
    const auto& v = j.at(key);
    return v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>();
}
} // namespace

void to_json(nlohmann::json& j, const Metrics& m)
{
    j = nlohmann::json{{"nmse", num(m.nmse)},         {"nrmse", num(m.nrmse)},
                       {"relmse", num(m.relmse)},     {"ueb", num(m.ueb)},
                       {"leb", num(m.leb)},           {"nonfinite", m.nonfinite},
                       {"pixels", m.pixels},          {"mean_ref", num(m.mean_ref)},
                       {"mean_test", num(m.mean_test)}};
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
}

} // namespace lb::metrics
