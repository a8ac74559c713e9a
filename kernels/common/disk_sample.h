/* disk_sample.h -- directions uniform in solid angle over the disk light
 * (mc's domain=solid on LB_SHAPE_DISK, kernels/mc.cl). Compiles as OpenCL C
 * and C++; tests/methods/test_disk_mc.cpp runs it on the host.
 *
 * Geometry in the light's plane, the receiver's foot point F (its projection
 * on the plane) at the origin, the receiver at height h > 0 above it: the
 * ellipse has its centre at (cx, cy) and semi-axes a (along u), b (along v).
 * In spherical coordinates about the plane's normal through the receiver,
 * d(omega) = dw dphi with w = 1 - cos(theta) = 1 - h / sqrt(h^2 + rho^2)
 * (rho the distance from F): the disk is the region w1(phi) <= w <= w2(phi)
 * between the ray's entry and exit (rho1 = 0 where F lies inside), and
 * uniform in solid angle is uniform in (phi, w). w is sampled exactly
 * (uniform between w1 and w2, inverted for rho in closed form); phi through
 * an angular variable t whose density G(t) = (w2 - w1) |dphi/dt| is smooth:
 * in the frame scaled by (1/a, 1/b) the ellipse is the unit circle about
 * C' = (cx/a, cy/b), |C'| = d, and
 *   F inside (d < 1):  psi = psi_c + t, t in [-pi, pi] (the whole circle);
 *   F outside (d >= 1): sin(psi - psi_c) = sin(t) / d, t in [-pi/2, pi/2]
 *                       (the rays between the two tangents; G vanishes
 *                       quadratically at the tangents, where phi's own
 *                       density has a square-root edge),
 * psi the ray's angle in the scaled frame. G is tabulated at LB_MC_DISK_K + 1
 * nodes per pixel (equidistant inside, Chebyshev-spaced outside) and t drawn
 * from the piecewise-linear density through them; the sample's density in solid angle is p_t(t) / G(t) with
 * G(t) evaluated at the sample, so the estimator f G / p_t is exact
 * (unbiased) whatever the table's error, and near-uniform where G is close
 * to linear between the nodes. Fixed loop trip counts, scalar reals and
 * selects only (the work-item loop vectoriser, mc_sample.h). */

#ifndef LB_MC_DISK_K
#define LB_MC_DISK_K 8 /* cells of the tabulated angular density */
#endif

typedef struct {
    real a, b, h;                 /* semi-axes, the receiver's height */
    real d, cc, sc;               /* |C'| and the cosine, sine of its angle psi_c */
    real tn[LB_MC_DISK_K + 1];    /* the nodes of t */
    real g[LB_MC_DISK_K + 1];     /* G at the nodes */
    real cum[LB_MC_DISK_K + 1];   /* the piecewise-linear G's integral up to node k */
    real total;                   /* its integral over t: ~ the solid angle (sr) */
    bool outside;                 /* F outside the ellipse (d >= 1) */
} lb_mc_sphdisk;

/* The ray at t (cos, sin = ct, st): its unit direction (ex, ey) in the
 * plane, w at its entry and exit (w1 <= w2); returns G(t). */
LB_FN_INLINE real lb_mc_sphdisk_ray(const lb_mc_sphdisk* q, real ct, real st, real* ex, real* ey, real* w1, real* w2)
{
    real d = q->d, d2 = d * d;
    bool out = q->outside;
    /* outside: sq = sqrt(d^2 - sin^2 t), the distance to the chord's middle
     * along the ray; inside: sqrt(1 - d^2 sin^2 t), half the chord through F */
    real arg = out ? d2 - st * st : R(1) - d2 * st * st;
    real sq = LB_MC_SQRT(arg > R(0) ? arg : R(0));
    real id = out ? R(1) / d : R(1);
    real ec = out ? sq * id : ct, es = st * id; /* cos, sin of psi - psi_c */
    /* the scaled frame's distances to the circle (the entry by the product
     * of the roots, (d^2 - 1) / (sq + ct), free of cancellation) */
    real rs1 = out ? (d2 - R(1)) / (sq + ct > R(0) ? sq + ct : R(1)) : R(0);
    real rs2 = out ? sq + ct : d * ct + sq;
    real jt = out ? (sq > R(0) ? ct / sq : R(0)) : R(1); /* dpsi / dt */
    real vx = q->a * (q->cc * ec - q->sc * es), vy = q->b * (q->sc * ec + q->cc * es);
    real m2 = vx * vx + vy * vy;
    real im = m2 > R(0) ? R(1) / LB_MC_SQRT(m2) : R(0);
    *ex = vx * im, *ey = vy * im;
    /* rho = rs m (m = |v|), w = rho^2 / (r (r + h)) with r = sqrt(h^2 + rho^2) */
    real h = q->h, h2 = h * h;
    real p1 = rs1 * rs1 * m2, p2 = rs2 * rs2 * m2;
    real r1 = LB_MC_SQRT(h2 + p1), r2 = LB_MC_SQRT(h2 + p2);
    *w1 = p1 / (r1 * (r1 + h));
    *w2 = p2 / (r2 * (r2 + h));
    /* dphi / dpsi = a b / m^2 */
    return m2 > R(0) ? (*w2 - *w1) * q->a * q->b / m2 * jt : R(0);
}

/* Set-up for the ellipse centred at (cx, cy) (relative to F) with semi-axes
 * a, b, the receiver at height h > 0. */
LB_FN_INLINE void lb_mc_sphdisk_setup(real cx, real cy, real h, real a, real b, lb_mc_sphdisk* q)
{
    real x = cx / a, y = cy / b;
    real d = LB_MC_SQRT(x * x + y * y);
    q->a = a, q->b = b, q->h = h, q->d = d;
    q->cc = d > R(0) ? x / d : R(1);
    q->sc = d > R(0) ? y / d : R(0);
    q->outside = d >= R(1);
    /* nodes of t: equidistant inside; outside at -(pi/2) cos(pi k / K),
     * dense at the tangents, where G falls quadratically and a linear cell
     * oversamples (the weight -> 0 there; the narrow end cells hold less of
     * the mass) */
    real acc = R(0), prev = R(0), tprev = R(0);
#ifdef __OPENCL_C_VERSION__
#pragma unroll
#endif
    for (int k = 0; k <= LB_MC_DISK_K; ++k) {
        real ck;
        (void)LB_MC_SINCOS(LB_PI * (real)k / (real)LB_MC_DISK_K, &ck);
        real t = q->outside ? R(-0.5) * LB_PI * ck : -LB_PI + LB_TWO_PI * (real)k / (real)LB_MC_DISK_K;
        real ct, st = LB_MC_SINCOS(t, &ct);
        real ex, ey, w1, w2;
        real g = lb_mc_sphdisk_ray(q, ct, st, &ex, &ey, &w1, &w2);
        /* outside, the tangents (the ends) hold G = 0 (0 / 0 there) */
        g = q->outside && (k == 0 || k == LB_MC_DISK_K) ? R(0) : g;
        g = g > R(0) ? g : R(0);
        acc += k > 0 ? R(0.5) * (t - tprev) * (prev + g) : R(0);
        q->tn[k] = t;
        q->g[k] = g;
        q->cum[k] = acc;
        prev = g;
        tprev = t;
    }
    q->total = acc;
}

/* The point (x, y) of the disk (relative to F) for (u0, u1) in [0,1)^2:
 * directions to it uniform in solid angle up to the table's error. Returns
 * the sample's weight G(t) / p_t(t) = 1 / its density in solid angle (0 on
 * a sample of no density). */
LB_FN_INLINE real lb_mc_sphdisk_sample(const lb_mc_sphdisk* q, real u0, real u1, real* x, real* y)
{
    real target = u0 * q->total;
    /* the cell: the last node whose integral is <= target (a fixed scan) */
    real c0 = R(0), g0 = q->g[0], g1 = q->g[1], ta = q->tn[0], tb = q->tn[1];
#ifdef __OPENCL_C_VERSION__
#pragma unroll
#endif
    for (int k = 1; k < LB_MC_DISK_K; ++k) {
        bool up = target >= q->cum[k];
        c0 = up ? q->cum[k] : c0;
        g0 = up ? q->g[k] : g0;
        g1 = up ? q->g[k + 1] : g1;
        ta = up ? q->tn[k] : ta;
        tb = up ? q->tn[k + 1] : tb;
    }
    real mass = R(0.5) * (g0 + g1) * (tb - ta);
    real uc = mass > R(0) ? (target - c0) / mass : R(0);
    uc = LB_MC_CLAMP(uc, R(0), R(1));
    real xc = g0 + g1 > R(0) ? lb_mc_linear(uc, g0, g1) : R(0.5);
    real glin = g0 + xc * (g1 - g0);
    real ct, st = LB_MC_SINCOS(ta + xc * (tb - ta), &ct);
    real ex, ey, w1, w2;
    real gt = lb_mc_sphdisk_ray(q, ct, st, &ex, &ey, &w1, &w2);
    /* w uniform in [w1, w2]; rho = h tan(theta), cos(theta) = 1 - w */
    real w = w1 + u1 * (w2 - w1);
    w = w < R(0.99999994) ? w : R(0.99999994);
    real rho = q->h * LB_MC_SQRT(w * (R(2) - w)) / (R(1) - w);
    *x = rho * ex;
    *y = rho * ey;
    return glin > R(0) && gt > R(0) ? gt * q->total / glin : R(0);
}
