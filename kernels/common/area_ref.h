/* area_ref.h -- the converged area integral of docs/design.md section 1 at one
 * receiver point, by globally adaptive cubature:
 *   E(x) = (1/A) int_light I(d) max(0, n_x . w) / r^2 dA = int_[0,1]^2 f(s, t) ds dt
 * (dA = A ds dt on the rectangle, and on the disk through the concentric map, lb_ref_f).
 * The one implementation behind the reference of the floor
 * (kernels/reference.cl) and the direct light on the walls and ceiling of the
 * indirect scene (kernels/indirect_reference.cl, kernels/indirect.cl's RSM
 * with direct=reference). Kernel-only (private arrays of LB_REF_CELLS cells);
 * include after common/lbmath.h.
 *
 * Each cell of the (s, t) square carries a value (the tensor 4x4
 * Gauss-Legendre rule summed over its 4 children) and an error estimate
 * (|rule on the cell - sum of the rules on its children|). Starting from a
 * 2x2 grid of cells, the cell with the largest error is split into its 4
 * children until the summed error is <= rel_tol * |E| (or the cell store /
 * split budget is spent): the loop of adaptive.h. Choosing the worst cell
 * globally (QUADPACK style) rather than a per-cell tolerance matters here:
 * the bilinear photometric table is only C0 across its grid lines, the
 * integrand's derivative jumps along curves on the light, and a rule
 * straddling such a curve has an error O(h^3) per cell; a global choice
 * refines along the curve until the O(h^2) total is small, where a per-area
 * criterion would demand h ~ tol.
 * Deterministic: no random numbers, a fixed order of operations. */

/* The first cells: an LB_REF_INIT^2 grid (each with its 4 children, so the
 * first error estimate compares 4x4 against 8x8 nodes per grid cell). */
#define LB_REF_INIT 2
/* Cells the store can hold (private memory per work-item): 4 + 3 x 128. */
#define LB_REF_CELLS 388

typedef struct {
    /* rectangle: the origin corner relative to x and the edge vectors; disk:
     * the centre relative to x and the half-axes (W/2) u, (L/2) v */
    real3 o, eu, ev, nx; /* ... and the receiver normal */
    lb_light L;
    __global const float* lum; /* the photometric table */
} lb_ref_ctx;

/* The integrand f(s, t) = I(d) max(0, n_x . w) / r^2 (dA / A = ds dt). On
 * the disk (s, t) go through Shirley and Chiu's concentric map, which keeps
 * areas (dA / A = ds dt) and a compact peak compact: polar coordinates
 * (dA / A = 2 s ds dt) smear a beam's peak near the centre over every
 * angle, and square cells then need ~1/h times as many splits (a 150 mm
 * downlight 0.1 m up spent the whole budget in most pixels). Its derivative
 * jumps along the square's diagonals: a kink like the table's, refined
 * the same way. */
LB_FN real lb_ref_f(const lb_ref_ctx* c, real s, real t)
{
    real3 w;
    if (c->L.shape == LB_SHAPE_DISK) {
        real a = s, b = t;
        lb_mc_concentric(&a, &b); /* area-preserving: dA / A = ds dt still */
        w = c->o + c->eu * (R(2) * a - R(1)) + c->ev * (R(2) * b - R(1));
    } else {
        w = c->o + c->eu * s + c->ev * t;
    }
    real r2 = dot(w, w);
    real cw = dot(c->nx, w);
    /* A node (nearly) at the receiver point adds nothing: there cw / r^3 ~
     * 1 / r^2 overflows (to inf in float below r ~ 1e-15 m), and such a
     * receiver lies on the light, where the integral itself diverges. */
#if LB_REAL_IS_DOUBLE
    const real r2min = R(1e-200);
#else
    const real r2min = R(1e-30);
#endif
    if (!(cw > R(0)) || !(r2 > r2min))
        return R(0);
    return lb_intensity_local(c->lum, lb_to_light_frame(c->L, -w)) * cw / (r2 * sqrt(r2));
}

/* lb_ref_rule, lb_ref_cell, lb_ref_refine: adaptive.h's rule on lb_ref_f. */
#define LB_REF_AREA(c, q) (q)
LB_ADAPT_GL4(lb_ref, lb_ref_ctx, lb_ref_f, LB_REF_AREA, LB_ADAPT_ONE_SURFACE)

/* E (lux) at the point x with normal nx from the light L: rel_tol the target
 * relative error, max_splits the budget of cell splits (each costs 4 x 80
 * integrand evaluations). *err receives the error estimate (sum of the
 * cells' errors), *splits the number of splits made. */
LB_FN real lb_ref_irradiance(__global const float* lum, lb_light L, real3 x, real3 nx, real rel_tol, int max_splits,
                             real* err, int* splits_made)
{
    lb_ref_ctx c;
    c.lum = lum;
    c.L = L;
    c.nx = nx;
    const int disk = L.shape == LB_SHAPE_DISK;
    c.o = disk ? c.L.c - x : c.L.c - c.L.u * (R(0.5) * c.L.w) - c.L.v * (R(0.5) * c.L.l) - x;
    c.eu = c.L.u * (disk ? R(0.5) * c.L.w : c.L.w);
    c.ev = c.L.v * (disk ? R(0.5) * c.L.l : c.L.l);

    real cs[LB_REF_CELLS], ct[LB_REF_CELLS], ch[LB_REF_CELLS], cv[LB_REF_CELLS], ce[LB_REF_CELLS];
    lb_adapt a = lb_adapt_store(0, cs, ct, ch, ch, cv, ce, LB_REF_CELLS);
    const real h0 = R(1) / (real)LB_REF_INIT;
    for (int j = 0; j < LB_REF_INIT; ++j)
        for (int i = 0; i < LB_REF_INIT; ++i) {
            real s0 = h0 * (real)i, t0 = h0 * (real)j;
            real e;
            real v = lb_ref_cell(&c, s0, t0, h0, h0, &e);
            lb_adapt_add(&a, 0, s0, t0, h0, h0, v, e);
        }
    lb_ref_refine(&a, &c, rel_tol, max_splits);
    *splits_made = a.splits;
    return lb_adapt_sum(&a, err);
}
