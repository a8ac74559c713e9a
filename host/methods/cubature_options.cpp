// cubature_options.cpp -- see cubature_options.h.
#include "methods/cubature_options.h"

#include "util/error.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <sstream>

namespace lb::methods {
namespace {

// Dynamic point names and their bits (kernels/common/cubature.h LB_CUB_*).
struct DynName {
    const char* name;
    int bit;
};
constexpr DynName kDyn[] = {{"cp", 1}, {"np", 2}, {"mrp", 4}, {"barycentre", 8}, {"bary", 8}, {"barycenter", 8}};

int choose(const std::string& key, const std::string& v, std::initializer_list<const char*> names)
{
    int i = 0;
    std::string all;
    for (const char* n : names) {
        if (v == n) return i;
        all += (i ? " | " : "") + std::string(n);
        ++i;
    }
    throw InputError(fmt::format("cubature: {}={} is not one of {}", key, v, all));
}

double nonNegative(const std::string& key, const std::string& v)
{
    size_t used = 0;
    double d = 0;
    try {
        d = std::stod(v, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != v.size() || v.empty() || !std::isfinite(d) || d < 0)
        throw InputError(fmt::format("cubature: {}={} is not a finite number >= 0", key, v));
    return d;
}

}  // namespace

int parseDynamicSet(const std::string& s)
{
    if (s == "none") return 0;
    int mask = 0;
    std::stringstream in(s);
    std::string item;
    while (std::getline(in, item, '+')) {
        int bit = 0;
        for (const auto& d : kDyn)
            if (item == d.name) bit = d.bit;
        if (!bit)
            throw InputError(fmt::format("cubature: dynamic={}: unknown point '{}' (expected cp, np, mrp, "
                                         "barycentre joined by '+', or none)",
                                         s, item));
        mask |= bit;
    }
    if (s.empty()) throw InputError("cubature: dynamic= is empty (use none for corners only)");
    return mask;
}

std::string dynamicSetName(int mask)
{
    std::string out;
    for (int i = 0; i < 4; ++i)
        if (mask & kDyn[i].bit) out += (out.empty() ? "" : "+") + std::string(kDyn[i].name);
    return out.empty() ? "none" : out;
}

CubatureOptions CubatureOptions::parse(const std::map<std::string, std::string>& kv)
{
    CubatureOptions o;
    for (const auto& [k, v] : kv) {
        if (k == "triangulation")
            o.triangulation = choose(k, v, {"fan", "delaunay"});
        else if (k == "weighting")
            o.weighting = choose(k, v, {"sample", "average", "dotout"});
        else if (k == "normalize")
            o.formfactor = choose(k, v, {"none", "formfactor"}) == 1;
        else if (k == "dynamic")
            o.dynamic = parseDynamicSet(v);
        else if (k == "plane_eps")
            o.planeEps = nonNegative(k, v);
        else if (k == "horizon_eps")
            o.horizonEps = nonNegative(k, v);
        else if (k == "corner_inset")
            o.cornerInset = nonNegative(k, v);
        else if (k == "dyn_weight")
            o.dynWeight = nonNegative(k, v);
        else if (k == "blend_dist")
            o.blendDist = nonNegative(k, v);
        else if (k == "lookup")
            o.lut = choose(k, v, {"lut", "exact"}) == 0;
        else if (k == "specialize")
            o.specialize = choose(k, v, {"auto", "none"}) == 0;
        else if (k == "lanes")
            o.lanes = std::array<int, 3>{0, 1, 8}[choose(k, v, {"auto", "1", "8"})];
        else if (k == "area")
            o.area = std::array<int, 3>{0, 2, 3}[choose(k, v, {"none", "gauss2", "gauss3"})];
        else if (k == "area_q")
            o.areaQ = nonNegative(k, v);
        else if (k == "area_sin")
            o.areaSin = nonNegative(k, v);
        else
            throw InputError(
                fmt::format("cubature: unknown parameter '{}' (expected triangulation, weighting, "
                            "normalize, dynamic, plane_eps, horizon_eps, corner_inset, dyn_weight, blend_dist, "
                            "lookup, specialize, lanes, area, area_q, area_sin)",
                            k));
    }
    return o;
}

std::string CubatureOptions::defines() const
{
    return fmt::format("-DLB_CUB_TRI={} -DLB_CUB_WEIGHT={} -DLB_CUB_NORMALIZE={} -DLB_CUB_DYNAMIC={}{}", triangulation,
                       weighting, formfactor ? 1 : 0, dynamic, area ? fmt::format(" -DLB_CUB_AREA={}", area) : "");
}

std::map<std::string, std::string> CubatureOptions::describe() const
{
    const char* tri[] = {"fan", "delaunay"};
    const char* wt[] = {"sample", "average", "dotout"};
    return {{"triangulation", tri[triangulation]},
            {"weighting", wt[weighting]},
            {"normalize", formfactor ? "formfactor" : "none"},
            {"dynamic", dynamicSetName(dynamic)},
            {"plane_eps", fmt::format("{}", planeEps)},
            {"horizon_eps", fmt::format("{}", horizonEps)},
            {"corner_inset", fmt::format("{}", cornerInset)},
            {"dyn_weight", fmt::format("{}", dynWeight)},
            {"blend_dist", fmt::format("{}", blendDist)},
            {"lookup", lut ? "lut" : "exact"},
            {"specialize", specialize ? "auto" : "none"},
            {"lanes", lanes == 0 ? "auto" : std::to_string(lanes)},
            {"area", area == 0 ? "none" : "gauss" + std::to_string(area)},
            {"area_q", fmt::format("{}", areaQ)},
            {"area_sin", fmt::format("{}", areaSin)}};
}

}  // namespace lb::methods
