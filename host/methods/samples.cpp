#include "methods/samples.h"

#include "math/kmath.h"
#include "util/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace lb::methods {

double radicalInverse(std::uint64_t i, unsigned base)
{
    double inv = 1.0 / base, f = inv, r = 0;
    while (i > 0) {
        r += f * static_cast<double>(i % base);
        i /= base;
        f *= inv;
    }
    return r;
}

namespace {

// The squared distance of (ds, dt) on the unit torus: each coordinate wraps,
// so that a point near the edge has neighbours across it.
double torusDist2(double ds, double dt)
{
    ds = std::fabs(ds);
    dt = std::fabs(dt);
    ds = std::min(ds, 1 - ds);
    dt = std::min(dt, 1 - dt);
    return ds * ds + dt * dt;
}

// The points placed so far, bucketed in a G x G grid over the unit torus, so
// that the nearest one to a candidate is found by looking at the cells
// around it, ring after ring (wrapping at the edges), instead of at every
// point: O(N) for N points instead of O(N^2), with the same result, since
// the ring search stops only when no unvisited cell can hold a point nearer
// than the nearest found. Once a ring wraps onto cells already seen (r >
// G / 2) every cell has been visited; a cell seen twice changes no minimum.
class PointGrid {
public:
    explicit PointGrid(int n)
        : g_(std::max(1, std::min(1024, static_cast<int>(std::ceil(std::sqrt(0.5 * n)))))),
          cells_(static_cast<size_t>(g_) * g_)
    {
    }
    void add(double s, double t) { cells_[cellOf(s, t)].push_back({s, t}); }
    // The squared torus distance from (s, t) to the nearest point (1e300 when
    // there is none), or any value <= `enough` once the nearest is known to be
    // that close: the caller only needs to know that it cannot beat `enough`.
    double nearest2(double s, double t, double enough) const
    {
        const int cs = coord(s), ct = coord(t);
        double d = 1e300;
        auto visit = [&](int x, int y) {
            x = ((x % g_) + g_) % g_;
            y = ((y % g_) + g_) % g_;
            for (const auto& p : cells_[static_cast<size_t>(y) * g_ + x])
                d = std::min(d, torusDist2(s - p[0], t - p[1]));
        };
        for (int r = 0; r <= g_ / 2; ++r) {
            // ring r: the cells at Chebyshev distance r, its perimeter only
            for (int x = cs - r; x <= cs + r; ++x) {
                visit(x, ct - r);
                if (r > 0) visit(x, ct + r);
            }
            for (int y = ct - r + 1; y <= ct + r - 1; ++y) {
                visit(cs - r, y);
                visit(cs + r, y);
            }
            if (d <= enough) return d;
            // A point in ring r + 1 or beyond is at least r cells away; 1e-9 of
            // slack for the rounding of the squared distances.
            const double reach = r / static_cast<double>(g_);
            if (d < reach * reach * (1 - 1e-9)) return d;
        }
        return d;
    }

private:
    int coord(double u) const { return std::min(g_ - 1, std::max(0, static_cast<int>(u * g_))); }
    size_t cellOf(double s, double t) const { return static_cast<size_t>(coord(t)) * g_ + coord(s); }

    int g_;
    std::vector<std::vector<std::array<double, 2>>> cells_;  // the points in each cell, row by row
};

// Best candidate (Mitchell 1991): each new point is the one of 10 uniform
// candidates farthest from the points placed so far (the first of equals),
// distances taken on the torus. The torus matters: with plain distances a
// candidate near an edge has no neighbours beyond it and wins too often, so
// the edge band of width 0.25 / sqrt(N) held 1.6x its share of the points at
// N = 48 .. 128 (16 seeds), each weighted 1 / N: a biased MCI whose expected
// NMSE rose from N = 32 to 64 on a real luminaire (docs/mc-baselines.md). On
// the torus the construction is invariant under a shift with wrap-around,
// so every point is uniform on the light over seeds: MCI-N is unbiased.
void bestCandidate(int n, std::mt19937_64& rng, std::vector<double>& st)
{
    std::uniform_real_distribution<double> U(0.0, 1.0);
    const int kCand = 10;
    PointGrid grid(n);
    for (int i = 0; i < n; ++i) {
        double bs = 0, bt = 0, bd = -1;
        for (int c = 0; c < kCand; ++c) {
            double s = U(rng), t = U(rng);
            double d = grid.nearest2(s, t, bd);  // a candidate no farther than bd cannot win
            if (d > bd) {
                bd = d;
                bs = s;
                bt = t;
            }
        }
        grid.add(bs, bt);
        st.push_back(bs);
        st.push_back(bt);
    }
}

}  // namespace

std::vector<double> samplePoints(const std::string& pattern, int n, std::uint64_t seed)
{
    if (n < 1) throw InputError("sample set: n must be >= 1");
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::vector<double> st;
    st.reserve(2 * static_cast<size_t>(n));
    if (pattern == "random") {
        for (int i = 0; i < n; ++i) {
            st.push_back(U(rng));
            st.push_back(U(rng));
        }
    } else if (pattern == "halton") {
        double ds = seed ? U(rng) : 0.0, dt = seed ? U(rng) : 0.0;
        for (int i = 0; i < n; ++i) {
            // Index from 1: the point 0 of the sequence sits on the corner.
            st.push_back(std::fmod(radicalInverse(i + 1, 2) + ds, 1.0));
            st.push_back(std::fmod(radicalInverse(i + 1, 3) + dt, 1.0));
        }
    } else if (pattern == "stratified") {
        int rows = std::max(1, static_cast<int>(std::floor(std::sqrt(static_cast<double>(n)))));
        for (int r = 0; r < rows; ++r) {
            int a = static_cast<int>(static_cast<long>(n) * r / rows),
                b = static_cast<int>(static_cast<long>(n) * (r + 1) / rows);
            for (int k = a; k < b; ++k) {
                st.push_back((k - a + U(rng)) / (b - a));
                st.push_back((r + U(rng)) / rows);
            }
        }
    } else if (pattern == "poisson") {
        bestCandidate(n, rng, st);
    } else {
        throw InputError("sample set: unknown pattern '" + pattern + "'; valid: poisson|halton|stratified|random");
    }
    return st;
}

void mapToDisk(std::vector<double>& st)
{
    for (size_t i = 0; i + 1 < st.size(); i += 2) f64::lb_mc_concentric(&st[i], &st[i + 1]);
}

}  // namespace lb::methods
