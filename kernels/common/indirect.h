/* indirect.h -- the room of the indirect scene (docs/design.md section 9) and the
 * math of one-bounce indirect light: its five reflecting surfaces, their
 * unfolded net (the RSM's texture space), the virtual point / area light
 * estimators of the ACRSM seed and the converged bounce integral.
 * Compiles as OpenCL C and C++ (see vec.h); the host includes it through
 * host/math/indirect_math.h. Include after common/lbmath.h.
 *
 * The room is the closed box [-h, h] x [-h, h] x [0, H] (h = LB_ROOM_HALF,
 * H = LB_ROOM_HEIGHT, kernels/common/scene.h), convex and empty: every
 * surface point sees every other, so no visibility term is computed anywhere
 * here. A scene with occluders would need it in three places, each marked
 * "visibility:" below: the direct light of a wall point (shadow of the light),
 * the bounce integral (wall point to floor point) and the virtual lights'
 * contributions (the seed's ISMs / soft shadows). */

/* Surfaces: 0 the ceiling z = H, 1 the wall x = -h, 2 x = +h, 3 y = -h,
 * 4 y = +h. Each is o + s a + t b, (s, t) in [0, 1]^2, with inward normal n. */
#define LB_ROOM_NSURF 5

LB_FN void lb_room_surface(int k, real3* o, real3* a, real3* b, real3* n)
{
    real h = R(LB_ROOM_HALF), H = R(LB_ROOM_HEIGHT);
    if (k == 0) {
        *o = R3(-h, -h, H); *a = R3(R(2) * h, 0, 0); *b = R3(0, R(2) * h, 0); *n = R3(0, 0, -1);
    } else if (k == 1 || k == 2) {
        real x = k == 1 ? -h : h;
        *o = R3(x, -h, 0); *a = R3(0, R(2) * h, 0); *b = R3(0, 0, H); *n = R3(k == 1 ? R(1) : R(-1), 0, 0);
    } else {
        real y = k == 3 ? -h : h;
        *o = R3(-h, y, 0); *a = R3(R(2) * h, 0, 0); *b = R3(0, 0, H); *n = R3(0, k == 3 ? R(1) : R(-1), 0);
    }
}

/* ---- The net: the ceiling in the middle of a square of side D = 2H + 2h,
 * each wall folded out along its ceiling edge (the box unfolded onto the
 * ceiling's plane, seen from below). Net point (X, Y) in [0, D]^2; the four
 * H x H corner squares belong to no surface. Along the ceiling's edges the
 * net is continuous (neighbouring texels are neighbours in the room), so the
 * seed's image-space clustering (windows, warping) works on it as on an RSM. */
LB_FN real lb_net_side(void)
{
    return R(2) * R(LB_ROOM_HEIGHT) + R(2) * R(LB_ROOM_HALF);
}

/* Surface of the net point (X, Y) (-1: none) and the room point p, normal n. */
LB_FN int lb_net_point(real X, real Y, real3* p, real3* n)
{
    real h = R(LB_ROOM_HALF), H = R(LB_ROOM_HEIGHT), D = lb_net_side();
    int inx = X >= H && X <= H + R(2) * h, iny = Y >= H && Y <= H + R(2) * h;
    real x = X - H - h, y = Y - H - h;
    if (inx && iny) {
        *p = R3(x, y, H); *n = R3(0, 0, -1);
        return 0;
    }
    if (iny && X < H) {
        *p = R3(-h, y, X); *n = R3(1, 0, 0);
        return 1;
    }
    if (iny && X > H + R(2) * h) {
        *p = R3(h, y, D - X); *n = R3(-1, 0, 0);
        return 2;
    }
    if (inx && Y < H) {
        *p = R3(x, -h, Y); *n = R3(0, 1, 0);
        return 3;
    }
    if (inx && Y > H + R(2) * h) {
        *p = R3(x, h, D - Y); *n = R3(0, -1, 0);
        return 4;
    }
    *p = R3(0, 0, 0); *n = R3(0, 0, 0);
    return -1;
}

LB_FN real lb_overlap(real a0, real a1, real b0, real b1)
{
    return fmax(R(0), fmin(a1, b1) - fmax(a0, b0));
}

/* Area (m^2) of the net square [X0, X1] x [Y0, Y1] that lies on the room's
 * surfaces: the cross of the two bands minus their common ceiling square. Summed
 * over a texel grid it is the room's reflecting area 4h^2 + 8hH exactly, so a
 * texel's flux (its E times this area) conserves the reflected flux also where
 * a texel straddles the net's border. */
LB_FN real lb_net_area(real X0, real X1, real Y0, real Y1)
{
    real h = R(LB_ROOM_HALF), H = R(LB_ROOM_HEIGHT), D = lb_net_side();
    real lo = H, hi = H + R(2) * h;
    real band_y = lb_overlap(X0, X1, R(0), D) * lb_overlap(Y0, Y1, lo, hi);
    real band_x = lb_overlap(X0, X1, lo, hi) * lb_overlap(Y0, Y1, R(0), D);
    real ceil = lb_overlap(X0, X1, lo, hi) * lb_overlap(Y0, Y1, lo, hi);
    return band_y + band_x - ceil;
}

/* ---- The records of the RSM methods (kernels/indirect.cl; the host reads
 * them too): an RSM texel, a cluster centre and a virtual light are
 * LB_IND_TEX reals each: position (3), normal (3), then flux (lm: a texel's
 * reflected flux, a light's) or a centre's radiosity B = flux / area, then
 * area (m^2: a texel's, a light's, 0 for a VPL; 0 for a centre). */
#define LB_IND_TEX 8
#define LB_IND_POS 0
#define LB_IND_NRM 3
#define LB_IND_FLUX 6
#define LB_IND_AREA 7

/* ---- Virtual lights. Irradiance at x (normal nx) from a virtual area light
 * (VAL) of reflected flux phi, centre c, normal nc and area a: the seed's
 * point-to-disk form factor (Eq. 3.9 / 5.5, its Fig. 3.11),
 *   E = phi cos_x cos_c / (pi r^2 + a),
 * exact on the axis of a parallel Lambertian disk of area a and exitance
 * phi / a (E = (phi / a) sin^2 of the disk's half-angle). a = 0 is a virtual
 * point light (VPL, Dachsbacher and Stamminger 2005), E = phi cos_x cos_c /
 * (pi r^2), with r^2 clamped to at least clamp2 (the usual 1/r^2 clamp
 * against "light sparks"; 0: no clamp). visibility: the room is convex and
 * empty; with occluders this is where the seed's ISM lookup would multiply. */
LB_FN real lb_val_irradiance(real3 x, real3 nx, real3 c, real3 nc, real phi, real a, real clamp2)
{
    real3 w = c - x;
    real r2 = dot(w, w);
    real cx = dot(nx, w), cc = -dot(nc, w);
    if (!(cx > R(0)) || !(cc > R(0)) || !(r2 > R(0)))
        return R(0);
    real ri2 = R(1) / r2; /* cos_x cos_c = cx cc / r^2 */
    return phi * cx * cc * ri2 / (LB_PI * fmax(r2, clamp2) + a);
}

/* ---- E_dir on the surfaces for the converged bounce: each surface k is cut
 * into gs x gt cells (grid[3k], grid[3k+1]), each with the 4 x 4
 * Gauss-Legendre nodes of adaptive.h; E_dir at node (is, it) of surface k is
 * edir[grid[3k+2] + it * 4 gs + is] (is, it the node's column and row over
 * the whole surface). Between the nodes E_dir is the cell's bicubic Lagrange
 * interpolant through its 16 nodes (exact for constants; for the smooth parts
 * of E_dir of order h^4). */
#define LB_BOUNCE_GRID 15 /* ints in grid[]: (gs, gt, first node) per surface */

/* Lagrange basis polynomial i through the 4 Gauss nodes, at u in [0, 1]. */
LB_FN real lb_gl4_lagrange(int i, real u)
{
    real l = R(1);
    for (int j = 0; j < 4; ++j)
        if (j != i)
            l *= (u - lb_gl4_x(j)) / (lb_gl4_x(i) - lb_gl4_x(j));
    return l;
}

/* E_dir at (s, t) in [0, 1]^2 of surface k by the cell's bicubic interpolant. */
LB_FN real lb_edir_interp(__global const real* edir, __global const int* grid, int k, real s, real t)
{
    int gs = grid[3 * k], gt = grid[3 * k + 1], base = grid[3 * k + 2];
    real fs = s * (real)gs, ft = t * (real)gt;
    int cs = LB_IMIN(LB_IMAX((int)floor(fs), 0), gs - 1), ct = LB_IMIN(LB_IMAX((int)floor(ft), 0), gt - 1);
    real us = fs - (real)cs, ut = ft - (real)ct;
    real ls[4], lt[4];
    for (int i = 0; i < 4; ++i) {
        ls[i] = lb_gl4_lagrange(i, us);
        lt[i] = lb_gl4_lagrange(i, ut);
    }
    real e = R(0);
    for (int j = 0; j < 4; ++j) {
        __global const real* row = edir + base + (4 * ct + j) * 4 * gs + 4 * cs;
        real r = R(0);
        for (int i = 0; i < 4; ++i)
            r += ls[i] * row[i];
        e += lt[j] * r;
    }
    return e;
}

/* The bounce's integrand over surface k (o, a, b, n: lb_room_surface) for
 * the receiver x with normal nx; la, lb the lengths of a and b (the area of
 * a unit of (s, t) is la lb). */
typedef struct {
    __global const real* edir; /* E_dir at the nodes (the grid above) */
    __global const int* grid;
    real3 x, nx;
    int k;
    real3 o, a, b, n;
    real la, lb;
} lb_bounce_ctx;

/* c readied for surface k. */
LB_FN void lb_bounce_at(lb_bounce_ctx* c, int k)
{
    c->k = k;
    lb_room_surface(k, &c->o, &c->a, &c->b, &c->n);
    c->la = length(c->a);
    c->lb = length(c->b);
}

/* The integrand at (s, t): E_dir(y) cos_x cos_y / r^2 (the factor rho / pi
 * comes last). visibility: none in the convex empty room. */
LB_FN real lb_bounce_f(const lb_bounce_ctx* c, real s, real t)
{
    real3 w = c->o + c->a * s + c->b * t - c->x;
    real r2 = dot(w, w);
    real cx = dot(c->nx, w), cy = -dot(c->n, w);
    if (!(cx > R(0)) || !(cy > R(0)) || !(r2 > R(0)))
        return R(0);
    return lb_edir_interp(c->edir, c->grid, c->k, s, t) * cx * cy / (r2 * r2);
}

/* lb_bounce_rule (in m^2), lb_bounce_cell, lb_bounce_refine: adaptive.h's
 * rule on lb_bounce_f. */
#define LB_BOUNCE_AREA(c, q) ((q) * (c)->la * (c)->lb)
LB_ADAPT_GL4(lb_bounce, lb_bounce_ctx, lb_bounce_f, LB_BOUNCE_AREA, lb_bounce_at)

/* First cells: about 1 m squares (ceiling 5 x 5, walls 5 x 3 in the
 * normalized room: 85 cells). */
LB_FN int lb_bounce_init_cells(int k, int* ns, int* nt)
{
    real h = R(LB_ROOM_HALF), H = R(LB_ROOM_HEIGHT);
    *ns = LB_IMAX((int)ceil(R(2) * h - R(1e-3)), 1);
    *nt = LB_IMAX((int)ceil((k == 0 ? R(2) * h : H) - R(1e-3)), 1);
    return *ns * *nt;
}
#define LB_BOUNCE_MAXINIT 85
/* Cells the store holds: the first cells plus 3 per split (LB_BOUNCE_MAXSPLITS at most). */
#define LB_BOUNCE_MAXSPLITS 160
#define LB_BOUNCE_CELLS (LB_BOUNCE_MAXINIT + 3 * LB_BOUNCE_MAXSPLITS)

/* One-bounce indirect irradiance at x (normal nx) of the room whose surfaces
 * have albedo rho and direct irradiance edir (the node grid above):
 *   E_ind(x) = (rho / pi) sum_k int_k E_dir(y) cos_x cos_y / r^2 dA(y),
 * by globally adaptive cubature over the five surfaces together (the cell of
 * the largest error estimate is split: adaptive.h), until the summed
 * estimate is <= goal.rel_tol E_ind or goal.max_splits splits are spent.
 * rep->err gets the quadrature's error estimate (lux), rep->splits the splits
 * made, rep->cells the cells at the end. The error of
 * E_dir's interpolation is the caller's (lb_bounce_interp_err). */
LB_FN real lb_bounce_irradiance(__global const real* edir, __global const int* grid, real3 x, real3 nx, real rho,
                                lb_adapt_goal goal, lb_adapt_report* rep)
{
    lb_bounce_ctx c;
    c.edir = edir;
    c.grid = grid;
    c.x = x;
    c.nx = nx;
    int ck[LB_BOUNCE_CELLS];
    real cs[LB_BOUNCE_CELLS], ct[LB_BOUNCE_CELLS], chs[LB_BOUNCE_CELLS], cht[LB_BOUNCE_CELLS], cv[LB_BOUNCE_CELLS],
        ce[LB_BOUNCE_CELLS];
    lb_adapt a = lb_adapt_store(ck, cs, ct, chs, cht, cv, ce, LB_BOUNCE_CELLS);
    for (int k = 0; k < LB_ROOM_NSURF; ++k) {
        int ns, nt;
        lb_bounce_init_cells(k, &ns, &nt);
        lb_bounce_at(&c, k);
        for (int j = 0; j < nt; ++j)
            for (int i = 0; i < ns; ++i) {
                if (a.n >= LB_BOUNCE_MAXINIT)
                    break;
                real hs = R(1) / (real)ns, ht = R(1) / (real)nt;
                real s0 = hs * (real)i, t0 = ht * (real)j;
                real e;
                real v = lb_bounce_cell(&c, s0, t0, hs, ht, &e);
                lb_adapt_add(&a, k, s0, t0, hs, ht, v, e);
            }
    }
    lb_bounce_refine(&a, &c, goal.rel_tol, LB_IMIN(goal.max_splits, LB_BOUNCE_MAXSPLITS));
    rep->splits = a.splits;
    rep->cells = a.n;
    real toterr;
    real total = lb_adapt_sum(&a, &toterr);
    rep->err = rho / LB_PI * toterr;
    return rho / LB_PI * total;
}

/* int_k cos_x cos_y / r^2 dA over surface k seen from x (normal nx): the
 * Lambert polygon irradiance at unit radiance (spherical.h). The walls touch
 * the floor's plane, none reaches below it: no clipping. */
LB_FN real lb_surface_lambert(int k, real3 x, real3 nx)
{
    real3 o, a, b, n;
    lb_room_surface(k, &o, &a, &b, &n);
    real3 p[4];
    p[0] = o - x;
    p[1] = o + a - x;
    p[2] = o + a + b - x;
    p[3] = o + b - x;
    return lb_polygon_irradiance_lambert(p, 4, nx);
}

/* Error of the bounce from E_dir's interpolation: delta[k] bounds
 * |E_dir - interpolant| on surface k (the largest deviation found at the
 * cells' centres), so the bounce errs by at most
 * (rho / pi) sum_k delta[k] int_k cos_x cos_y / r^2 dA. */
LB_FN real lb_bounce_interp_err(__global const real* delta, real3 x, real3 nx, real rho)
{
    real e = R(0);
    for (int k = 0; k < LB_ROOM_NSURF; ++k)
        e += delta[k] * lb_surface_lambert(k, x, nx);
    return rho / LB_PI * e;
}
