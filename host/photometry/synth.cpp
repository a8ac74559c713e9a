#include "photometry/synth.h"

#include "photometry/text.h"
#include "util/error.h"

#include <fmt/format.h>

#include <cmath>
#include <map>

namespace lb::photometry {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

struct Kind {
    std::string what;
    bool exact;
    double (*shape)(double c, double g, double n);  // relative intensity, degrees
    // The measured grid of the non-exact kinds: C planes over 0 .. 360 and
    // gamma angles over 0 .. gammaMax, both uniform.
    int nc = 25, ng = 73;
    double gammaMax = 180;
};

// Angular distance of C planes a, b in degrees (0 .. 180).
double cDistance(double a, double b)
{
    double d = std::fmod(std::fabs(a - b), 360.0);
    return d > 180 ? 360 - d : d;
}

double cosPlus(double g) { return g < 90 ? std::cos(g * kDeg) : 0.0; }
double bump(double x, double mu, double sigma) { return std::exp(-0.5 * (x - mu) * (x - mu) / (sigma * sigma)); }
// 1 below a, 0 above b, smooth in between.
double cutoff(double x, double a, double b)
{
    if (x <= a) return 1;
    if (x >= b) return 0;
    double t = (x - a) / (b - a);
    return 1 - t * t * (3 - 2 * t);
}

const std::map<std::string, Kind>& kinds()
{
    static const std::map<std::string, Kind> k = {
        {"lambert",
         {"Lambertian I0 cos(gamma), exact flux pi I0", true, [](double, double g, double) { return cosPlus(g); }}},
        {"phong",
         {"Phong I0 cos^n(gamma), exact flux 2 pi I0 / (n + 1)", true,
          [](double, double g, double n) { return std::pow(cosPlus(g), n); }}},
        {"spot",
         {"narrow spot (like ARCOS): Gaussian beam sigma 6 deg, nothing at or above 60 deg", false,
          [](double, double g, double) { return bump(g, 0, 6) * cutoff(g, 30, 60); }}},
        {"downlight",
         {"downlight with cut-off (like PANOS): cos^1.5 falling to 0 between 65 and 78 deg", false,
          [](double, double g, double) { return std::pow(cosPlus(g), 1.5) * cutoff(g, 65, 78); }}},
        {"linear",
         {"near-Lambertian linear (like SLOTLIGHT): cos(gamma), narrower along C90", false,
          [](double c, double g, double) {
              double s = std::sin(g * kDeg) * std::sin(c * kDeg);
              return cosPlus(g) * (1 - 0.35 * s * s);
          }}},
        {"diffuse",
         {"near-diffuse (like PERLUCE): 0.55 + 0.45 cos(gamma), emits in the light's plane and above", false,
          [](double c, double g, double) {
              return (0.55 + 0.45 * std::cos(g * kDeg)) * (1 - 0.1 * std::pow(std::sin(c * kDeg), 2));
          }}},
        {"batwing",
         {"batwing (like MIREL): cos^3(gamma) (1 + 3 sin^2(gamma) cos^2 C), peak near 25-30 deg in C0", false,
          [](double c, double g, double) {
              double s = std::sin(g * kDeg), cc = std::cos(c * kDeg);
              return std::pow(cosPlus(g), 3) * (1 + 3 * s * s * cc * cc);
          }}},
        {"sideways",
         {"asymmetric sideways emitter (like INTRO): peak at gamma 60 toward C0, no symmetry", false,
          [](double c, double g, double) {
              double toward = 0.5 + 0.5 * std::cos(c * kDeg);
              double side = 1 + 0.3 * std::sin(c * kDeg);  // breaks the C0-C180 mirror
              return 0.15 * cosPlus(g) + bump(g, 60, 14) * toward * toward * side;
          }}},
        {"updown",
         {"direct/indirect (like LINETIK-S): main peak upward at gamma 140, weaker downward part", false,
          [](double c, double g, double) {
              double cc = std::cos(c * kDeg);
              return 0.35 * cosPlus(g) * (1 - 0.3 * (1 - cc * cc)) + bump(g, 140, 12) * (1 + 0.2 * cc * cc);
          }}},
        // Stress cases (docs/studies/robust.md): emission in the light's own plane, a
        // beam narrower than a degree, no mirror symmetry at all.
        {"grazing",
         {"stress: wall washer, a fan of light in the light's plane (peak at gamma 90, sigma 10 deg) over a "
          "weak cos(gamma) base",
          false,
          [](double c, double g, double) {
              return 0.1 * cosPlus(g) + bump(g, 90, 10) * (0.7 + 0.3 * std::pow(std::cos(c * kDeg), 2));
          }}},
        {"pencil",
         {"stress: pencil spot, Gaussian beam sigma 0.4 deg, measured to gamma 90 deg in 0.05 deg steps", false,
          [](double, double g, double) { return bump(g, 0, 0.4); }, 5, 1801, 90.0}},
        {"quadrant",
         {"stress: quadrant-asymmetric, cos(gamma)^1.5 with a lobe aimed into the quadrant C 0 .. 90 (peak "
          "near C 45, gamma 35), a tenth elsewhere; the lobe fades as sin^2(gamma) towards the axis, so "
          "every C plane agrees at gamma 0",
          false,
          [](double c, double g, double) {
              double s = std::sin(g * kDeg);
              return std::pow(cosPlus(g), 1.5) * (0.1 + 3 * s * s * bump(cDistance(c, 45), 0, 30) * bump(g, 35, 15));
          }}},
    };
    return k;
}

}  // namespace

std::vector<std::string> synthKinds()
{
    std::vector<std::string> v;
    for (const auto& [name, k] : kinds()) v.push_back(name);
    return v;
}

std::string synthDescription(const std::string& kind)
{
    auto it = kinds().find(kind);
    return it == kinds().end() ? "" : it->second.what;
}

Table synth(const std::string& kind, const SynthParams& p)
{
    auto it = kinds().find(kind);
    if (it == kinds().end()) {
        std::string all;
        for (const auto& k : synthKinds()) all += (all.empty() ? "" : ", ") + k;
        throw InputError(fmt::format("luminaire synth: expected a kind ({}), got \"{}\"", all, kind));
    }
    // Up to 1e9 lm (real luminaires: < 1e6 lm), so that the table's candela stay
    // far below photometry::kMaxCandela, which the readers enforce.
    if (!(p.flux > 0 && p.flux <= 1e9))
        throw InputError(fmt::format("luminaire synth: expected flux in (0, 1e9] lm, got {}", p.flux));
    if (!(p.n >= 0 && p.n <= 10000))
        throw InputError(fmt::format("luminaire synth: expected the exponent n in [0, 10000], got {}", p.n));
    const Kind& k = it->second;
    Table t;
    double n = p.n;
    auto shape = k.shape;
    if (k.exact) {
        if (!(p.gammaStep > 0 && p.gammaStep <= 10 && std::abs(90 / p.gammaStep - std::round(90 / p.gammaStep)) < 1e-9))
            throw InputError(
                fmt::format("luminaire synth: expected a gamma step dividing 90 degrees, got {}", p.gammaStep));
        // checked before anything is computed or written: the readers take at most kMaxAngles angles
        if (std::lround(180 / p.gammaStep) + 1 > kMaxAngles)
            throw InputError(fmt::format("luminaire synth: expected a gamma step of at least {:.4g} degrees (at "
                                         "most {} gamma angles, as the readers accept), got {}",
                                         180.0 / (kMaxAngles - 1), kMaxAngles, p.gammaStep));
        // I0 from the closed-form flux: pi I0 (Lambert), 2 pi I0 / (n + 1) (Phong).
        double i0 = kind == "lambert" ? p.flux / kPi : p.flux * (n + 1) / (2 * kPi);
        int ng = static_cast<int>(std::lround(180 / p.gammaStep)) + 1;
        t = tabulate([&](double c, double g) { return i0 * shape(c, g, n); }, 2, ng, 0, 180);
        t.declaredFluxLm = p.flux;  // the closed form, not the table's integral
    } else {
        t = tabulate([&](double c, double g) { return shape(c, g, n); }, k.nc, k.ng, 0, k.gammaMax);
        double f = t.fluxLm();
        for (double& v : t.cd) v *= p.flux / f;
        t.declaredFluxLm = p.flux;
    }
    t.format = "synth";
    t.source = kind;
    t.opening = Opening::rectangle(1.0, 1.0);  // the scene's 1 x 1 m light
    return t;
}

}  // namespace lb::photometry
