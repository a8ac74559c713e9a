#include "methods/mc_options.h"

#include "methods/registry.h"
#include "methods/specialize.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lb::methods {

namespace {

int domainIndex(const std::string& d)
{
    if (d == "solid") return 1;
    if (d == "projected") return 2;
    if (d == "mis") return 3;
    if (d == "table") return 4;
    if (d == "mis_table") return 5;
    if (d == "mis_table_solid") return 6;
    return 0;
}

int sequenceIndex(const std::string& s)
{
    if (s == "random") return 1;
    if (s == "sobol") return 2;
    if (s == "zsobol") return 3;
    return 0;
}

// The disk light's -D options: area sampling (the shared set mapped onto the
// disk on the host, without a shift) or solid angle over the whole disk
// (common/disk_sample.h; any sequence, the shared set unmapped); the other
// domains and the cosine warp are the rectangle's.
std::string mcDiskDefines(const McOptions& o)
{
    if ((o.domain != "area" && o.domain != "solid") || (o.domain == "area" && o.shift) ||
        (o.domain == "solid" && o.cosineWarp))
        throw InputError(fmt::format("method mc: on a disk light (shape=disk) mc samples domain=area (without "
                                     "shift) or domain=solid (without cosine_warp); got domain={}{}{}",
                                     o.domain, o.shift ? ",shift=1" : "", o.cosineWarp ? ",cosine_warp=1" : ""));
    return o.domain == "solid" || o.sequence != "shared" ? " -DLB_MC_DISK" : "";
}

}  // namespace

bool McOptions::extended() const { return domain != "area" || sequence != "shared" || shift || denoise != "none"; }

int McOptions::projectedOf(int n) const
{
    if (domain != "mis" && domain != "mis_table" && domain != "mis_table_solid") return domain == "projected" ? n : 0;
    return std::clamp(static_cast<int>(std::lround(misSplit * n)), 0, n);
}

McOptions mcOptions(const MethodSpec& s)
{
    McOptions o;
    o.domain = s.str("domain");
    o.sequence = s.str("sequence");
    o.pattern = s.str("pattern");
    o.shift = s.integer("shift") != 0;
    o.cosineWarp = s.integer("cosine_warp") != 0;
    o.minSolid = s.num("min_solid");
    o.misSplit = s.num("mis_split");
    o.denoise = s.str("denoise");
    o.gaussSigma = s.num("gauss_sigma");
    o.gaussRadius = s.integer("gauss_radius");
    if (s.integer("paper") != 0) {
        o.domain = "solid";
        o.sequence = "shared";
        o.pattern = "halton";
        o.shift = true;
        o.minSolid = 1e-3;
    }
    return o;
}

namespace {

// Whether key k of an mc SPEC holds its default value (a canonical SPEC
// writes every key out, so a key at its default overrides nothing).
bool atDefault(const MethodSpec& s, const std::string& k)
{
    for (const auto& p : s.family().params)
        if (p.name == k) return s.values.at(k) == p.canonical("mc", p.def);
    return false;
}

// A key set away from its default where it has no effect is refused, naming
// what would make it act: `active` says whether it acts in this SPEC, whose
// `has` (e.g. "domain=area") decides.
void refuseInert(const MethodSpec& s, const std::string& k, bool active, const std::string& actsWith,
                 const std::string& has)
{
    if (active || atDefault(s, k)) return;
    throw InputError(fmt::format("method mc: {}={} has no effect with {}; it acts only with {}: drop {}= or give {}", k,
                                 s.values.at(k), has, actsWith, k, actsWith));
}

}  // namespace

void validateMc(const MethodSpec& s)
{
    if (s.integer("paper") != 0) {
        for (const char* k : {"domain", "sequence", "pattern", "shift", "min_solid"})
            if (s.given.count(k) && !atDefault(s, k))
                throw InputError(fmt::format("method mc: paper=1 sets {} itself (solid angle, shared Halton points "
                                             "with a per-pixel shift, area sampling below 1e-3 sr); drop {}= or "
                                             "paper=1",
                                             k, k));
    }
    const McOptions o = mcOptions(s);  // paper=1 applied
    const std::string domain = "domain=" + o.domain, sequence = "sequence=" + o.sequence;
    const bool mis = o.domain == "mis" || o.domain == "mis_table" || o.domain == "mis_table_solid";
    refuseInert(s, "cosine_warp", o.domain == "solid", "domain=solid", domain);
    refuseInert(s, "mis_split", mis, "domain=mis, mis_table or mis_table_solid", domain);
    refuseInert(s, "min_solid", o.domain == "solid" || o.domain == "mis_table_solid", "domain=solid or mis_table_solid",
                domain);
    refuseInert(s, "shift", o.sequence == "shared", "sequence=shared", sequence);
    refuseInert(s, "pattern", o.sequence == "shared", "sequence=shared", sequence);
    refuseInert(s, "atrous_sigma", o.denoise == "atrous", "denoise=atrous", "denoise=" + o.denoise);
}

std::string mcDefines(const McOptions& o)
{
    if (!o.extended()) return "";
    std::string d =
        fmt::format(" -DLB_MC_EXT -DLB_MC_DOMAIN={} -DLB_MC_SEQ={}", domainIndex(o.domain), sequenceIndex(o.sequence));
    if (o.shift && o.sequence == "shared") d += " -DLB_MC_SHIFT";
    if (o.cosineWarp && o.domain == "solid") d += " -DLB_MC_WARP";
    if (o.denoise == "atrous") d += " -DLB_MC_VAR";
    return d;
}

bool mcStraight(const McOptions& o, const Scene& scene, bool lut, bool specialize)
{
    const bool domain = o.domain == "area" || o.domain == "solid" || o.domain == "projected" || o.domain == "mis";
    return o.extended() && domain && scene.shape == LightShape::Rect && lut && specialize;
}

int mcLog2(int samples)
{
    int lg = 0;
    while ((1L << lg) < samples) ++lg;
    return lg;
}

std::string mcSceneDefines(const McOptions& o, const Scene& scene, int n)
{
    if (!o.extended()) return "";
    std::string d = scene.shape == LightShape::Disk ? mcDiskDefines(o) : "";
    if (o.domain != "area" && scene.shape != LightShape::Disk) {
        // The sampled domains take the part of the light above the horizon as
        // a rectangle: exact where the horizon cuts along u (every normalized
        // scene). Solid angle and table also work on the whole light
        // (max(0, cos)); projected, mis and mis_table need the clipped polygon.
        if (horizonAlongU(scene))
            d += " -DLB_MC_CLIPV";
        else if (o.domain != "solid" && o.domain != "table" && o.domain != "mis_table_solid")
            throw InputError(fmt::format("method mc: domain={} needs the receiver normal perpendicular to the "
                                         "light's u axis (as in every normalized scene)",
                                         o.domain));
    }
    if (o.sequence == "zsobol") {
        const int bits = 2 * mcLog2(scene.res) + mcLog2(n + 1);
        if (bits > 30)
            throw InputError(fmt::format("method mc: sequence=zsobol at {} pixels per side and n={} needs a {}-bit "
                                         "index, more than 30",
                                         scene.res, n, bits));
    }
    return d;
}

}  // namespace lb::methods
