// ltc.h -- the suite's own LTC table for the GGX BRDF of docs/design.md section 8
// (kernels/common/ltc.h evaluates it): the fit of Heitz et al. 2016, the
// table file and its packing for the kernels.
//
// The fit (Heitz, Dupuy, Hill, Neubelt 2016, their published procedure):
// for each cell of an n x n grid, roughness sqrt(alpha) = i / (n - 1)
// (alpha at least alphaMin) and theta_o = j / (n - 1) * pi / 2 (at most
// thetaMax), the view w_o = (sin theta_o, 0, cos theta_o);
//   1. norm = int f_r cos dw (the directional albedo) by Gauss-Legendre over
//      the half vector (normPanels^2 panels of 8 x 8 nodes, fit.cpp albedoGL)
//      and the lobe's mean direction Z = normalize(int f_r cos w dw) (its y
//      part dropped) by a samples^2 midpoint grid through the VNDF sampler;
//   2. M = [X Y Z] [[m11, 0, m13], [0, m22, 0], [0, 0, 1]], X = (Z_z, 0, -Z_x),
//      Y = (0, 1, 0), the parameters (m11, m22, m13) found by Nelder-Mead
//      (nlopt LN_NELDERMEAD, initial step 0.05) minimising Heitz's error
//        (1/N) sum over both sample sets of |norm D(w) - f_r cos|^3 / (pdf_ltc + pdf_brdf)
//      over an N = samples^2 midpoint grid drawn once from the LTC and once
//      from the BRDF (VNDF here; Heitz drew from D); at theta_o = 0 the lobe
//      is symmetric: m22 = m11, m13 = 0, one parameter;
//   3. warm start as Heitz: roughness from 1 down, theta_o from 0 up; each
//      cell starts from the previous theta_o's parameters, theta_o = 0 from
//      the next rougher cell's.
// Deterministic: fixed grids, no random numbers, one thread.
#pragma once

#include <string>
#include <vector>

namespace lb::ltc {

struct FitOptions {
    int size = 64;  // n: cells per side
    int samples = 32;  // per side of the error's sample grid (Heitz: 32)
    int normPanels = 32;  // per side of the albedo's Gauss-Legendre panels
    double alphaMin = 1e-4;  // alpha of the roughness-0 row
    double thetaMax = 1.57;  // theta_o of the last column (Heitz: 1.57)
    int maxEval = 400;  // Nelder-Mead evaluations per cell at most
    double power = 3;  // exponent of the error |norm D - f_r cos| (Heitz: 3)
};

struct Cell {
    double m00 = 1, m02 = 0, m20 = 0, m22 = 1;  // M^-1 / (M^-1)_11
    double norm = 0;  // int f_r cos dw
    double error = 0;  // Heitz's objective at the fit
    double l1 = 0;  // int |norm D - f_r cos| dw / norm (same samples)
    double m11 = 1, m22p = 1, m13 = 0;  // the fitted parameters (warm start)
};

struct Table {
    FitOptions options;
    std::vector<Cell> cells;  // index j * size + i (i: roughness, j: theta_o)
    const Cell& at(int i, int j) const { return cells[static_cast<size_t>(j) * options.size + i]; }
    double alpha(int i) const;  // alpha of row i
    double theta(int j) const;  // theta_o of column j
};

// The whole fit; `progress` (may be null) is called after each cell.
Table fit(const FitOptions& o, void (*progress)(const Table&, int i, int j, void*) = nullptr, void* user = nullptr);

// One cell's LTC density D(w) (integrates to 1 over the sphere) and the
// directional albedo by the fit's own quadrature (for tests).
double ltcDensity(const Cell& c, double wx, double wy, double wz);
double albedo(double alpha, double theta, int normPanels = 32);

// The table file (JSON, doubles in round-trip precision): written atomically,
// read with clear errors (InputError naming the file and what was expected).
std::string toJson(const Table& t);
void write(const Table& t, const std::string& path);
Table read(const std::string& path);

// The float buffer kernels/common/ltc.h reads: n, then 5 floats per cell.
std::vector<float> packed(const Table& t);

// data/ltc/ggx.json of the source tree, or $LUMIBENCH_DATA_DIR/ltc/ggx.json.
std::string dataDir();
std::string defaultTablePath();
// The default table, read once per process.
const Table& defaultTable();

}  // namespace lb::ltc
