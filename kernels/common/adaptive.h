/* adaptive.h -- globally adaptive cubature over rectangular cells (QUADPACK
 * style), the one loop and the one rule behind the converged references: the
 * floor's area integral (area_ref.h), the specular area form (specref.h) and
 * the one-bounce integral over the room's surfaces (indirect.h).
 *
 * A cell is the rectangle [s, s + hs] x [t, t + ht] of surface k's parameter
 * square; it carries a value v and an error estimate e (the references' rule,
 * LB_ADAPT_GL4 below: a tensor 4x4 Gauss-Legendre rule summed over the
 * cell's 4 children, and e = |rule on the cell - that sum|). The caller puts its first
 * cells (lb_adapt_add), then, while the summed error exceeds rel_tol times
 * the summed value, the store can take 3 more cells, the split budget lasts
 * and some cell has a positive error, the cell of the largest error (the
 * first of ties: deterministic) is split into its 4 quadrants: child 0
 * replaces it, children 1..3 go to the end. OpenCL C has no function
 * pointers, so the loop hands the children out instead of calling an
 * integrand: lb_adapt_next gives the next cell to evaluate, the caller puts
 * its value and error back with lb_adapt_put, until lb_adapt_next says done
 * (LB_ADAPT_GL4's NAME_refine is that loop for its integrand);
 * lb_adapt_sum then re-sums the cells (the running sums carry rounding
 * residues of the subtractions).
 *
 * The store is the caller's arrays (private memory, sized for its budget):
 * ks may be 0 for a single surface, and hs and ht may be the same array for
 * square cells.
 * Compiles as OpenCL C and C++ (see vec.h); tests/math/test_adaptive.cpp runs
 * it on the host. */

/* 4-point Gauss-Legendre nodes and weights on [0, 1]. */
LB_CONSTANT real lb_gl4_xs[4] = {R(0.0694318442029737124), R(0.330009478207571868), R(0.669990521792428132),
                                 R(0.930568155797026288)};
LB_CONSTANT real lb_gl4_ws[4] = {R(0.173927422568726929), R(0.326072577431273071), R(0.326072577431273071),
                                 R(0.173927422568726929)};

LB_FN real lb_gl4_x(int i)
{
    return lb_gl4_xs[i];
}

LB_FN real lb_gl4_w(int i)
{
    return lb_gl4_ws[i];
}

typedef struct {
    int* ks;                          /* surface of each cell (0: all on surface 0) */
    real *ss, *ts, *hss, *hts, *vs, *es; /* corner, size, value, error of each cell */
    int n, cap;                       /* cells held, cells the arrays hold */
    real total, err;                  /* running sums of the values and errors */
    int splits;                       /* splits made */
    int m, q;                         /* the cell being split, its child handed out (4: none) */
    int k;                            /* the child handed out: surface, corner, size */
    real s, t, hs, ht;
} lb_adapt;

LB_FN lb_adapt lb_adapt_store(int* ks, real* ss, real* ts, real* hss, real* hts, real* vs, real* es, int cap)
{
    lb_adapt a;
    a.ks = ks;
    a.ss = ss;
    a.ts = ts;
    a.hss = hss;
    a.hts = hts;
    a.vs = vs;
    a.es = es;
    a.n = 0;
    a.cap = cap;
    a.total = R(0);
    a.err = R(0);
    a.splits = 0;
    a.m = 0;
    a.q = 4;
    a.k = 0;
    a.s = R(0);
    a.t = R(0);
    a.hs = R(0);
    a.ht = R(0);
    return a;
}

/* Slot `slot` holds the cell [s, s + hs] x [t, t + ht] of surface k ... */
LB_FN void lb_adapt_place(lb_adapt* a, int slot, int k, real s, real t, real hs, real ht)
{
    if (a->ks)
        a->ks[slot] = k;
    a->ss[slot] = s;
    a->ts[slot] = t;
    a->hss[slot] = hs;
    a->hts[slot] = ht;
}

/* ... with value v and error e (both added to the running sums). */
LB_FN void lb_adapt_value(lb_adapt* a, int slot, real v, real e)
{
    a->vs[slot] = v;
    a->es[slot] = e;
    a->total += v;
    a->err += e;
}

/* A first cell (the caller keeps within cap). */
LB_FN void lb_adapt_add(lb_adapt* a, int k, real s, real t, real hs, real ht, real v, real e)
{
    lb_adapt_place(a, a->n, k, s, t, hs, ht);
    lb_adapt_value(a, a->n++, v, e);
}

/* The next cell to evaluate: 1 with it in a->k, a->s, a->t, a->hs, a->ht,
 * or 0 when the cubature is done. */
LB_FN int lb_adapt_next(lb_adapt* a, real rel_tol, int max_splits)
{
    if (a->q == 4) {
        if (!(a->err > rel_tol * fabs(a->total)) || a->n + 3 > a->cap || a->splits >= max_splits)
            return 0;
        int m = 0;
        for (int i = 1; i < a->n; ++i)
            if (a->es[i] > a->es[m])
                m = i;
        if (!(a->es[m] > R(0)))
            return 0;
        a->m = m;
        a->q = 0;
        a->k = a->ks ? a->ks[m] : 0;
        a->hs = R(0.5) * a->hss[m];
        a->ht = R(0.5) * a->hts[m];
        a->total -= a->vs[m];
        a->err -= a->es[m];
        ++a->splits;
    }
    a->s = a->ss[a->m] + ((a->q & 1) ? a->hs : R(0));
    a->t = a->ts[a->m] + ((a->q & 2) ? a->ht : R(0));
    return 1;
}

/* Value and error of the cell lb_adapt_next handed out. */
LB_FN void lb_adapt_put(lb_adapt* a, real v, real e)
{
    int slot = a->q == 0 ? a->m : a->n++;
    ++a->q;
    lb_adapt_place(a, slot, a->k, a->s, a->t, a->hs, a->ht);
    lb_adapt_value(a, slot, v, e);
}

/* The summed value of the cells; *err gets their summed error. */
LB_FN real lb_adapt_sum(const lb_adapt* a, real* err)
{
    real total = R(0), toterr = R(0);
    for (int i = 0; i < a->n; ++i) {
        total += a->vs[i];
        toterr += a->es[i];
    }
    *err = toterr;
    return total;
}

/* What a reference's caller asks for: the loop stops once the summed error
 * is <= rel_tol times the summed value, or after max_splits splits ... */
typedef struct {
    real rel_tol;
    int max_splits;
} lb_adapt_goal;

LB_FN lb_adapt_goal lb_adapt_goal_of(real rel_tol, int max_splits)
{
    lb_adapt_goal g;
    g.rel_tol = rel_tol;
    g.max_splits = max_splits;
    return g;
}

/* ... and what it reports: the summed error estimate, the splits made and
 * the cells at the end. */
typedef struct {
    real err;
    int splits, cells;
} lb_adapt_report;

/* LB_ADAPT_GL4(NAME, CTX, F, AREA, AT): the references' rule, written once for
 * the integrand F(const CTX* c, real s, real t) over the (s, t) square. It
 * defines
 *   NAME_rule(c, s0, t0, hs, ht): the tensor 4x4 Gauss-Legendre rule on the
 *     cell [s0, s0 + hs] x [t0, t0 + ht], AREA(c, q) of its sum q times
 *     hs ht (the measure of the cell: q itself where ds dt is the measure);
 *   NAME_cell(c, s0, t0, hs, ht, &err): the cell's value (the rule summed
 *     over its 4 children) and error estimate (|rule on the cell - that
 *     sum|);
 *   NAME_refine(a, c, rel_tol, max_splits): the adaptive loop above over the
 *     store a once its first cells are in (lb_adapt_next, NAME_cell,
 *     lb_adapt_put), AT(c, k) readying c for surface k before each cell
 *     (LB_ADAPT_ONE_SURFACE: nothing to do).
 * A macro, not a function: OpenCL C has no function pointers. */
#define LB_ADAPT_ONE_SURFACE(c, k) ((void)(c), (void)(k))
#define LB_ADAPT_GL4(NAME, CTX, F, AREA, AT)                                                                   \
    LB_FN real NAME##_rule(const CTX* c, real s0, real t0, real hs, real ht)                                   \
    {                                                                                                          \
        real q = R(0);                                                                                         \
        for (int j = 0; j < 4; ++j) {                                                                          \
            real row = R(0);                                                                                   \
            for (int i = 0; i < 4; ++i)                                                                        \
                row += lb_gl4_w(i) * F(c, s0 + hs * lb_gl4_x(i), t0 + ht * lb_gl4_x(j));                       \
            q += lb_gl4_w(j) * row;                                                                            \
        }                                                                                                      \
        return AREA(c, q * hs * ht);                                                                           \
    }                                                                                                          \
    LB_FN real NAME##_cell(const CTX* c, real s0, real t0, real hs, real ht, real* err)                        \
    {                                                                                                          \
        real q = NAME##_rule(c, s0, t0, hs, ht);                                                               \
        real a = R(0.5) * hs, b = R(0.5) * ht;                                                                 \
        real v = NAME##_rule(c, s0, t0, a, b) + NAME##_rule(c, s0 + a, t0, a, b) +                             \
                 NAME##_rule(c, s0, t0 + b, a, b) + NAME##_rule(c, s0 + a, t0 + b, a, b);                      \
        *err = fabs(v - q);                                                                                    \
        return v;                                                                                              \
    }                                                                                                          \
    LB_FN void NAME##_refine(lb_adapt* a, CTX* c, real rel_tol, int max_splits)                                \
    {                                                                                                          \
        while (lb_adapt_next(a, rel_tol, max_splits)) {                                                        \
            AT(c, a->k);                                                                                       \
            real e;                                                                                            \
            real v = NAME##_cell(c, a->s, a->t, a->hs, a->ht, &e);                                             \
            lb_adapt_put(a, v, e);                                                                             \
        }                                                                                                      \
    }
