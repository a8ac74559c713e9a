/* mc_table.h -- importance sampling of the luminaire's intensity table over
 * the directions towards a rectangle (kernels/mc.cl, domain=table and
 * mis_table). Compiles as OpenCL C and C++ (vec.h); the host builds the
 * table (host/methods/mc_table.cpp) and tests this code
 * (tests/methods/test_mc_sampling.cpp).
 *
 * Directions are emission directions d in the luminaire frame, parametrised
 * by the azimuth C (radians, atan2(d.y, d.x)) and the versine
 * v = 1 - cos(gamma) = 1 - d.z / |d| (uniform in v is uniform in solid angle).
 * The host's cells are the table's C planes x its gamma steps (0 and 180
 * degrees added), each weighted by its solid angle times the largest
 * intensity at its corners plus a floor (so every direction has a density),
 * quantised to integers >= 1. The density is constant in solid angle inside
 * a cell: q / (Q dC dv) for a cell of weight q in a window of total Q.
 *
 * Layout of the float buffer `tab`:
 *   tab[0] = nc, tab[1] = nv                   (counts, stored as floats)
 *   tab[2 .. 2+nc)                             C nodes in radians, ascending from 0,
 *                                              the table's planes over [0, 2 pi] twice
 *                                              (to 4 pi: a window may cross C = 0)
 *   tab[2+nc .. 2+nc+nv)                       v nodes, ascending from 0 to 2
 *   tab[2+nc+nv + i*nv + j], i < nc, j < nv    the summed-area table: the sum of the
 *                                              weights of the cells (i' < i, j' < j);
 *                                              integers <= 2^24, exact in float
 * The window of a pixel is the block of cells [i0, i1] x [j0, j1] that holds
 * every direction towards the part of the light above the horizon; its
 * column sums and prefix sums are differences of the table (exact), so the
 * sampled density is q / Q whatever the table's magnitudes. */

#define LB_TAB_HEADER 2

typedef struct {
    __global const float* c; /* C nodes */
    __global const float* v; /* v nodes */
    __global const float* s; /* the summed-area table, nv per C node */
    int nv, i0, i1, j0, j1;  /* the window: cells [i0, i1] x [j0, j1] */
    real q;                  /* its total weight */
    real a0;                 /* S(i0, j1 + 1) - S(i0, j0) */
} lb_mc_tabwin;

/* S(i, j) of the window's table. */
#define LB_TAB_S(tw, i, j) ((real)(tw)->s[(i) * (tw)->nv + (j)])

/* The largest k in [lo, hi] with a[k] <= x (lo when none): photometry.h's
 * binary search on a[lo .. hi + 1]. */
LB_FN int lb_mc_tab_find(__global const float* a, int lo, int hi, real x)
{
    return lo + lb_find_cell(a + lo, hi - lo + 2, x);
}

/* v = 1 - cos(gamma) of the emission direction towards a point at squared
 * distance rho2 from the foot, on = n_L . (light point - receiver point):
 * cos(gamma) = -on / r; without cancellation where -on ~ r. */
LB_FN real lb_mc_versine(real rho2, real on)
{
    real r = sqrt(rho2 + on * on);
    if (!(r > R(0)))
        return R(1);
    return (on < R(0) ? rho2 / (r - on) : r + on) / r;
}

/* The window's azimuth range [*c0, *c1] (c0 in [0, 2 pi), c1 - c0 <= 2 pi) of
 * the emission directions towards the rectangle [x0, x1] x [y0, y1] of offsets
 * from the receiver's foot on the light's plane. */
LB_FN void lb_mc_tab_azimuths(real x0, real x1, real y0, real y1, real* c0, real* c1)
{
    real dx = fmax(fmax(x0, -x1), R(0)), dy = fmax(fmax(y0, -y1), R(0));
    if (dx == R(0) && dy == R(0)) {
        /* the foot on the rectangle: every azimuth */
        *c0 = R(0);
        *c1 = R(2) * LB_PI;
        return;
    }
    /* an exterior foot: the rectangle lies within less than pi of its
     * centre's direction; the extremes are at corners (the emission
     * direction is minus the offset: the same angles between them) */
    real cx = R(0.5) * (x0 + x1), cy = R(0.5) * (y0 + y1);
    real px[4] = {x0, x1, x1, x0}, py[4] = {y0, y0, y1, y1};
    real lo = R(0), hi = R(0);
    for (int k = 0; k < 4; ++k) {
        real dl = atan2(cx * py[k] - cy * px[k], cx * px[k] + cy * py[k]);
        lo = fmin(lo, dl);
        hi = fmax(hi, dl);
    }
    real cc = atan2(-cy, -cx);
    /* a margin for the rounding of atan2 (the window is snapped outward to
     * cells anyway) */
    real a = cc + lo - R(1e-5), b = cc + hi + R(1e-5);
    real sh = a < R(0) ? R(2) * LB_PI : R(0);
    *c0 = a + sh;
    *c1 = b + sh;
}

/* The pixel's window for the rectangle [x0, x0 + w] x [y0, y0 + ey] of the
 * light's plane (offsets from the receiver point, the plane at on). */
LB_FN void lb_mc_tabwin_setup(__global const float* tab, real x0, real y0, real on, real w, real ey,
                              lb_mc_tabwin* tw)
{
    int nc = (int)tab[0], nv = (int)tab[1];
    tw->c = tab + LB_TAB_HEADER;
    tw->v = tw->c + nc;
    tw->s = tw->v + nv;
    tw->nv = nv;
    real x1 = x0 + w, y1 = y0 + ey;
    real dx = fmax(fmax(x0, -x1), R(0)), dy = fmax(fmax(y0, -y1), R(0));
    real fx = fmax(-x0, x1), fy = fmax(-y0, y1);
    /* v is monotonic in the distance from the foot: increasing in front of
     * the light (on < 0), decreasing behind it */
    real va = lb_mc_versine(dx * dx + dy * dy, on), vb = lb_mc_versine(fx * fx + fy * fy, on);
    real vmin = fmin(va, vb) * R(0.99999), vmax = fmax(va, vb) * R(1.00001) + R(1e-7);
    real c0, c1;
    lb_mc_tab_azimuths(x0, x1, y0, y1, &c0, &c1);
    tw->i0 = lb_mc_tab_find(tw->c, 0, nc - 2, c0);
    /* never more than one turn (the node at 2 pi may round onto c1): a
     * direction must lie in one column of the window only */
    int i1 = lb_mc_tab_find(tw->c, tw->i0, nc - 2, c1), turn = tw->i0 + (nc - 1) / 2 - 1;
    tw->i1 = i1 < turn ? i1 : turn;
    tw->j0 = lb_mc_tab_find(tw->v, 0, nv - 2, vmin);
    tw->j1 = lb_mc_tab_find(tw->v, tw->j0, nv - 2, vmax);
    int i0 = tw->i0, ie = tw->i1 + 1, j0 = tw->j0, j1 = tw->j1 + 1;
    tw->a0 = LB_TAB_S(tw, i0, j1) - LB_TAB_S(tw, i0, j0);
    tw->q = (LB_TAB_S(tw, ie, j1) - LB_TAB_S(tw, ie, j0)) - tw->a0;
}

/* The window's weight in columns [i0, i) (an integer, exact). */
LB_FN real lb_mc_tab_colsum(const lb_mc_tabwin* tw, int i)
{
    return (LB_TAB_S(tw, i, tw->j1 + 1) - LB_TAB_S(tw, i, tw->j0)) - tw->a0;
}

/* Column i's weight in rows [j0, j) (an integer, exact). */
LB_FN real lb_mc_tab_rowsum(const lb_mc_tabwin* tw, int i, int j)
{
    return (LB_TAB_S(tw, i + 1, j) - LB_TAB_S(tw, i, j)) - (LB_TAB_S(tw, i + 1, tw->j0) - LB_TAB_S(tw, i, tw->j0));
}

/* A direction of the window for (u0, u1) in [0,1)^2: the column by u0 on the
 * window's column sums, the row by u1 on the column's, the position inside
 * the cell from the remainders (uniform in C and v). Returns the emission
 * direction's (cos C, sin C) times sin(gamma) in *dx, *dy and cos(gamma) in
 * *dz (unit), and the density in solid angle. */
LB_FN real lb_mc_tab_sample(const lb_mc_tabwin* tw, real u0, real u1, real* dx, real* dy, real* dz)
{
    real a = u0 * tw->q;
    int lo = tw->i0, hi = tw->i1 + 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) >> 1;
        if (lb_mc_tab_colsum(tw, mid) <= a)
            lo = mid;
        else
            hi = mid;
    }
    int i = lo;
    real f0 = lb_mc_tab_colsum(tw, i), mi = lb_mc_tab_colsum(tw, i + 1) - f0;
    real fc = LB_MC_CLAMP((a - f0) / mi, R(0), R(1));
    real b = u1 * mi;
    lo = tw->j0, hi = tw->j1 + 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) >> 1;
        if (lb_mc_tab_rowsum(tw, i, mid) <= b)
            lo = mid;
        else
            hi = mid;
    }
    int j = lo;
    real g0 = lb_mc_tab_rowsum(tw, i, j), qc = lb_mc_tab_rowsum(tw, i, j + 1) - g0;
    real fv = LB_MC_CLAMP((b - g0) / qc, R(0), R(1));
    real ca = (real)tw->c[i], cb = (real)tw->c[i + 1], va = (real)tw->v[j], vb = (real)tw->v[j + 1];
    real cang = ca + fc * (cb - ca), v = va + fv * (vb - va);
    real sg = sqrt(fmax(v * (R(2) - v), R(0))), cc;
    real sc = LB_MC_SINCOS(cang, &cc);
    *dx = sg * cc;
    *dy = sg * sc;
    *dz = R(1) - v;
    return qc / (tw->q * (cb - ca) * (vb - va));
}

/* The density in solid angle of lb_mc_tab_sample at the emission direction
 * (dx, dy, dz) (any length): 0 outside the window. */
LB_FN real lb_mc_tab_pdf(const lb_mc_tabwin* tw, real dx, real dy, real dz)
{
    real cang = atan2(dy, dx);
    cang = cang < R(0) ? cang + R(2) * LB_PI : cang;
    cang = cang < (real)tw->c[tw->i0] ? cang + R(2) * LB_PI : cang;
    real v = lb_mc_versine(dx * dx + dy * dy, -dz);
    bool in = cang <= (real)tw->c[tw->i1 + 1] && v >= (real)tw->v[tw->j0] && v <= (real)tw->v[tw->j1 + 1];
    if (!in)
        return R(0);
    int i = lb_mc_tab_find(tw->c, tw->i0, tw->i1, cang), j = lb_mc_tab_find(tw->v, tw->j0, tw->j1, v);
    real qc = (LB_TAB_S(tw, i + 1, j + 1) - LB_TAB_S(tw, i, j + 1)) - (LB_TAB_S(tw, i + 1, j) - LB_TAB_S(tw, i, j));
    real ca = (real)tw->c[i], cb = (real)tw->c[i + 1], va = (real)tw->v[j], vb = (real)tw->v[j + 1];
    return qc / (tw->q * (cb - ca) * (vb - va));
}
