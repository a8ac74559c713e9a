/* area_ref.h -- the converged area integral of DESIGN section 1 at one
 * receiver point, by globally adaptive cubature:
 *   E(x) = (1/A) int_light I(d) max(0, n_x . w) / r^2 dA = int_[0,1]^2 f(s, t) ds dt
 * (dA = A ds dt). The one implementation behind the reference of the floor
 * (kernels/reference.cl) and the direct light on the walls and ceiling of the
 * indirect scene (kernels/indirect_reference.cl, kernels/indirect.cl's RSM
 * with direct=reference). Kernel-only (private arrays of LB_REF_CELLS cells,
 * __constant nodes); include after common/lbmath.h.
 *
 * Each cell of the (s, t) square carries a value (the tensor 4x4
 * Gauss-Legendre rule summed over its 4 children) and an error estimate
 * (|rule on the cell - sum of the rules on its children|). Starting from a
 * 2x2 grid of cells, the cell with the largest error is split into its 4
 * children until the summed error is <= rel_tol * |E| (or the cell store /
 * split budget is spent). Choosing the worst cell globally (QUADPACK style)
 * rather than a per-cell tolerance matters here: the bilinear photometric
 * table is only C0 across its grid lines, the integrand's derivative jumps
 * along curves on the light, and a rule straddling such a curve has an error
 * O(h^3) per cell; a global choice refines along the curve until the O(h^2)
 * total is small, where a per-area criterion would demand h ~ tol.
 * Deterministic: no random numbers, a fixed order of operations. */

/* The first cells: an LB_REF_INIT^2 grid (each with its 4 children, so the
 * first error estimate compares 4x4 against 8x8 nodes per grid cell). */
#define LB_REF_INIT 2
/* Cells the store can hold (private memory per work-item): 4 + 3 x 128. */
#define LB_REF_CELLS 388

/* 4-point Gauss-Legendre nodes and weights on [0, 1]. */
__constant real lb_gl_x[4] = {R(0.0694318442029737124), R(0.330009478207571868), R(0.669990521792428132),
                             R(0.930568155797026288)};
__constant real lb_gl_w[4] = {R(0.173927422568726929), R(0.326072577431273071), R(0.326072577431273071),
                             R(0.173927422568726929)};

typedef struct {
    real3 o, eu, ev, nx; /* light origin corner relative to x, edge vectors, receiver normal */
    lb_light L;
} lb_ref_ctx;

/* The integrand f(s, t) = I(d) max(0, n_x . w) / r^2. */
LB_FN real lb_ref_f(__global const float* lum, const lb_ref_ctx* c, real s, real t)
{
    real3 w = c->o + c->eu * s + c->ev * t;
    real r2 = dot(w, w);
    real cw = dot(c->nx, w);
    if (!(cw > R(0)) || !(r2 > R(0)))
        return R(0);
    return lb_intensity_local(lum, lb_to_light_frame(c->L, -w)) * cw / (r2 * sqrt(r2));
}

/* Tensor 4x4 Gauss-Legendre rule on the cell [s0, s0+h] x [t0, t0+h]. */
LB_FN real lb_ref_rule(__global const float* lum, const lb_ref_ctx* c, real s0, real t0, real h)
{
    real q = R(0);
    for (int j = 0; j < 4; ++j) {
        real row = R(0);
        for (int i = 0; i < 4; ++i)
            row += lb_gl_w[i] * lb_ref_f(lum, c, s0 + h * lb_gl_x[i], t0 + h * lb_gl_x[j]);
        q += lb_gl_w[j] * row;
    }
    return q * h * h;
}

/* Value (children's sum) and error estimate of a cell whose own rule is q. */
LB_FN real lb_ref_refine(__global const float* lum, const lb_ref_ctx* c, real s0, real t0, real h, real q,
                         real* err)
{
    real hh = R(0.5) * h;
    real v = lb_ref_rule(lum, c, s0, t0, hh) + lb_ref_rule(lum, c, s0 + hh, t0, hh) +
             lb_ref_rule(lum, c, s0, t0 + hh, hh) + lb_ref_rule(lum, c, s0 + hh, t0 + hh, hh);
    *err = fabs(v - q);
    return v;
}

/* E (lux) at the point x with normal nx from the light L: rel_tol the target
 * relative error, max_splits the budget of cell splits (each costs 4 x 80
 * integrand evaluations). *err receives the error estimate (sum of the
 * cells' errors), *splits the number of splits made. */
LB_FN real lb_ref_irradiance(__global const float* lum, lb_light L, real3 x, real3 nx, real rel_tol, int max_splits,
                             real* err, int* splits_made)
{
    lb_ref_ctx c;
    c.L = L;
    c.nx = nx;
    c.o = c.L.c - c.L.u * (R(0.5) * c.L.w) - c.L.v * (R(0.5) * c.L.l) - x;
    c.eu = c.L.u * c.L.w;
    c.ev = c.L.v * c.L.l;

    real cs[LB_REF_CELLS], ct[LB_REF_CELLS], ch[LB_REF_CELLS], cv[LB_REF_CELLS], ce[LB_REF_CELLS];
    int n = 0;
    real total = R(0), toterr = R(0);
    const real h0 = R(1) / (real)LB_REF_INIT;
    for (int j = 0; j < LB_REF_INIT; ++j)
        for (int i = 0; i < LB_REF_INIT; ++i) {
            real s0 = h0 * (real)i, t0 = h0 * (real)j;
            real q = lb_ref_rule(lum, &c, s0, t0, h0);
            real e;
            real v = lb_ref_refine(lum, &c, s0, t0, h0, q, &e);
            cs[n] = s0; ct[n] = t0; ch[n] = h0; cv[n] = v; ce[n] = e;
            ++n;
            total += v;
            toterr += e;
        }
    int splits = 0;
    while (toterr > rel_tol * fabs(total) && n + 3 <= LB_REF_CELLS && splits < max_splits) {
        /* The worst cell; ties go to the first (deterministic). */
        int k = 0;
        for (int i = 1; i < n; ++i)
            if (ce[i] > ce[k])
                k = i;
        if (!(ce[k] > R(0)))
            break;
        real s0 = cs[k], t0 = ct[k], hh = R(0.5) * ch[k];
        total -= cv[k];
        toterr -= ce[k];
        /* Child 0 replaces the cell, children 1..3 go to the end. */
        for (int q4 = 0; q4 < 4; ++q4) {
            real s = s0 + ((q4 & 1) ? hh : R(0)), t = t0 + ((q4 & 2) ? hh : R(0));
            real q = lb_ref_rule(lum, &c, s, t, hh);
            real e;
            real v = lb_ref_refine(lum, &c, s, t, hh, q, &e);
            int slot = q4 == 0 ? k : n++;
            cs[slot] = s; ct[slot] = t; ch[slot] = hh; cv[slot] = v; ce[slot] = e;
            total += v;
            toterr += e;
        }
        ++splits;
    }
    /* Re-sum so that the running subtractions leave no rounding residue. */
    total = R(0);
    toterr = R(0);
    for (int i = 0; i < n; ++i) {
        total += cv[i];
        toterr += ce[i];
    }
    *err = toterr;
    *splits_made = splits;
    return total;
}
