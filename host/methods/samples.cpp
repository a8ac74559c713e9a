#include "methods/samples.h"

#include "util/error.h"

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
        // Best candidate: each new point is the one of 10 uniform candidates
        // farthest from the points placed so far.
        const int kCand = 10;
        for (int i = 0; i < n; ++i) {
            double bs = 0, bt = 0, bd = -1;
            for (int c = 0; c < kCand; ++c) {
                double s = U(rng), t = U(rng), d = 1e300;
                for (int j = 0; j < i; ++j) {
                    double ds = s - st[2 * j], dt = t - st[2 * j + 1];
                    d = std::min(d, ds * ds + dt * dt);
                }
                if (d > bd) {
                    bd = d;
                    bs = s;
                    bt = t;
                }
            }
            st.push_back(bs);
            st.push_back(bt);
        }
    } else {
        throw InputError("sample set: unknown pattern '" + pattern + "'; valid: poisson|halton|stratified|random");
    }
    return st;
}

}  // namespace lb::methods
