#include "methods/sh_fit.h"

#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <mutex>

namespace lb::methods {

namespace {

// Solves the symmetric positive definite system M x = r in place (Cholesky);
// M is n x n row-major (only its lower triangle is read).
std::vector<double> solveSpd(std::vector<double> M, std::vector<double> r, int n)
{
    for (int j = 0; j < n; ++j) {
        double s = M[j * n + j];
        for (int k = 0; k < j; ++k) s -= M[j * n + k] * M[j * n + k];
        if (!(s > 0)) throw Error(fmt::format("sh fit: the normal equations are singular at row {}", j));
        double d = std::sqrt(s);
        M[j * n + j] = d;
        for (int i = j + 1; i < n; ++i) {
            double t = M[i * n + j];
            for (int k = 0; k < j; ++k) t -= M[i * n + k] * M[j * n + k];
            M[i * n + j] = t / d;
        }
    }
    for (int i = 0; i < n; ++i) {
        for (int k = 0; k < i; ++k) r[i] -= M[i * n + k] * r[k];
        r[i] /= M[i * n + i];
    }
    for (int i = n - 1; i >= 0; --i) {
        for (int k = i + 1; k < n; ++k) r[i] -= M[k * n + i] * r[k];
        r[i] /= M[i * n + i];
    }
    return r;
}

double intensityAt(const photometry::Table& t, glm::dvec3 d)
{
    double g = std::acos(std::clamp(d.z, -1.0, 1.0)) * 180 / M_PI;
    double c = std::atan2(d.y, d.x) * 180 / M_PI;
    if (c < 0) c += 360;
    return t.intensity(std::min(c, 360.0), g);
}

double dotv(const std::vector<double>& a, const std::vector<double>& b)
{
    double s = 0;
    for (size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
    return s;
}

// One hemisphere's coefficients (side 0: d.z > 0).
std::vector<double> fitSide(const photometry::Table& t, const ShFitOptions& o, int side)
{
    const int L = o.L, n = (L + 1) * (L + 1), nc = std::max(72, 4 * L + 8);
    std::vector<double> mu, wg;
    gaussLegendre(96, 0, 1, mu, wg);
    std::vector<double> M(static_cast<size_t>(n) * n, 0), r(n, 0);
    const bool lsq = o.kind == "lsq";
    for (size_t i = 0; i < mu.size(); ++i) {
        const double st = std::sqrt(1 - mu[i] * mu[i]);
        for (int k = 0; k < nc; ++k) {
            const double phi = 2 * M_PI * (k + 0.5) / nc, w = wg[i] * 2 * M_PI / nc;
            glm::dvec3 d(st * std::cos(phi), st * std::sin(phi), side ? -mu[i] : mu[i]);
            const double I = intensityAt(t, d);
            std::vector<double> y = realSh(L, d);
            if (!lsq) {
                // the mirrored g on the whole sphere (capped where mu is tiny)
                std::vector<double> ym = realSh(L, {d.x, d.y, -d.z});
                const double g = I / std::max(mu[i], 1e-3);
                for (int a = 0; a < n; ++a) r[a] += w * g * (y[a] + ym[a]);
                continue;
            }
            const double wm = w * mu[i] * mu[i];
            for (int a = 0; a < n; ++a) {
                r[a] += w * mu[i] * I * y[a];
                const double ya = wm * y[a];
                for (int b = 0; b <= a; ++b) M[a * n + b] += ya * y[b];
            }
        }
    }
    if (lsq) {
        double tr = 0;
        for (int a = 0; a < n; ++a) tr += M[a * n + a];
        for (int a = 0; a < n; ++a) M[a * n + a] += o.ridge * tr / n;
        r = solveSpd(std::move(M), std::move(r), n);
    }
    if (o.hann)
        for (int l = 0; l <= L; ++l) {
            const double s = std::cos(M_PI * l / (2.0 * (L + 1)));
            for (int m = -l; m <= l; ++m) r[l * (l + 1) + m] *= s * s;
        }
    return r;
}

ShFit fitNow(const photometry::Table& t, const ShFitOptions& o)
{
    if (o.L < 0 || o.L > 20) throw InputError(fmt::format("sh: L must be 0 .. 20, got {}", o.L));
    if (o.kind != "lsq" && o.kind != "projection")
        throw InputError(fmt::format("sh: fit must be lsq or projection, got '{}'", o.kind));
    ShFit f;
    f.opt = o;
    f.c[0] = fitSide(t, o, 0);
    f.c[1] = fitSide(t, o, 1);
    double err = 0, ref = 0;
    for (int ig = 0; ig < 180; ++ig) {
        const double g = (ig + 0.5) * M_PI / 180, st = std::sin(g), ct = std::cos(g);
        for (int ic = 0; ic < 180; ++ic) {
            const double c = (ic + 0.5) * M_PI / 90;
            glm::dvec3 d(st * std::cos(c), st * std::sin(c), ct);
            const double I = intensityAt(t, d), e = shEval(f, ct < 0, d) * std::fabs(ct) - I;
            err += st * e * e;
            ref += st * I * I;
        }
    }
    f.error = ref > 0 ? std::sqrt(err / ref) : 0;
    const double rms = std::sqrt(ref * (M_PI / 180) * (M_PI / 90) / (4 * M_PI));
    f.coefNorm = rms > 0 ? std::sqrt(std::max(dotv(f.c[0], f.c[0]), dotv(f.c[1], f.c[1]))) / rms : 0;
    return f;
}

}  // namespace

void gaussLegendre(int n, double a, double b, std::vector<double>& x, std::vector<double>& w)
{
    x.assign(n, 0);
    w.assign(n, 0);
    for (int i = 0; i < n; ++i) {
        double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1, p1 = z;
            for (int k = 2; k <= n; ++k) {
                double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (z * p1 - p0) / (z * z - 1);
            double dz = p1 / dp;
            z -= dz;
            if (std::fabs(dz) < 1e-16) break;
        }
        x[i] = 0.5 * (a + b) + 0.5 * (b - a) * z;
        w[i] = (b - a) / ((1 - z * z) * dp * dp);
    }
}

std::vector<double> realSh(int L, glm::dvec3 d)
{
    std::vector<double> y(static_cast<size_t>((L + 1) * (L + 1)), 0);
    const double x = std::clamp(d.z, -1.0, 1.0), st = std::sqrt(std::max(0.0, 1 - x * x));
    const double phi = std::atan2(d.y, d.x);
    double pmm = 1 / std::sqrt(4 * M_PI);  // the orthonormal P_m^m
    for (int m = 0; m <= L; ++m) {
        if (m > 0) pmm *= std::sqrt((2 * m + 1) / (2.0 * m)) * st;
        const double cm = m ? std::sqrt(2.0) * std::cos(m * phi) : 1, sm = std::sqrt(2.0) * std::sin(m * phi);
        double p0 = 0, p1 = pmm;
        for (int l = m; l <= L; ++l) {
            if (l == m + 1) {
                p0 = p1;
                p1 = x * std::sqrt(2.0 * m + 3) * pmm;
            } else if (l > m + 1) {
                const double a = std::sqrt((4.0 * l * l - 1) / (double(l) * l - double(m) * m));
                const double b = std::sqrt(((l - 1.0) * (l - 1.0) - double(m) * m) / (4.0 * (l - 1.0) * (l - 1.0) - 1));
                const double p2 = a * (x * p1 - b * p0);
                p0 = p1;
                p1 = p2;
            }
            y[l * (l + 1) + m] = p1 * cm;
            if (m) y[l * (l + 1) - m] = p1 * sm;
        }
    }
    return y;
}

const ShFit& shFit(const photometry::Table& t, const ShFitOptions& o)
{
    static std::mutex mu;
    static std::map<std::string, ShFit> cache;
    std::string key = fmt::format("{}|{}|{}|{}|{}|{}|", o.L, o.kind, o.ridge, o.hann, t.nc(), t.ng());
    for (const auto* v : {&t.c, &t.gamma, &t.cd}) key.append(reinterpret_cast<const char*>(v->data()), v->size() * 8);
    std::lock_guard<std::mutex> lock(mu);
    auto it = cache.find(key);
    if (it == cache.end()) it = cache.emplace(key, fitNow(t, o)).first;
    return it->second;
}

double shEval(const ShFit& f, int side, glm::dvec3 d) { return dotv(f.c[side ? 1 : 0], realSh(f.opt.L, d)); }

std::vector<glm::dvec3> fibonacciDirs(int nd)
{
    std::vector<glm::dvec3> w(nd);
    const double ga = M_PI * (3 - std::sqrt(5.0));
    for (int j = 0; j < nd; ++j) {
        const double z = 1 - (2 * j + 1.0) / nd, r = std::sqrt(1 - z * z);
        w[j] = {r * std::cos(ga * j), r * std::sin(ga * j), z};
    }
    return w;
}

std::vector<double> shToLobes(const std::vector<double>& c, int N, const std::vector<glm::dvec3>& w)
{
    const int nd = static_cast<int>(w.size());
    std::vector<double> out(static_cast<size_t>(3 * nd + (N + 1) * nd), 0);
    std::vector<std::vector<double>> yw(nd);
    for (int j = 0; j < nd; ++j) {
        yw[j] = realSh(N, w[j]);
        out[3 * j] = w[j].x;
        out[3 * j + 1] = w[j].y;
        out[3 * j + 2] = w[j].z;
    }
    for (int l = 0; l <= N; ++l) {
        // band l: sum_j b_j (4 pi / (2l + 1)) Y_lm(w_j) = c_lm for every m, the least-norm b
        const int k = 2 * l + 1;
        const double s = 4 * M_PI / k;
        std::vector<double> G(static_cast<size_t>(k) * k, 0), cl(k);
        for (int a = 0; a < k; ++a) {
            cl[a] = c[l * l + a];
            for (int b = 0; b < k; ++b)
                for (int j = 0; j < nd; ++j) G[a * k + b] += s * s * yw[j][l * l + a] * yw[j][l * l + b];
        }
        std::vector<double> y = solveSpd(G, cl, k);
        const double div = l ? double(l) * (l + 1) : 1;
        for (int j = 0; j < nd; ++j) {
            double b = 0;
            for (int a = 0; a < k; ++a) b += s * yw[j][l * l + a] * y[a];
            out[3 * nd + l * nd + j] = b / div;
        }
    }
    return out;
}

std::vector<double> shLobes(const ShFit& f, const Scene& sc)
{
    const int N = f.opt.L + 1, n = (N + 1) * (N + 1), nphi = 2 * N + 2;
    const glm::dvec3 u = sc.u(), v = sc.v(), nl = sc.n();
    const double area = sc.area();
    std::vector<double> z, wz;
    gaussLegendre(N + 2, -1, 1, z, wz);
    const std::vector<glm::dvec3> dirs = fibonacciDirs(shDirs(f.opt.L));
    std::vector<double> out;
    for (int side = 0; side < 2; ++side) {
        std::vector<double> c(n, 0);
        for (size_t i = 0; i < z.size(); ++i)
            for (int k = 0; k < nphi; ++k) {
                const double phi = 2 * M_PI * (k + 0.5) / nphi, st = std::sqrt(1 - z[i] * z[i]);
                const glm::dvec3 x(st * std::cos(phi), st * std::sin(phi), z[i]);  // toward the light
                const glm::dvec3 d = -x;  // the emission direction
                const double q = shEval(f, side, {glm::dot(d, u), glm::dot(d, v), glm::dot(d, nl)}) * x.z / area;
                std::vector<double> y = realSh(N, x);
                for (int a = 0; a < n; ++a) c[a] += wz[i] * (2 * M_PI / nphi) * q * y[a];
            }
        std::vector<double> b = shToLobes(c, N, dirs);
        out.insert(out.end(), b.begin(), b.end());
    }
    return out;
}

}  // namespace lb::methods
