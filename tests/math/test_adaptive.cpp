// kernels/common/adaptive.h (the globally adaptive cubature loop of the
// references) on the host, with integrands whose integrals are closed forms.
#include "math/kmath.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace {

using Fn = std::function<double(int k, double s, double t)>;

// What the references do per cell: the tensor 4x4 Gauss-Legendre rule summed
// over the cell's 4 children, error |rule on the cell - that sum|.
double rule(const Fn& f, int k, double s0, double t0, double hs, double ht)
{
    using namespace lb::f64;
    double q = 0;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) q += lb_gl4_w(i) * lb_gl4_w(j) * f(k, s0 + hs * lb_gl4_x(i), t0 + ht * lb_gl4_x(j));
    return q * hs * ht;
}

double cell(const Fn& f, int k, double s0, double t0, double hs, double ht, double* err)
{
    double a = 0.5 * hs, b = 0.5 * ht;
    double v = rule(f, k, s0, t0, a, b) + rule(f, k, s0 + a, t0, a, b) + rule(f, k, s0, t0 + b, a, b) +
        rule(f, k, s0 + a, t0 + b, a, b);
    *err = std::fabs(v - rule(f, k, s0, t0, hs, ht));
    return v;
}

struct Store {
    std::vector<int> k;
    std::vector<double> s, t, hs, ht, v, e;
    lb::f64::lb_adapt a;
    explicit Store(int cap) : k(cap), s(cap), t(cap), hs(cap), ht(cap), v(cap), e(cap)
    {
        a = lb::f64::lb_adapt_store(k.data(), s.data(), t.data(), hs.data(), ht.data(), v.data(), e.data(), cap);
    }
    void add(const Fn& f, int kk, double s0, double t0, double h0s, double h0t)
    {
        double err;
        double val = cell(f, kk, s0, t0, h0s, h0t, &err);
        lb::f64::lb_adapt_add(&a, kk, s0, t0, h0s, h0t, val, err);
    }
    // The loop as the references run it; returns the re-summed value.
    double run(const Fn& f, double relTol, int maxSplits, double* err)
    {
        while (lb::f64::lb_adapt_next(&a, relTol, maxSplits)) {
            double e1;
            double val = cell(f, a.k, a.s, a.t, a.hs, a.ht, &e1);
            lb::f64::lb_adapt_put(&a, val, e1);
        }
        return lb::f64::lb_adapt_sum(&a, err);
    }
    double area(int kk) const
    {
        double sum = 0;
        for (int i = 0; i < a.n; ++i)
            if (k[i] == kk) sum += hs[i] * ht[i];
        return sum;
    }
};

// sqrt(s + t) over the unit square: (4/15) (4 sqrt 2 - 2). Its derivative
// is singular at the corner (0, 0): the rule's error there is O(h^2.5) per
// cell, only refinement towards the corner converges.
double rootS(int, double s, double t) { return std::sqrt(s + t); }
const double kRootS = 4.0 / 15.0 * (4.0 * std::sqrt(2.0) - 2.0);

TEST(Adaptive, ConvergesOnACornerSingularityAndItsEstimateBoundsTheError)
{
    Store st(1000);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) st.add(rootS, 0, 0.5 * i, 0.5 * j, 0.5, 0.5);
    double err;
    double v = st.run(rootS, 1e-12, 300, &err);
    // The loop stopped on the tolerance, not on a budget.
    EXPECT_LT(st.a.splits, 300);
    EXPECT_LE(err, 1e-12 * std::fabs(v) * (1 + 1e-9));
    EXPECT_GT(st.a.splits, 10);
    // The estimate |parent - children| is the coarser rule's error, so the
    // children's (which are returned) is well inside it; 1e-12 plus a few
    // ulps of the sum of ~50 cells.
    EXPECT_NEAR(v, kRootS, 1e-12 + 1e-13);
    EXPECT_LE(std::fabs(v - kRootS), err + 1e-13);
    // The cells still tile the square (halvings are exact in binary).
    EXPECT_EQ(st.area(0), 1.0);
    EXPECT_EQ(st.a.n, 4 + 3 * st.a.splits);
    // Refined towards the corner: the smallest cell is there.
    int smallest = 0;
    for (int i = 1; i < st.a.n; ++i)
        if (st.hs[i] < st.hs[smallest]) smallest = i;
    EXPECT_EQ(st.s[smallest], 0.0);
    EXPECT_EQ(st.t[smallest], 0.0);
    EXPECT_LT(st.hs[smallest], 1.0 / 64);
}

TEST(Adaptive, AnExactRuleNeedsNoSplit)
{
    // The 4-point rule integrates degree 7 per variable exactly: s^7 t^3 -> 1/32.
    Fn f = [](int, double s, double t) { return std::pow(s, 7) * t * t * t; };
    Store st(100);
    st.add(f, 0, 0, 0, 1, 1);
    double err;
    double v = st.run(f, 1e-12, 100, &err);
    EXPECT_EQ(st.a.splits, 0);
    EXPECT_NEAR(v, 1.0 / 32, 1e-16);
    EXPECT_LE(err, 1e-12 / 32);
}

TEST(Adaptive, RectangularCellsOnSeveralSurfacesAreSplitTogether)
{
    // Surface 0: sqrt(s + t); surface 1: 2 sqrt(s + 1 - t) (its singular
    // corner at (0, 1)), started as two cells of 1 x 0.5. One budget, the
    // worst cell of either surface.
    Fn f = [](int k, double s, double t) { return k == 0 ? rootS(0, s, t) : 2 * rootS(0, s, 1 - t); };
    Store st(1000);
    st.add(f, 0, 0, 0, 1, 1);
    st.add(f, 1, 0, 0, 1, 0.5);
    st.add(f, 1, 0, 0.5, 1, 0.5);
    double err;
    double v = st.run(f, 1e-8, 300, &err);
    EXPECT_LT(st.a.splits, 300);
    EXPECT_NEAR(v, 3 * kRootS, 1e-8 * 3 * kRootS);
    EXPECT_EQ(st.area(0), 1.0);
    EXPECT_EQ(st.area(1), 1.0);
    // Both surfaces were refined, each towards its own singular corner, and the
    // cells keep their aspect (1 : 0.5 on surface 1).
    bool split0 = false, split1 = false;
    for (int i = 0; i < st.a.n; ++i) {
        if (st.k[i] == 0 && st.hs[i] < 1) split0 = true;
        if (st.k[i] == 1 && st.hs[i] < 1) {
            split1 = true;
            EXPECT_EQ(st.hs[i], 2 * st.ht[i]);
        }
    }
    EXPECT_TRUE(split0);
    EXPECT_TRUE(split1);
}

TEST(Adaptive, SplitsTheWorstCellChildZeroInItsPlace)
{
    // One step by hand: the worst of three cells is split, the first of ties.
    Store st(100);
    lb::f64::lb_adapt* a = &st.a;
    lb::f64::lb_adapt_add(a, 0, 0.0, 0.0, 0.5, 0.5, 1.0, 0.1);
    lb::f64::lb_adapt_add(a, 0, 0.5, 0.0, 0.5, 0.5, 1.0, 0.3);
    lb::f64::lb_adapt_add(a, 0, 0.0, 0.5, 0.5, 0.5, 1.0, 0.3);
    ASSERT_TRUE(lb::f64::lb_adapt_next(a, 0.0, 10));
    EXPECT_EQ(a->m, 1);
    EXPECT_NEAR(a->total, 2.0, 1e-15);  // the parent's value left the sum
    const double want[4][2] = {{0.5, 0.0}, {0.75, 0.0}, {0.5, 0.25}, {0.75, 0.25}};
    for (int q = 0; q < 4; ++q) {
        if (q > 0) {
            ASSERT_TRUE(lb::f64::lb_adapt_next(a, 0.0, 10));
        }
        EXPECT_EQ(a->s, want[q][0]);
        EXPECT_EQ(a->t, want[q][1]);
        EXPECT_EQ(a->hs, 0.25);
        lb::f64::lb_adapt_put(a, 0.25, 0.0);
    }
    EXPECT_EQ(a->n, 6);
    EXPECT_EQ(st.s[1], 0.5);  // child 0 in the parent's slot
    EXPECT_EQ(st.hs[1], 0.25);
    EXPECT_EQ(st.s[5], 0.75);  // child 3 last
    EXPECT_EQ(st.t[5], 0.25);
    EXPECT_EQ(a->splits, 1);
    // Next the other cell of error 0.3.
    ASSERT_TRUE(lb::f64::lb_adapt_next(a, 0.0, 10));
    EXPECT_EQ(a->m, 2);
}

TEST(Adaptive, StopsOnTheBudgetTheStoreAndAZeroEstimate)
{
    double err;
    {
        Store st(1000);
        st.add(rootS, 0, 0, 0, 1, 1);
        st.run(rootS, 0.0, 7, &err);
        EXPECT_EQ(st.a.splits, 7);  // the budget
        EXPECT_EQ(st.a.n, 1 + 3 * 7);
    }
    {
        Store st(11);
        st.add(rootS, 0, 0, 0, 1, 1);
        st.run(rootS, 0.0, 100, &err);
        EXPECT_EQ(st.a.splits, 3);  // 1 + 3 x 3 = 10 cells; one more split would need 13
        EXPECT_EQ(st.a.n, 10);
    }
    {
        Fn zero = [](int, double, double) { return 0.0; };
        Store st(100);
        st.add(zero, 0, 0, 0, 1, 1);
        double v = st.run(zero, 0.0, 100, &err);  // 0 > 0 * |0| is false: done at once
        EXPECT_EQ(st.a.splits, 0);
        EXPECT_EQ(v, 0.0);
    }
}

TEST(Adaptive, SquareCellsNeedNeitherSurfacesNorASecondSizeArray)
{
    // The references' store: no surface array, hs and ht the same array; in
    // float as the float kernels run it.
    using namespace lb::f32;
    std::vector<float> s(64), t(64), h(64), v(64), e(64);
    lb_adapt a = lb_adapt_store(nullptr, s.data(), t.data(), h.data(), h.data(), v.data(), e.data(), 64);
    auto f = [](float x, float y) { return std::sqrt(x + y); };
    auto cellf = [&](float s0, float t0, float hh, float* err) {
        double ee;
        double val = cell([&](int, double x, double y) { return f(float(x), float(y)); }, 0, s0, t0, hh, hh, &ee);
        *err = float(ee);
        return float(val);
    };
    float e0;
    float v0 = cellf(0, 0, 1, &e0);
    lb_adapt_add(&a, 0, 0, 0, 1, 1, v0, e0);
    while (lb_adapt_next(&a, 1e-5f, 100)) {
        EXPECT_EQ(a.k, 0);
        EXPECT_EQ(a.hs, a.ht);
        float e1;
        float v1 = cellf(a.s, a.t, a.hs, &e1);
        lb_adapt_put(&a, v1, e1);
    }
    float err;
    float sum = lb_adapt_sum(&a, &err);
    EXPECT_GT(a.splits, 0);
    EXPECT_NEAR(sum, float(kRootS), 2e-5f);  // tolerance 1e-5 plus float rounding of ~20 cells
}

}  // namespace
