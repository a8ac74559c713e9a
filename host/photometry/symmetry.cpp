#include "photometry/symmetry.h"

#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lb::photometry {

const char* symmetryName(int isym)
{
    switch (isym) {
    case 0:
        return "none";
    case 1:
        return "rotational";
    case 2:
        return "C0-C180";
    case 3:
        return "C90-C270";
    case 4:
        return "quadrant";
    default:
        return "unknown";
    }
}

double foldC(int isym, double c)
{
    switch (isym) {
    case 1:
        return 0;
    case 2:
        return c <= 180 ? c : 360 - c;  // I(C) = I(360 - C)
    case 3:
        return c >= 90 && c <= 270 ? c : (c < 90 ? 180 - c : 540 - c);  // I(C) = I(180 - C)
    case 4: {
        double h = c <= 180 ? c : 360 - c;
        return h <= 90 ? h : 180 - h;
    }
    default:
        return c;  // none: 360 is looked up as 360 if stored, else as 0 (below)
    }
}

// The table gate, as bad input: values finite after scaling (a huge value
// times a multiplier can overflow), angles ascending.
static void check(const Table& t, const std::string& where)
{
    try {
        t.validate();
    } catch (const InputError&) {
        throw;
    } catch (const Error& e) {
        throw InputError(fmt::format("{}: expected a valid table, got {}", where, e.what()));
    }
}

Table unfold(int isym, const std::vector<double>& c, const std::vector<double>& gamma,
             const std::vector<std::vector<double>>& planes, const std::string& where)
{
    auto fail = [&](const std::string& what, const std::string& got) {
        throw InputError(fmt::format("{}: expected {}, got {}", where, what, got));
    };
    if (c.empty() || c.size() != planes.size()) fail("at least one stored C plane", "none");
    for (const auto& p : planes)
        if (p.size() != gamma.size()) fail("one value per gamma in every plane", "a short plane");
    Table t;
    t.gamma = gamma;
    if (isym == 1) {
        t.c = {0, 360};
        t.cd = planes[0];
        t.cd.insert(t.cd.end(), planes[0].begin(), planes[0].end());
        t.isym = 1;
        t.symmetry = symmetryName(1);
        check(t, where);
        return t;
    }
    // The stored plane a full-table angle takes its values from: the one at its
    // folded angle. Angles come from text, so mirror images are matched with a
    // tolerance of 1e-6 degrees. Without symmetry, 360 repeats 0 unless stored.
    auto source = [&](double full) -> long {
        double f = foldC(isym, full);
        for (size_t i = 0; i < c.size(); ++i)
            if (std::abs(c[i] - f) < 1e-6) return static_cast<long>(i);
        if (isym == 0 && full == 360) {
            for (size_t i = 0; i < c.size(); ++i)
                if (std::abs(c[i]) < 1e-6) return static_cast<long>(i);
        }
        return -1;
    };
    // Candidate angles: every stored angle and its mirror images, plus the ends.
    std::vector<double> cand = {0, 360};
    auto wrap = [](double a) { return a < 0 ? a + 360 : (a > 360 ? a - 360 : a); };
    for (double s : c)
        for (double a : {s, 360 - s, wrap(180 - s), wrap(180 + s)})
            if (a >= 0 && a <= 360) cand.push_back(a);
    std::sort(cand.begin(), cand.end());
    for (double end : {0.0, 360.0})
        if (source(end) < 0)
            fail(fmt::format("a stored plane at C = {} (symmetry {}, for the C = {} plane)", foldC(isym, end),
                             symmetryName(isym), end),
                 "none");
    for (double a : cand) {
        if (!t.c.empty() && a - t.c.back() < 1e-6) continue;
        long k = source(a);
        if (k < 0) continue;
        t.c.push_back(a);
        t.cd.insert(t.cd.end(), planes[k].begin(), planes[k].end());
    }
    t.c.front() = 0;
    t.c.back() = 360;
    t.isym = isym;
    t.symmetry = symmetryName(isym);
    check(t, where);
    return t;
}

}  // namespace lb::photometry
