/* specref.h -- the converged reference of the specular scene (docs/design.md section
 * 8): the area form
 *   L_s(x, w_o) = (1/A) int_light I(d) f_r(w, w_o) max(0, n_x . w) / r^2 dA
 *              = int_[0,1]^2 g(s, t) ds dt
 * by globally adaptive cubature (adaptive.h, the scheme of area_ref.h: cells
 * with a 4x4 Gauss-Legendre rule summed over their 4 children, error =
 * |parent rule - children|, the worst cell split until the summed error is
 * <= rel_tol |L_s|), with a first mesh that finds the peaks.
 *
 * The GGX lobe of alpha = 0.02 seen from 2 m covers ~5 cm of the light (a
 * 1/20 of its side; at h = 0.1 a few mm): a first grid of cells whose nodes
 * straddle it would measure no error there and never refine. The first mesh
 * is therefore a quadtree refined towards two targets in (s, t), each down to
 * its own width:
 *   - the mirror point, where the reflected view ray w_r = 2 (n . w_o) n - w_o
 *     meets the light's plane (clamped to the light), width alpha * tau (tau
 *     the ray's length: the lobe's footprint);
 *   - the receiver's foot point on the light's plane (clamped), width the
 *     distance to the plane (the 1/r^2 peak of a near light).
 * A cell is split while it is wider than a target's width and overlaps the
 * target's square of that half-width; widths are floored at 2^-16 of the
 * light. Then the global adaptive loop takes over.
 * Compiles as OpenCL C and C++ (see vec.h); the host tests run it directly
 * (tests/specular), the kernel kernels/specular_reference.cl per pixel. */

/* Cells the store holds (private memory per call): first mesh <= 160,
 * then 3 per split. */
#define LB_SREF_CELLS 640
#define LB_SREF_FIRST 160

typedef struct {
    real3 o, eu, ev, nx; /* light's corner (-u,-v) relative to x, edge vectors, receiver normal */
    real3 t1, t2;        /* view frame (ggx.h lb_view_frame) */
    real ox, oz;         /* w_o in the view frame: (ox, 0, oz) */
    real alpha;
    lb_light L;
    __global const float* lum; /* the photometric table */
} lb_sref_ctx;

/* g(s, t) = I(d) f_r(w, w_o) max(0, n_x . w) / r^2. */
LB_FN real lb_sref_g(const lb_sref_ctx* c, real s, real t)
{
    real3 p = c->o + c->eu * s + c->ev * t;
    real r2 = dot(p, p);
    if (!(r2 > R(0)))
        return R(0);
    real r = sqrt(r2);
    real3 w = p / r;
    real cz = dot(c->nx, w);
    if (!(cz > R(0)))
        return R(0);
    real f = lb_ggx_brdf(dot(w, c->t1), dot(w, c->t2), cz, c->ox, R(0), c->oz, c->alpha);
    if (!(f > R(0)))
        return R(0);
    return lb_intensity_local(c->lum, lb_to_light_frame(c->L, -w)) * f * cz / r2;
}

/* lb_sref_rule, lb_sref_cell, lb_sref_refine: adaptive.h's rule on lb_sref_g. */
#define LB_SREF_AREA(c, q) (q)
LB_ADAPT_GL4(lb_sref, lb_sref_ctx, lb_sref_g, LB_SREF_AREA, LB_ADAPT_ONE_SURFACE)

/* Does the cell [s0, s0+h] x [t0, t0+h] need a split for the target (ts, tt)
 * of half-width d? */
LB_FN int lb_sref_needs(real s0, real t0, real h, real ts, real tt, real d)
{
    return h > d && ts + d >= s0 && ts - d <= s0 + h && tt + d >= t0 && tt - d <= t0 + h;
}

/* The reference at the receiver point x (world), normal nx (unit), eye
 * point eye, GGX alpha, to the goal's tolerance and budget. *rep: the summed
 * error estimate, the adaptive splits made (not counting the first mesh) and
 * the cells at the end. */
LB_FN real lb_specular_reference(__global const float* lum, lb_light L, real3 x, real3 nx, real3 eye, real alpha,
                                 lb_adapt_goal goal, lb_adapt_report* rep)
{
    lb_sref_ctx c;
    c.lum = lum;
    c.L = L;
    c.nx = nx;
    c.o = L.c - L.u * (R(0.5) * L.w) - L.v * (R(0.5) * L.l) - x;
    c.eu = L.u * L.w;
    c.ev = L.v * L.l;
    c.alpha = alpha;
    real3 wo = normalize(eye - x);
    lb_view_frame(nx, wo, &c.t1, &c.t2);
    c.ox = dot(wo, c.t1);
    c.oz = dot(wo, nx);
    rep->err = R(0);
    rep->splits = 0;
    rep->cells = 0;
    if (!(c.oz > R(0)))
        return R(0);

    /* targets: mirror point and foot point, in (s, t), with half-widths */
    real size = fmax(L.w, L.l);
    real floor_w = R(1) / R(65536);
    real ts[2], tt[2], td[2];
    int nt = 0;
    real3 wr = nx * (R(2) * c.oz) - wo;
    real dn = dot(L.n, wr);
    real tau = dn != R(0) ? dot(L.n, L.c - x) / dn : R(-1);
    if (tau > R(0)) {
        real3 hit = x + wr * tau - (L.c - L.u * (R(0.5) * L.w) - L.v * (R(0.5) * L.l));
        ts[nt] = clamp(dot(hit, L.u) / L.w, R(0), R(1));
        tt[nt] = clamp(dot(hit, L.v) / L.l, R(0), R(1));
        td[nt] = fmax(alpha * tau / size, floor_w);
        ++nt;
    }
    {
        real3 rel = -c.o;
        ts[nt] = clamp(dot(rel, L.u) / L.w, R(0), R(1));
        tt[nt] = clamp(dot(rel, L.v) / L.l, R(0), R(1));
        td[nt] = fmax(fabs(dot(L.n, x - L.c)) / size, floor_w);
        ++nt;
    }

    real cs[LB_SREF_CELLS], ct[LB_SREF_CELLS], ch[LB_SREF_CELLS], cv[LB_SREF_CELLS], ce[LB_SREF_CELLS];
    int n = 1;
    cs[0] = R(0);
    ct[0] = R(0);
    ch[0] = R(1);
    /* first mesh: split every cell that needs it, breadth first */
    for (int k = 0; k < n && n + 3 <= LB_SREF_FIRST;) {
        int need = 0;
        for (int q = 0; q < nt; ++q)
            need = need || lb_sref_needs(cs[k], ct[k], ch[k], ts[q], tt[q], td[q]);
        if (!need) {
            ++k;
            continue;
        }
        real hh = R(0.5) * ch[k];
        real s0 = cs[k], t0 = ct[k];
        for (int q4 = 0; q4 < 4; ++q4) {
            int slot = q4 == 0 ? k : n++;
            cs[slot] = s0 + ((q4 & 1) ? hh : R(0));
            ct[slot] = t0 + ((q4 & 2) ? hh : R(0));
            ch[slot] = hh;
        }
    }
    lb_adapt a = lb_adapt_store(0, cs, ct, ch, ch, cv, ce, LB_SREF_CELLS);
    for (int k = 0; k < n; ++k) {
        real e;
        real v = lb_sref_cell(&c, cs[k], ct[k], ch[k], ch[k], &e);
        lb_adapt_add(&a, 0, cs[k], ct[k], ch[k], ch[k], v, e);
    }
    lb_sref_refine(&a, &c, goal.rel_tol, goal.max_splits);
    rep->splits = a.splits;
    rep->cells = a.n;
    return lb_adapt_sum(&a, &rep->err);
}
