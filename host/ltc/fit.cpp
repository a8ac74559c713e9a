// fit.cpp -- the LTC fit of ltc.h (Heitz et al. 2016's procedure).
#include "ltc/ltc.h"

#include "math/kmath.h"
#include "util/error.h"

#include <fmt/format.h>
#include <nlopt.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace lb::ltc {
namespace {

using V3 = std::array<double, 3>;
using M3 = std::array<std::array<double, 3>, 3>;  // [row][col]

V3 mul(const M3& m, const V3& v)
{
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

double det(const M3& m)
{
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
        m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

M3 inverse(const M3& m)
{
    double d = det(m);
    M3 r;
    r[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / d;
    r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / d;
    r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / d;
    r[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / d;
    r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / d;
    r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / d;
    r[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / d;
    r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / d;
    r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / d;
    return r;
}

V3 normalized(V3 v)
{
    double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {v[0] / l, v[1] / l, v[2] / l};
}

// One LTC during the fit: M = [X Y Z] diag-like(m11, m22, m13).
struct Ltc {
    V3 X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1};
    double m11 = 1, m22 = 1, m13 = 0;
    M3 M{}, invM{};
    double detInv = 1;
    void update()
    {
        M3 B{{{X[0], Y[0], Z[0]}, {X[1], Y[1], Z[1]}, {X[2], Y[2], Z[2]}}};
        M3 S{{{m11, 0, m13}, {0, m22, 0}, {0, 0, 1}}};
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) M[r][c] = B[r][0] * S[0][c] + B[r][1] * S[1][c] + B[r][2] * S[2][c];
        invM = inverse(M);
        detInv = std::fabs(det(invM));
    }
    // D(w), w unit: integrates to 1.
    double eval(const V3& w) const
    {
        V3 o = mul(invM, w);
        double l = std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
        return std::max(0.0, o[2] / l) / M_PI * detInv / (l * l * l);
    }
    V3 sample(double u1, double u2) const
    {
        double ct = std::sqrt(u1), st = std::sqrt(std::max(0.0, 1 - u1)), phi = 2 * M_PI * u2;
        return normalized(mul(M, V3{st * std::cos(phi), st * std::sin(phi), ct}));
    }
};

// The LTC of the kernels' M^-1 = [[m[0], 0, m[1]], [0, 1, 0], [m[2], 0, m[3]]].
Ltc fromInverse(const double* m)
{
    Ltc l;
    l.invM = M3{{{m[0], 0, m[1]}, {0, 1, 0}, {m[2], 0, m[3]}}};
    l.M = inverse(l.invM);
    l.detInv = std::fabs(det(l.invM));
    return l;
}

// The BRDF side: f_r cos and the VNDF sampler of kernels/common/ggx.h.
struct Brdf {
    V3 V;
    double alpha;
    double fcos(const V3& L) const { return f64::lb_ggx_brdf_cos(L[0], L[1], L[2], V[0], V[1], V[2], alpha); }
    double pdf(const V3& L) const { return f64::lb_ggx_vndf_pdf(L[0], L[1], L[2], V[0], V[1], V[2], alpha); }
    V3 sample(double u1, double u2) const
    {
        const f64::real3 m = f64::lb_ggx_sample_vndf(V[0], V[1], V[2], alpha, u1, u2);
        const double mx = m.x, my = m.y, mz = m.z;
        double d = V[0] * mx + V[1] * my + V[2] * mz;
        return {2 * d * mx - V[0], 2 * d * my - V[1], 2 * d * mz - V[2]};
    }
};

// The mean direction by an ns^2 midpoint grid through the VNDF sampler
// (f cos / pdf = G2 / G1(w_o) per sample), Heitz's averageDir.
V3 averageDirection(const Brdf& b, int ns)
{
    V3 d{0, 0, 0};
    for (int j = 0; j < ns; ++j)
        for (int i = 0; i < ns; ++i) {
            V3 L = b.sample((i + 0.5) / ns, (j + 0.5) / ns);
            double p = b.pdf(L);
            if (!(p > 0)) continue;
            double w = b.fcos(L) / p;
            for (int k = 0; k < 3; ++k) d[k] += w * L[k];
        }
    d[1] = 0;
    return normalized(d);
}

// norm = int f_r cos dw_i over the half vector (dw_i = 4 (w_o . h) dw_h), the
// lobe unrolled by tan theta_h = alpha tan psi (dtheta_h = alpha sec^2 psi
// cos^2 theta_h dpsi), psi in [0, pi/2); for each theta_h the azimuths with
// w_i above the horizon, |phi| <= phimax, exactly, so that the one kink (G2 ->
// 0 at the horizon) is at an interval's end. Composite 8-point Gauss-Legendre
// on `panels` x `panels` panels. A midpoint grid through the sampler misses
// the lobe's tail beyond the horizon (alpha^2 of the mass at normal view:
// 4e-4 at alpha = 0.02 on a 256^2 grid).
double albedoGL(const Brdf& b, int panels)
{
    static const double x8[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                 0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
    static const double w8[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                 0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    const V3& V = b.V;
    double a = b.alpha, so = V[0], co = V[2];
    double sum = 0;
    // psi split where phimax leaves pi (theta_h = pi/4 - theta_o/2) and reaches
    // 0 (theta_h = pi/4 + theta_o/2): the inner range's kinks, as nodes
    double thetaO = std::acos(co);
    double cuts[4] = {0, std::atan(std::tan(std::max(0.0, M_PI / 4 - thetaO / 2)) / a),
                      std::atan(std::tan(std::min(M_PI / 2 - 1e-12, M_PI / 4 + thetaO / 2)) / a), M_PI / 2};
    for (int seg = 0; seg < 3; ++seg)
        for (int pv = 0; pv < panels; ++pv)
            for (int iv = 0; iv < 8; ++iv) {
                double len = cuts[seg + 1] - cuts[seg];
                if (!(len > 0)) continue;
                double psi = cuts[seg] + len * (pv + 0.5 + 0.5 * x8[iv]) / panels, wv = 0.5 * len * w8[iv] / panels;
                double th = std::atan(a * std::tan(psi));
                double den = so * std::sin(2 * th), phimax;
                if (den > 0)
                    phimax = std::acos(std::clamp(-co * std::cos(2 * th) / den, -1.0, 1.0));
                else
                    phimax = std::cos(2 * th) > 0 ? M_PI : 0.0;
                double ct = std::cos(th), st = std::sin(th), cp = std::cos(psi);
                double jac = a / (cp * cp) * ct * ct * st;
                for (int pp = 0; pp < panels; ++pp)
                    for (int ip = 0; ip < 8; ++ip) {
                        double phi = phimax * (pp + 0.5 + 0.5 * x8[ip]) / panels, wp = 0.5 * w8[ip] * phimax / panels;
                        V3 h{st * std::cos(phi), st * std::sin(phi), ct};
                        double oh = V[0] * h[0] + V[1] * h[1] + V[2] * h[2];
                        if (!(oh > 0)) continue;
                        V3 L{2 * oh * h[0] - V[0], 2 * oh * h[1] - V[1], 2 * oh * h[2] - V[2]};
                        sum += wv * wp * jac * b.fcos(L) * 4 * oh;
                    }
            }
    return 2 * sum;
}

// The frame of ltc.h step 2 at the angle phi in the xz plane: Z = (sin phi, 0, cos phi).
void setFrame(Ltc& l, double phi)
{
    l.Z = {std::sin(phi), 0, std::cos(phi)};
    l.X = {std::cos(phi), 0, -std::sin(phi)};
    l.Y = {0, 1, 0};
}

// The fit's error as a function of the parameters x: (m11) with m22 = m11,
// m13 = 0 (isotropic, 1 parameter); (m11, m22, m13) in the given frame (3);
// (m11, m22, m13, phi), the frame's angle free (4).
struct FitError {
    const Brdf* brdf;
    Ltc* ltc;
    double norm;
    int ns;
    int nparams;
    bool cubed;  // Objective::L3
    int evals = 0;
    void apply(const std::vector<double>& x) const
    {
        ltc->m11 = std::max(x[0], 1e-7);
        if (nparams == 1) {
            ltc->m22 = ltc->m11;
            ltc->m13 = 0;
        } else {
            ltc->m22 = std::max(x[1], 1e-7);
            ltc->m13 = x[2];
        }
        if (nparams == 4) setFrame(*ltc, x[3]);
        ltc->update();
    }
    // The objective (cubed: Heitz's; else the L1 distance) and the L1
    // distance / norm, same samples.
    void errors(double* e, double* l1) const
    {
        double s = 0, a = 0;
        for (int j = 0; j < ns; ++j)
            for (int i = 0; i < ns; ++i) {
                double u1 = (i + 0.5) / ns, u2 = (j + 0.5) / ns;
                for (int which = 0; which < 2; ++which) {
                    V3 L = which == 0 ? ltc->sample(u1, u2) : brdf->sample(u1, u2);
                    double d = ltc->eval(L);
                    double pb = brdf->pdf(L);
                    double den = d + pb;
                    if (!(den > 0)) continue;
                    double diff = std::fabs(brdf->fcos(L) - norm * d);
                    s += (cubed ? diff * diff * diff : diff) / den;
                    a += diff / den;
                }
            }
        *e = s / (double(ns) * ns);
        *l1 = a / (double(ns) * ns) / (norm > 0 ? norm : 1);
    }
};

double objective(const std::vector<double>& x, std::vector<double>&, void* data)
{
    auto* o = static_cast<FitError*>(data);
    o->apply(x);
    ++o->evals;
    double e, l1;
    o->errors(&e, &l1);
    return std::isfinite(e) ? e : 1e300;
}

// Nelder-Mead from x (ltc.h step 2); the cell of the minimum found.
Cell minimise(const FitOptions& o, const Brdf& b, double norm, Ltc& ltc, std::vector<double> x)
{
    int np = static_cast<int>(x.size());
    FitError err{&b, &ltc, norm, o.samples, np, o.objective == Objective::L3};
    nlopt::opt opt(nlopt::LN_NELDERMEAD, static_cast<unsigned>(np));
    opt.set_min_objective(objective, &err);
    std::vector<double> lo(x.size(), -1e30);
    lo[0] = 1e-7;
    if (np > 1) lo[1] = 1e-7;
    opt.set_lower_bounds(lo);
    opt.set_initial_step(0.05);
    opt.set_ftol_rel(1e-7);
    opt.set_xtol_rel(1e-7);
    opt.set_maxeval(o.maxEval);
    double fbest = 0;
    try {
        opt.optimize(x, fbest);
    } catch (const nlopt::roundoff_limited&) {
        // x holds the best point found
    }
    err.apply(x);
    Cell c;
    c.m11 = ltc.m11;
    c.m22p = ltc.m22;
    c.m13 = ltc.m13;
    c.phi = std::atan2(ltc.Z[0], ltc.Z[2]);
    const M3& inv = ltc.invM;
    double s = inv[1][1];
    c.m00 = inv[0][0] / s;
    c.m02 = inv[0][2] / s;
    c.m20 = inv[2][0] / s;
    c.m22 = inv[2][2] / s;
    c.norm = norm;
    err.errors(&c.error, &c.l1);
    return c;
}

// Cell (i, j) of the fit, warm-started (ltc.h step 3) from the cells before
// it; phiAvgPrev: the mean direction's angle at (i, j - 1).
Cell fitCell(const FitOptions& o, const Table& t, int i, int j, double* phiAvgPrev)
{
    double alpha = t.alpha(i), theta = t.theta(j);
    Brdf b{V3{std::sin(theta), 0, std::cos(theta)}, alpha};
    double norm = albedoGL(b, o.normPanels);
    V3 avg = averageDirection(b, o.samples);
    double phiAvg = std::atan2(avg[0], avg[2]);
    Ltc ltc;
    std::vector<double> x;
    if (j == 0) {
        // the lobe is symmetric about the normal: one parameter
        const Cell* prev = i + 1 < o.size ? &t.at(i + 1, 0) : nullptr;
        ltc.m11 = prev ? prev->m11 : 1;
        ltc.m22 = prev ? prev->m22p : 1;
        x = {ltc.m11};
    } else {
        const Cell& prev = t.at(i, j - 1);
        ltc.m11 = prev.m11;
        ltc.m22 = prev.m22p;
        ltc.m13 = prev.m13;
        if (o.frame == Frame::Fixed) {
            ltc.Z = avg;
            ltc.X = {avg[2], 0, -avg[0]};
            x = {ltc.m11, ltc.m22, ltc.m13};
        } else {
            // the previous cell's frame turned as the mean direction turned
            double phi = prev.phi + (phiAvg - *phiAvgPrev);
            setFrame(ltc, phi);
            x = {ltc.m11, ltc.m22, ltc.m13, phi};
        }
    }
    ltc.update();
    *phiAvgPrev = phiAvg;
    return minimise(o, b, norm, ltc, x);
}

}  // namespace

double Table::alpha(int i) const
{
    double r = double(i) / (options.size - 1);
    return std::max(r * r, options.alphaMin);
}

double Table::theta(int j) const { return std::min(double(j) / (options.size - 1) * M_PI / 2, options.thetaMax); }

double ltcDensity(const Cell& c, double wx, double wy, double wz)
{
    double m[4] = {c.m00, c.m02, c.m20, c.m22};
    return fromInverse(m).eval(normalized(V3{wx, wy, wz}));
}

double l1Distance(const double* c, double alpha, double theta, int ns)
{
    Ltc l = fromInverse(c);
    Brdf b{V3{std::sin(theta), 0, std::cos(theta)}, alpha};
    double sum = 0;
    for (int j = 0; j < ns; ++j)
        for (int i = 0; i < ns; ++i) {
            double u1 = (i + 0.5) / ns, u2 = (j + 0.5) / ns;
            for (const V3& L : {l.sample(u1, u2), b.sample(u1, u2)}) {
                double d = l.eval(L), p = d + b.pdf(L);
                if (p > 0) sum += std::fabs(c[4] * d - b.fcos(L)) / p;
            }
        }
    return sum / (double(ns) * ns) / (c[4] > 0 ? c[4] : 1);
}

double massBelowHorizon(const double* c)
{
    // D's mass in {z > 0} is the cosine's in M^-1 {z > 0} = {w : (M^T e_z) . w > 0}
    Ltc l = fromInverse(c);
    V3 h{l.M[2][0], l.M[2][1], l.M[2][2]};
    double cb = h[2] / std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    return (1 - cb) / 2;
}

double albedo(double alpha, double theta, int normPanels)
{
    return albedoGL(Brdf{V3{std::sin(theta), 0, std::cos(theta)}, alpha}, normPanels);
}

Table fit(const FitOptions& o, void (*progress)(const Table&, int, int, void*), void* user)
{
    if (o.size < 2 || o.size > 1024) throw InputError(fmt::format("ltc fit: table size {} (expected 2..1024)", o.size));
    if (o.samples < 4 || o.normPanels < 4) throw InputError("ltc fit: sample grids need at least 4 points per side");
    Table t;
    t.options = o;
    int n = o.size;
    t.cells.assign(static_cast<size_t>(n) * n, Cell{});
    for (int i = n - 1; i >= 0; --i) {
        double phiAvgPrev = 0;
        for (int j = 0; j < n; ++j) {
            t.cells[static_cast<size_t>(j) * n + i] = fitCell(o, t, i, j, &phiAvgPrev);
            if (progress) progress(t, i, j, user);
        }
    }
    return t;
}

}  // namespace lb::ltc
