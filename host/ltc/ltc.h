// ltc.h -- the suite's own LTC table for the GGX BRDF of docs/design.md section 8
// (kernels/common/ltc.h evaluates it): the fit, the table file and its
// packing for the kernels.
//
// The fit (Heitz, Dupuy, Hill, Neubelt 2016's procedure, with the LTC's
// frame free and the L1 distance as the objective by default): for each cell
// of an n x n grid, roughness sqrt(alpha) = i / (n - 1) (alpha at least
// alphaMin) and theta_o = j / (n - 1) * pi / 2 (at most thetaMax), the view
// w_o = (sin theta_o, 0, cos theta_o);
//   1. norm = int f_r cos dw (the directional albedo) by Gauss-Legendre over
//      the half vector (normPanels^2 panels of 8 x 8 nodes, fit.cpp albedoGL)
//      and the lobe's mean direction Z_avg = normalize(int f_r cos w dw) (its
//      y part dropped) by a samples^2 midpoint grid through the VNDF sampler;
//   2. M = [X Y Z] [[m11, 0, m13], [0, m22, 0], [0, 0, 1]], Z = (sin phi, 0,
//      cos phi), X = (cos phi, 0, -sin phi), Y = (0, 1, 0): every M^-1 of the
//      kernels' form (4 numbers up to scale). Frame::Fixed is Heitz's: Z =
//      Z_avg, 3 parameters (m11, m22, m13); Frame::Free fits phi as well (4
//      parameters). The LTC's own horizon is the plane normal to M^-T e_z;
//      with Z pinned to the mean direction it is tilted against the
//      receiver's, mass falls below that and the lobe's back tail is cut. Nelder-Mead (nlopt
//      LN_NELDERMEAD, initial step 0.05) minimises
//        (1/N) sum over both sample sets of |norm D(w) - f_r cos|^p / (pdf_ltc + pdf_brdf)
//      over an N = samples^2 midpoint grid drawn once from the LTC and once
//      from the BRDF (VNDF here; Heitz drew from D): p = 3 (Objective::L3,
//      Heitz's) or p = 1 (Objective::L1: the balance-heuristic estimate of the
//      L1 distance int |norm D - f_r cos| dw, which bounds every polygon's
//      error); at theta_o = 0 the lobe is symmetric: m22 = m11, m13 = 0,
//      phi = 0, one parameter;
//   3. warm start as Heitz: roughness from 1 down, theta_o from 0 up; each
//      cell starts from the previous theta_o's parameters (Frame::Free: its
//      phi turned by the change of the mean direction's angle), theta_o = 0
//      from the next rougher cell's.
// Deterministic: fixed grids, no random numbers, one thread.
#pragma once

#include <string>
#include <vector>

namespace lb::ltc {

enum class Frame { Fixed, Free };
enum class Objective { L3, L1 };

struct FitOptions {
    int size = 64;  // n: cells per side
    int samples = 32;  // per side of the error's sample grid (Heitz: 32)
    int normPanels = 32;  // per side of the albedo's Gauss-Legendre panels
    double alphaMin = 1e-4;  // alpha of the roughness-0 row
    double thetaMax = 1.57;  // theta_o of the last column (Heitz: 1.57)
    int maxEval = 400;  // Nelder-Mead evaluations per cell at most
    Frame frame = Frame::Free;  // Heitz: Fixed
    Objective objective = Objective::L1;  // Heitz: L3
};

struct Cell {
    double m00 = 1, m02 = 0, m20 = 0, m22 = 1;  // M^-1 / (M^-1)_11
    double norm = 0;  // int f_r cos dw
    double error = 0;  // Heitz's objective at the fit
    double l1 = 0;  // int |norm D - f_r cos| dw / norm (same samples)
    double m11 = 1, m22p = 1, m13 = 0, phi = 0;  // the fitted parameters (warm start)
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

// Quality of an LTC c = (m00, m02, m20, m22, norm) (a cell's or an
// interpolated one) at (alpha, theta_o): the L1 distance int |norm D - f_r
// cos| dw / norm over the sphere, estimated independently of the fit's
// samples (balance heuristic over two ns^2 midpoint grids, one through the
// VNDF sampler, one through the LTC's cosine sampling), and the LTC's mass
// below the receiver's horizon, int_{z < 0} D dw (exact: the cosine's mass
// outside M^-1 {z > 0} = {w : (M^T e_z) . w > 0}, (1 - cos b) / 2, b the
// angle between M^T e_z and e_z).
double l1Distance(const double* c, double alpha, double theta, int ns = 64);
double massBelowHorizon(const double* c);
// The LTC the kernels use at (alpha, theta_o): lb_ltc_lookup on packed(t).
void lookup(const std::vector<float>& packedTable, double alpha, double theta, double* c);

// Per alpha and theta_o range, the mean L1 distance (l1Distance) at the
// table's theta_o nodes and at the midpoints between them (the bilinear
// lookup), and the mean mass below the horizon, of `t` and (when given)
// `against` side by side: a Markdown table.
std::string qualitySummary(const Table& t, const Table* against, int ns = 64);

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
