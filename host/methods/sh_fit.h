// sh_fit.h -- the `sh` method's host side: the luminaire's radiance in real
// spherical harmonics, once per luminaire, and per scene the zonal lobes the
// kernel integrates (kernels/common/sh.h).
//
// The fit (per hemisphere of the light, emission directions d in the light's
// frame (u, v, n_L), mu = |cos gamma|): f_s(d) = sum_lm c_lm Y_lm(d) of degree L
// with f_s(d) mu ~ I(d), i.e. f_s ~ A g, g = I / (A mu) the radiance of
// docs/design.md section 1 times the light's area. Kinds:
//   lsq        weighted least squares of f mu - I over the hemisphere (area
//              weights; the residual carries the cos^2 weight on g's error)
//              with a ridge term ridge * trace / n on the coefficients;
//   projection the projection of the hemisphere's g, mirrored to the whole
//              sphere, onto the SH (g capped at 1 / mu_min: it diverges where
//              I does not vanish at gamma 90 deg);
// and optionally the Hann window cos^2(pi l / (2 (L + 1))) on either.
// The fit's error: sqrt(sum w (f_s mu - I)^2 / sum w I^2) over a 1 x 2 degree
// grid of the whole sphere, each hemisphere by its own fit.
#pragma once

#include "photometry/table.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <array>
#include <string>
#include <vector>

namespace lb::methods {

// Real SH Y_lm(d) (orthonormal on the sphere), l <= L, at index l (l + 1) + m;
// d a unit vector, the pole along z.
std::vector<double> realSh(int L, glm::dvec3 d);

struct ShFitOptions {
    int L = 8;
    std::string kind = "lsq";  // lsq | projection
    double ridge = 1e-7;
    bool hann = false;
};

struct ShFit {
    ShFitOptions opt;
    std::array<std::vector<double>, 2> c;  // front (gamma < 90), back: (L + 1)^2 each
    double error = 0;  // relative L2 of f mu - I over the sphere (above)
    double coefNorm = 0;  // sqrt(sum c^2) / sqrt(sum w I^2 / 4 pi): > 1e3 means cancelling lobes
};

// The fit of table t (cached per table and options: a render asks once per scene).
const ShFit& shFit(const photometry::Table& t, const ShFitOptions& o);

// f_s at the emission direction d (light frame, unit).
double shEval(const ShFit& f, int side, glm::dvec3 d);

// The kernel's buffer for scene sc (kernels/common/sh.h layout, twice: the
// front's then the back's): q_s(u) = f_s(-u) (n_x . u) / A in the world frame,
// degree L + 1, in shBands(L) bands over shDirs(L) Fibonacci directions.
std::vector<double> shLobes(const ShFit& f, const Scene& sc);
inline int shBands(int L) { return L + 2; }
// 2 (L + 1) + 2 directions: one more than band L + 1 needs, because the
// Fibonacci lattice of an odd count 2 N + 1 makes the odd bands' zonal
// functions dependent (measured: singular Gram matrices at every odd N; with
// one more point the smallest Cholesky pivot is >= 8e-3 of the largest to N = 17).
inline int shDirs(int L) { return 2 * L + 4; }

// The zonal lobes of the SH coefficients c (degree N = c's, world frame) over
// the directions w: the kernel's layout for one hemisphere (sh.h).
std::vector<double> shToLobes(const std::vector<double>& c, int N, const std::vector<glm::dvec3>& w);
// The n-point Gauss-Legendre rule on [a, b] (Newton on P_n, to 1e-16).
void gaussLegendre(int n, double a, double b, std::vector<double>& x, std::vector<double>& w);
// nd unit directions, well spread (the Fibonacci lattice).
std::vector<glm::dvec3> fibonacciDirs(int nd);

}  // namespace lb::methods
