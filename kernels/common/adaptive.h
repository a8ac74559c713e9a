/* adaptive.h -- globally adaptive cubature over rectangular cells (QUADPACK
 * style), the one loop behind the converged references: the floor's area
 * integral (area_ref.h), the specular area form (specref.h) and the one-bounce
 * integral over the room's surfaces (indirect.h).
 *
 * A cell is the rectangle [s, s + hs] x [t, t + ht] of surface k's parameter
 * square; it carries a value v and an error estimate e, both the caller's
 * (each caller sums a tensor 4x4 Gauss-Legendre rule over the cell's 4
 * children, and e = |rule on the cell - that sum|). The caller puts its first
 * cells (lb_adapt_add), then, while the summed error exceeds rel_tol times
 * the summed value, the store can take 3 more cells, the split budget lasts
 * and some cell has a positive error, the cell of the largest error (the
 * first of ties: deterministic) is split into its 4 quadrants: child 0
 * replaces it, children 1..3 go to the end. OpenCL C has no function
 * pointers, so the loop hands the children out instead of calling an
 * integrand: lb_adapt_next gives the next cell to evaluate, the caller puts
 * its value and error back with lb_adapt_put, until lb_adapt_next says done;
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

LB_FN void lb_adapt_set(lb_adapt* a, int slot, int k, real s, real t, real hs, real ht, real v, real e)
{
    if (a->ks)
        a->ks[slot] = k;
    a->ss[slot] = s;
    a->ts[slot] = t;
    a->hss[slot] = hs;
    a->hts[slot] = ht;
    a->vs[slot] = v;
    a->es[slot] = e;
    a->total += v;
    a->err += e;
}

/* A first cell (the caller keeps within cap). */
LB_FN void lb_adapt_add(lb_adapt* a, int k, real s, real t, real hs, real ht, real v, real e)
{
    lb_adapt_set(a, a->n++, k, s, t, hs, ht, v, e);
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
    lb_adapt_set(a, slot, a->k, a->s, a->t, a->hs, a->ht, v, e);
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
