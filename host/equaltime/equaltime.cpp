#include "equaltime/equaltime.h"

#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace lb::equaltime {

long solveN(Curve pts, double targetMs)
{
    std::sort(pts.begin(), pts.end());
    auto clampN = [](double n) {
        return static_cast<long>(std::clamp(std::isfinite(n) ? std::round(n) : 1.0, 1.0, double(kMaxN)));
    };
    if (pts.empty()) return 1;
    if (pts.size() == 1) return clampN(double(pts[0].first) * targetMs / pts[0].second);  // t proportional to N
    if (targetMs <= pts.front().second)
        return pts.front().first > 1 ? clampN(pts.front().first * targetMs / pts.front().second) : 1;
    // The first segment whose end reaches the target, else the last one (extrapolated).
    size_t i = 1;
    while (i + 1 < pts.size() && pts[i].second < targetMs) ++i;
    auto [n0, t0] = pts[i - 1];
    auto [n1, t1] = pts[i];
    if (!(t1 > t0)) return clampN(targetMs <= t1 ? double(n1) : double(n1) * targetMs / t1);  // flat by noise
    return clampN(double(n0) + (targetMs - t0) * double(n1 - n0) / (t1 - t0));
}

double interpolateMs(Curve pts, long n)
{
    std::sort(pts.begin(), pts.end());
    if (pts.empty()) return NAN;
    if (n <= pts.front().first) return pts.front().second * double(n) / double(pts.front().first);
    for (size_t i = 1; i < pts.size(); ++i)
        if (n <= pts[i].first) {
            auto [n0, t0] = pts[i - 1];
            auto [n1, t1] = pts[i];
            return t0 + (t1 - t0) * double(n - n0) / double(n1 - n0);
        }
    return pts.back().second * double(n) / double(pts.back().first);
}

double medianRatio(const std::vector<ocl::Timing>& tt, size_t k)
{
    std::vector<double> rr;
    for (size_t ri = 0; ri < tt[0].samples_ms.size(); ++ri) rr.push_back(tt[k].samples_ms[ri] / tt[0].samples_ms[ri]);
    return ocl::summarize(rr).median_ms;
}

namespace {

// The Ns one try times: the aimed N and its neighbour towards the target on
// the curve (first try), or the aimed N and both neighbours (later tries);
// none measured before, none below 1.
std::vector<long> triesAround(long next, int attempt, const Curve& pts, double tM,
                              const std::map<long, double>& measured)
{
    long n1 = std::max(1L, next);
    std::vector<long> tries = {n1};
    if (attempt == 0)
        tries.push_back(interpolateMs(pts, n1) > tM ? n1 - 1 : n1 + 1);
    else
        tries.insert(tries.end(), {n1 - 1, n1 + 1});
    std::vector<long> cand;
    for (long n : tries)
        if (n >= 1 && !measured.count(n) && std::find(cand.begin(), cand.end(), n) == cand.end()) cand.push_back(n);
    return cand;
}

// The state of one search: what was timed, and the best so far.
struct Search {
    const Sides& sides;
    const Options& opt;
    std::map<long, Launch> mcs;  // MC's launch by N, built once
    std::map<long, double> measured;  // N -> median round ratio
    Result best;

    // The method and each of `launches` in alternation: whole frames.
    std::vector<ocl::Timing> rounds(const std::vector<Launch>& launches) const
    {
        std::vector<Launch> all = {sides.method};
        all.insert(all.end(), launches.begin(), launches.end());
        return ocl::Runtime::timeInterleaved(all, opt.rounds, 1);
    }
    // Keeps (n, extra) if its ratio q is closer to 1 than the best so far.
    void consider(long n, double extra, double q, const ocl::Timing& tm, const ocl::Timing& tp, double scale = 1)
    {
        if (best.n != 0 && !(std::fabs(std::log(q)) < std::fabs(std::log(best.ratio)))) return;
        best.n = n;
        best.extra = extra;
        best.scale = scale;
        best.ratio = q;
        best.method = tm;
        best.partner = tp;
    }
    // Times the candidates against the method in one set of alternating rounds.
    void time(const std::vector<long>& cand)
    {
        std::vector<Launch> ls;
        for (long n : cand) {
            auto it = mcs.find(n);
            if (it == mcs.end()) it = mcs.emplace(n, sides.mc(n, 0)).first;
            ls.push_back(it->second);
        }
        const std::vector<ocl::Timing> tt = rounds(ls);
        for (size_t k = 0; k < cand.size(); ++k) {
            const double q = medianRatio(tt, k + 1);
            measured[cand[k]] = q;
            best.candidates.push_back({{"n", cand[k]}, {"ratio", q}, {"ms", tt[k + 1].median_ms}});
            consider(cand[k], 0, q, tt[0], tt[k + 1]);
        }
    }
    // The next aim on the paired ratios themselves: the secant through the
    // measured points nearest below and above 1 (or the two nearest to 1 when
    // all lie on one side); none when those below and above are adjacent Ns.
    std::optional<long> secantAim() const
    {
        std::vector<std::pair<long, double>> m(measured.begin(), measured.end());
        std::sort(m.begin(), m.end(),
                  [](auto x, auto y) { return std::fabs(std::log(x.second)) < std::fabs(std::log(y.second)); });
        auto lo = std::find_if(m.begin(), m.end(), [](auto x) { return x.second < 1; });
        auto hi = std::find_if(m.begin(), m.end(), [](auto x) { return x.second >= 1; });
        std::pair<long, double> p0 = m[0], p1 = m.size() > 1 ? m[1] : m[0];
        if (lo != m.end() && hi != m.end()) p0 = *lo, p1 = *hi;
        if (lo != m.end() && hi != m.end() && std::abs(p0.first - p1.first) == 1) return std::nullopt;  // bracketed
        double slope = p1.first != p0.first ? (p1.second - p0.second) / double(p1.first - p0.first) : 0;
        long next = slope > 0 ? std::lround(double(p0.first) + (1 - p0.second) / slope)
                              : std::lround(double(p0.first) / p0.second);  // t proportional to N
        return std::clamp(next, 1L, kMaxN);
    }
    // The neighbour of N_eq on the other side of 1 was measured too (or
    // N_eq = 1 is too slow already).
    bool bracketed() const
    {
        auto at = [&](long n) { return measured.count(n) ? std::optional<double>(measured.at(n)) : std::nullopt; };
        const long n = best.n;
        return best.ratio >= 1 ? (n == 1 || (at(n - 1) && *at(n - 1) < 1)) : (at(n + 1) && *at(n + 1) >= 1);
    }
    // Between bracketing N and N + 1: the fraction aimed by linear
    // interpolation of their paired ratios, then of the nearest pair; two tries.
    void fractional()
    {
        const long lo = best.ratio >= 1 ? best.n - 1 : best.n;
        if (!(std::abs(best.ratio - 1) > opt.tolerance && best.bracketed && lo >= 1 && measured.count(lo) &&
              measured.count(lo + 1) && sides.fractional))
            return;
        double f0 = 0, q0 = measured.at(lo), f1 = 1, q1 = measured.at(lo + 1);
        for (int attempt = 0; attempt < 2 && q1 > q0; ++attempt) {
            const double f = std::round(1000 * std::clamp(f0 + (1 - q0) * (f1 - f0) / (q1 - q0), 0.001, 0.999)) / 1000;
            const std::vector<ocl::Timing> tt = rounds({sides.mc(lo, f)});
            const double q = medianRatio(tt, 1);
            best.candidates.push_back({{"n", lo}, {"extra", f}, {"ratio", q}, {"ms", tt[1].median_ms}});
            consider(lo, f, q, tt[0], tt[1]);
            if (std::abs(q - 1) <= opt.tolerance) break;
            (q < 1 ? f0 : f1) = f;
            (q < 1 ? q0 : q1) = q;
        }
    }
    // Below N = 1 (Sides::scaled), while MC at N = 1 is too slow: the scale
    // s searched in x = s^2 on the paired ratios of scaled launches alone (a
    // scaled frame adds its upsampling, so N = 1's ratio is not on their
    // line). The first try times x = 1 / ratio(1) (time as the pixels) and
    // half of it in one set of rounds; then, while off: between the nearest
    // ratios below and above 1, linear interpolation; else along the line
    // through the two nearest 1 where it rises; else x / ratio. s in
    // [minScale, 0.999] to 3 decimals; tries + 1 sets of rounds at most.
    void subpixel()
    {
        if (!sides.scaled || !measured.count(1) || !(measured.at(1) > 1 + opt.tolerance)) return;
        auto scaleOf = [&](double x) {
            return std::round(1000 * std::clamp(std::sqrt(std::max(x, 0.0)), opt.minScale, 0.999)) / 1000;
        };
        std::map<double, double> pts;  // scale -> paired ratio
        auto timeScales = [&](std::vector<double> scales) {
            std::vector<Launch> ls;
            for (double sc : scales) ls.push_back(sides.scaled(sc));
            const std::vector<ocl::Timing> tt = rounds(ls);
            for (size_t k = 0; k < scales.size(); ++k) {
                const double q = medianRatio(tt, k + 1);
                pts[scales[k]] = q;
                best.candidates.push_back({{"n", 1}, {"scale", scales[k]}, {"ratio", q}, {"ms", tt[k + 1].median_ms}});
                consider(1, 0, q, tt[0], tt[k + 1], scales[k]);
            }
        };
        const double x1 = 1 / measured.at(1);
        std::vector<double> first = {scaleOf(x1)};
        if (scaleOf(x1 / 2) != first[0]) first.push_back(scaleOf(x1 / 2));
        timeScales(first);
        for (int attempt = 0; attempt < opt.tries; ++attempt) {
            if (std::abs(best.ratio - 1) <= opt.tolerance) break;
            const double sc = scaleOf(scaleAim(pts));
            if (pts.count(sc)) break;  // aimed where it was timed: nothing closer on this device
            timeScales({sc});
        }
    }
    // The next x = s^2 from the timed (scale, ratio) points (subpixel above).
    static double scaleAim(const std::map<double, double>& pts)
    {
        std::vector<std::pair<double, double>> p;  // (x, ratio)
        for (auto [sc, q] : pts) p.emplace_back(sc * sc, q);
        std::optional<std::pair<double, double>> lo, hi;  // nearest 1 from below and above
        for (auto pt : p) {
            if (pt.second < 1 && (!lo || pt.second > lo->second)) lo = pt;
            if (pt.second >= 1 && (!hi || pt.second < hi->second)) hi = pt;
        }
        if (lo && hi && hi->first != lo->first)
            return lo->first + (1 - lo->second) * (hi->first - lo->first) / (hi->second - lo->second);
        std::sort(p.begin(), p.end(),
                  [](auto a, auto b) { return std::fabs(std::log(a.second)) < std::fabs(std::log(b.second)); });
        if (p.size() > 1 && std::fabs(p[1].first - p[0].first) > 0.05 * p[0].first) {
            const double slope = (p[1].second - p[0].second) / (p[1].first - p[0].first);
            if (slope > 0) return p[0].first + (1 - p[0].second) / slope;
        }
        return p[0].first / p[0].second;
    }
};

}  // namespace

Result search(const Sides& sides, const Options& options, const Curve& fit, double targetMs)
{
    if (fit.empty()) throw Error("equaltime::search: no measured point of MC to aim from");
    if (options.rounds < 1) throw Error("equaltime::search: rounds must be >= 1");
    Search s{sides, options, {}, {}, {}};
    long next = solveN(fit, targetMs);  // first aim: the curve
    if (options.mode == Mode::Aim) {
        s.time({next});
        s.best.ok = std::abs(s.best.ratio - 1) <= options.tolerance;
        return s.best;
    }
    for (int attempt = 0; attempt < options.tries; ++attempt) {
        const std::vector<long> cand = triesAround(next, attempt, fit, targetMs, s.measured);
        if (cand.empty()) break;
        s.time(cand);
        if (std::abs(s.best.ratio - 1) <= options.tolerance) break;
        // MC at N = 1 already slower than the tolerance allows: no N comes closer (its floor)
        if (s.measured.count(1) && s.measured.at(1) > 1 + options.tolerance) break;
        const std::optional<long> aim = s.secantAim();
        if (!aim) break;
        next = *aim;
    }
    s.best.bracketed = s.bracketed();  // of the integer N
    s.fractional();
    s.subpixel();
    s.best.ok = std::abs(s.best.ratio - 1) <= options.tolerance;
    return s.best;
}

double metricAt(const std::vector<MetricPoint>& curveByN, double ms)
{
    if (curveByN.empty()) throw Error("equaltime::metricAt: empty MC curve");
    std::vector<std::pair<double, double>> p;  // (log t, log metric), t increasing
    double t = 0;
    for (const auto& c : curveByN) {
        t = std::max({t, c.ms, 1e-9});
        const double lt = std::log(t), lm = std::log(std::max(c.metric, 1e-300));
        if (!p.empty() && lt <= p.back().first)
            p.back().second = std::min(p.back().second, lm);
        else
            p.emplace_back(lt, lm);
    }
    const double x = std::log(std::max(ms, 1e-9));
    if (x <= p.front().first) return std::exp(p.front().second - (x - p.front().first));
    if (x >= p.back().first) return std::exp(p.back().second - (x - p.back().first));
    size_t i = 1;
    while (p[i].first < x) ++i;
    const double w = (x - p[i - 1].first) / (p[i].first - p[i - 1].first);
    return std::exp(p[i - 1].second + w * (p[i].second - p[i - 1].second));
}

}  // namespace lb::equaltime
