/* disk.h -- the disk light (LB_SHAPE_DISK, docs/design.md section 2): the
 * ellipse inscribed in the W x L rectangle of the frame (u, v, n_L), a disk
 * of diameter D when W = L = D. Its rim is
 *   p(phi) = c + (W/2) cos(phi) u + (L/2) sin(phi) v.
 *
 * What the methods need of it, exactly where a rectangle has Lambert's
 * formula: the projected solid angle of a region bounded by straight edges
 * and arcs of the rim, by Stokes' theorem the contour integral
 *   Phi = 1/2 | oint  n_x . (r x dr) / |r|^2 |,   r = p - x
 * (Lambert's formula is that integral over straight edges, each giving
 * Theta_i n_x . (r_i x r_i+1) / |r_i x r_i+1|). An arc's part has no closed
 * form; it is integrated by 4-node Gauss-Legendre per arc of the fan. With
 * r(phi) = d + A cos + B sin (d = c - x, A = (W/2) u, B = (L/2) v, A . B = 0)
 * its integrand is a ratio of trigonometric polynomials,
 *   n_x . (r x r') / |r|^2 = (n.(A x B) - sin n.(d x A) + cos n.(d x B))
 *                          / (d.d + 2 cos d.A + 2 sin d.B + cos^2 A.A + sin^2 B.B),
 * whose coefficients are the pixel's (lb_disk_arcs); the nodes' cos and sin
 * come from rotations, so a pixel costs six sincos whatever the fan's size
 * (tests/methods/test_disk.cpp holds the rule's error).
 *
 * The horizon of the receiver (n_x . r > 0) leaves of the rim one arc; the
 * region it bounds with its chord is what every method integrates
 * (lb_disk_visible_arc). Sines, cosines and atan2 are the polynomial ones
 * (LB_MC_SINCOS, lb_atan2_poly): PoCL's library calls cost more than all
 * the rest of a pixel (six sincos: cp 8.1 -> 1.1 ms at 128^2 without them).
 * Include at the end of lbmath.h. */

#define LB_DISK_FAN 8 /* sectors of the fan over the visible arc (lb_disk_fan) */

/* The rim point at angle phi relative to x. */
LB_FN real3 lb_disk_rim(lb_light L, real3 x, real phi)
{
    real c, s = LB_MC_SINCOS(phi, &c);
    return L.c - x + L.u * (R(0.5) * L.w * c) + L.v * (R(0.5) * L.l * s);
}

/* The arc of the rim above the horizon of the receiver (x, nx):
 * [phi0, phi0 + span]. vis = 0 when no part of the disk is above it, 1 when
 * the whole rim is (span 2 pi), 2 when the horizon cuts the disk (the chord
 * from the arc's end to its start closes the region). */
typedef struct {
    real phi0, span;
    int vis;
} lb_disk_view;

LB_FN lb_disk_view lb_disk_visible_arc(lb_light L, real3 x, real3 nx)
{
    lb_disk_view w;
    real g0 = dot(nx, L.c - x);
    real a = R(0.5) * L.w * dot(nx, L.u), b = R(0.5) * L.l * dot(nx, L.v);
    real rho = sqrt(a * a + b * b);
    w.phi0 = R(0);
    w.span = LB_TWO_PI;
    w.vis = g0 > rho ? 1 : (g0 <= -rho ? 0 : 2);
    if (w.vis == 2) {
        real cd = clamp(-g0 / rho, R(-1), R(1));
        real d = lb_atan2_poly(sqrt((R(1) - cd) * (R(1) + cd)), cd); /* acos(cd) */
        w.phi0 = lb_atan2_poly(b, a) - d;
        w.span = R(2) * d;
    }
    return w;
}

/* n_x . (a x b) / |a x b| times the angle between a and b: twice the
 * straight edge a -> b's part of Phi (a, b relative to x). */
LB_FN real lb_disk_edge(real3 a, real3 b, real3 nx)
{
    real3 c = cross(a, b);
    real lc = length(c);
    real ab = dot(a, b);
    if (!(lc > R(0)))
        return R(0);
    return lb_atan2_poly(lc, ab) * dot(nx, c) / lc;
}

/* The pixel's arc integrand (the coefficients above) and the rotations of
 * the fan: sectors of dphi = span / LB_DISK_FAN, 4 Gauss nodes each. */
typedef struct {
    real k0, ks, kc;          /* numerator: k0 + ks sin + kc cos */
    real d0, dc, ds, dcc, dss; /* denominator: d0 + dc cos + ds sin + dcc cos^2 + dss sin^2 */
    real3 d, a, b;            /* the rim r(phi) = d + a cos + b sin, relative to x */
    real c0, s0, cstep, sstep; /* cos, sin of the first angle and of dphi */
    real cn0, cn1, sn0, sn1;  /* cos, sin of the nodes' offsets dphi x_j, j = 0, 1 (j = 3, 2 mirror them) */
    real h;                   /* dphi */
} lb_disk_arcs;

LB_FN lb_disk_arcs lb_disk_arcs_at(lb_light L, real3 x, real3 nx, lb_disk_view w)
{
    lb_disk_arcs q;
    q.d = L.c - x;
    q.a = L.u * (R(0.5) * L.w);
    q.b = L.v * (R(0.5) * L.l);
    q.k0 = dot(nx, cross(q.a, q.b));
    q.ks = -dot(nx, cross(q.d, q.a));
    q.kc = dot(nx, cross(q.d, q.b));
    q.d0 = dot(q.d, q.d);
    q.dc = R(2) * dot(q.d, q.a);
    q.ds = R(2) * dot(q.d, q.b);
    q.dcc = dot(q.a, q.a);
    q.dss = dot(q.b, q.b);
    q.h = w.span / (real)LB_DISK_FAN;
    q.s0 = LB_MC_SINCOS(w.phi0, &q.c0);
    q.sstep = LB_MC_SINCOS(q.h, &q.cstep);
    q.sn0 = LB_MC_SINCOS(q.h * lb_gl4_x(0), &q.cn0);
    q.sn1 = LB_MC_SINCOS(q.h * lb_gl4_x(1), &q.cn1);
    return q;
}

/* The integrand at the angle whose cos, sin are (cp, sp). */
LB_FN real lb_disk_arc_f(const lb_disk_arcs* q, real cp, real sp)
{
    return (q->k0 + q->ks * sp + q->kc * cp) /
           (q->d0 + q->dc * cp + q->ds * sp + q->dcc * cp * cp + q->dss * sp * sp);
}

/* Twice the part of Phi of the sector's arc starting at the angle whose
 * cos, sin are (c, s): the 4-node Gauss rule on the integrand above. */
LB_FN real lb_disk_arc(const lb_disk_arcs* q, real c, real s)
{
    /* nodes x_j and 1 - x_j: the sector's end (ce, se) turned back by the same offsets */
    const real ce = c * q->cstep - s * q->sstep, se = s * q->cstep + c * q->sstep;
    return (lb_disk_arc_f(q, c * q->cn0 - s * q->sn0, s * q->cn0 + c * q->sn0) +
            lb_disk_arc_f(q, ce * q->cn0 + se * q->sn0, se * q->cn0 - ce * q->sn0)) *
               (lb_gl4_w(0) * q->h) +
           (lb_disk_arc_f(q, c * q->cn1 - s * q->sn1, s * q->cn1 + c * q->sn1) +
            lb_disk_arc_f(q, ce * q->cn1 + se * q->sn1, se * q->cn1 - ce * q->sn1)) *
               (lb_gl4_w(1) * q->h);
}

/* The rim point at (cos, sin) = (c, s), relative to x. */
LB_FN real3 lb_disk_arcs_rim(const lb_disk_arcs* q, real c, real s)
{
    return q->d + q->a * c + q->b * s;
}

/* The next sector's first angle: (c, s) turned by dphi. */
LB_FN void lb_disk_arcs_turn(const lb_disk_arcs* q, real* c, real* s)
{
    real cc = *c * q->cstep - *s * q->sstep;
    *s = *s * q->cstep + *c * q->sstep;
    *c = cc;
}

/* The closest point of the visible disk to x, relative to x: x projected
 * onto the light's plane, pulled radially into the ellipse (the closest
 * point for a circle; inside the disk for an ellipse), and, when the horizon
 * cuts the disk and that point lies below it, the nearest point of the chord
 * between the visible arc's ends. */
LB_FN real3 lb_disk_cp(lb_light L, real3 x, real3 nx, lb_disk_view w)
{
    real3 q = x - L.c;
    real qu = dot(q, L.u) / (R(0.5) * L.w), qv = dot(q, L.v) / (R(0.5) * L.l);
    real k = qu * qu + qv * qv;
    if (k > R(1)) {
        k = R(1) / sqrt(k);
        qu *= k;
        qv *= k;
    }
    real3 s = L.c - x + L.u * (R(0.5) * L.w * qu) + L.v * (R(0.5) * L.l * qv);
    if (w.vis == 2 && !(dot(nx, s) > R(0)))
        s = lb_closest_on_segment(lb_disk_rim(L, x, w.phi0), lb_disk_rim(L, x, w.phi0 + w.span), R3(0, 0, 0));
    return s;
}

/* The regular hexagon inscribed in the rim (vertices at phi = k pi / 3),
 * relative to x and clipped to the horizon of nx: the polygon on which np
 * and mrp find their points (lb_normal_point, lb_mrp take a polygon).
 * Returns its vertex count (LB_MAXV holds the 7 a clip can make). */
LB_FN int lb_disk_hexagon(lb_light L, real3 x, real3 nx, real3* p)
{
    const real h = R(0.86602540378443865); /* sin(pi / 3) */
    const real cs[6] = {R(1), R(0.5), R(-0.5), R(-1), R(-0.5), R(0.5)};
    const real sn[6] = {R(0), h, h, R(0), -h, -h};
    for (int k = 0; k < 6; ++k)
        p[k] = L.c - x + L.u * (R(0.5) * L.w * cs[k]) + L.v * (R(0.5) * L.l * sn[k]);
    return lb_clip_polygon(p, 6, nx, R(0));
}

/* Phi of the visible part w of the disk: its arc in LB_DISK_FAN pieces and,
 * when clipped, its chord. */
LB_FN real lb_disk_phi(lb_light L, real3 x, real3 nx, lb_disk_view w)
{
    lb_disk_arcs q = lb_disk_arcs_at(L, x, nx, w);
    real c = q.c0, s = q.s0, e = R(0);
    for (int i = 0; i < LB_DISK_FAN; ++i) {
        e += lb_disk_arc(&q, c, s);
        lb_disk_arcs_turn(&q, &c, &s);
    }
    if (w.vis == 2) /* the chord from the arc's end (c, s) back to its start */
        e += lb_disk_edge(lb_disk_arcs_rim(&q, c, s), lb_disk_arcs_rim(&q, q.c0, q.s0), nx);
    return R(0.5) * fabs(e);
}

/* E (lux) at x, normal nx, from the visible part w of the disk by the
 * cubature on a fan: LB_DISK_FAN sectors from the apex s (relative to x,
 * inside the visible region) over the visible arc, and, when clipped, the
 * triangle of the apex and the chord; each sector's Phi (exact up to the
 * arc's Gauss rule: spokes edge(s, p_i) - edge(s, p_i+1) plus the arc) times
 * the mean radiance of its apex and its two rim points (paper Eq. 10). */
LB_FN real lb_disk_fan(__global const float* lum, lb_light L, real3 x, real3 nx, real3 s, lb_disk_view w)
{
    lb_disk_arcs q = lb_disk_arcs_at(L, x, nx, w);
    const real ls = lb_radiance_from(lum, L, s);
    const int closed = w.vis == 1;
    const real3 start = lb_disk_arcs_rim(&q, q.c0, q.s0);
    const real lstart = lb_radiance_from(lum, L, start);
    const real spoke0 = lb_disk_edge(s, start, nx);
    real c = q.c0, sn = q.s0, la = lstart, spoke = spoke0, e = R(0);
    real3 a = start;
    for (int i = 0; i < LB_DISK_FAN; ++i) {
        const int wrap = closed && i + 1 == LB_DISK_FAN;
        real arc = lb_disk_arc(&q, c, sn);
        lb_disk_arcs_turn(&q, &c, &sn);
        a = wrap ? start : lb_disk_arcs_rim(&q, c, sn);
        real lbv = wrap ? lstart : lb_radiance_from(lum, L, a);
        real next = wrap ? spoke0 : lb_disk_edge(s, a, nx);
        e += (spoke + arc - next) * (ls + la + lbv);
        la = lbv;
        spoke = next;
    }
    if (!closed) /* the triangle of the apex, the arc's end a and its start */
        e += (spoke + lb_disk_edge(a, start, nx) - spoke0) * (ls + la + lstart);
    return fabs(e) / R(6);
}

/* The cubature on a disk at x: the fan around the visible disk's closest
 * point (lb_disk_cp). */
LB_FN real lb_disk_irradiance(__global const float* lum, lb_light L, real3 x, real3 nx)
{
    lb_disk_view w = lb_disk_visible_arc(L, x, nx);
    if (w.vis == 0)
        return R(0);
    return lb_disk_fan(lum, L, x, nx, lb_disk_cp(L, x, nx, w), w);
}

/* The area form E = (1/A) int I max(0, n_x . w) / r^2 dA on the disk by a
 * polar product rule: n Gauss-Legendre nodes in r^2 (the rim's radius 1;
 * dA / A = d(r^2) dphi / 2 pi) times 2n equally spaced angles, exact for
 * polynomials of degree 2n - 1 in the light's coordinates; n = 2 or 3 (the
 * cubature's LB_CUB_AREA: 8 or 18 nodes). */
LB_FN real lb_disk_area_gauss(__global const float* lum, lb_light L, real3 x, real3 nx, int n)
{
    const real g3x[3] = {R(0.11270166537925831), R(0.5), R(0.88729833462074169)};
    const real g3w[3] = {R(0.27777777777777778), R(0.44444444444444444), R(0.27777777777777778)};
    const real g2x[2] = {R(0.21132486540518712), R(0.78867513459481288)};
    real3 hu = L.u * (R(0.5) * L.w), hv = L.v * (R(0.5) * L.l);
    real e = R(0);
    for (int i = 0; i < n; ++i) {
        real r = sqrt(n == 3 ? g3x[i] : g2x[i]), gw = n == 3 ? g3w[i] : R(0.5);
        for (int j = 0; j < 2 * n; ++j) {
            /* the angles pi (j + 1/2) / n: 30, 90, ... 330 deg (n = 3), 45, 135, ... (n = 2) */
            const real h3 = R(0.86602540378443865), h2 = R(0.70710678118654752);
            const real c3[6] = {h3, R(0), -h3, -h3, R(0), h3}, s3[6] = {R(0.5), R(1), R(0.5), R(-0.5), R(-1), R(-0.5)};
            const real c2[4] = {h2, -h2, -h2, h2}, s2[4] = {h2, h2, -h2, -h2};
            real cphi = n == 3 ? c3[j] : c2[j], sphi = n == 3 ? s3[j] : s2[j];
            real3 p = L.c - x + hu * (r * cphi) + hv * (r * sphi);
            real r2 = dot(p, p);
            real cw = dot(nx, p);
            if (r2 > R(0) && cw > R(0))
                e += gw * lb_intensity_local(lum, lb_to_light_frame(L, -p)) * cw / (r2 * sqrt(r2));
        }
    }
    return e / (real)(2 * n);
}

/* Weight of the area form against the disk's cubature, the rectangle's rule
 * (common/cubature/clip_blend.inc lb_area_weight) on the disk: rho the
 * distance to the disk's closest point in units of its longer diameter a,
 * sin(beta) = |h| / r_far the elevation of its farthest rim point; the
 * cubature alone where rho <= q a / 2 and sin(beta) >= s, the area form alone
 * where rho >= q a or sin(beta) <= s / 2, smoothstep between. */
LB_FN real lb_disk_area_weight(lb_light L, real3 x, real3 nx, real area_q, real area_sin)
{
    lb_disk_view all;
    all.vis = 1;
    real3 d = x - L.c;
    real h = dot(d, L.n);
    real a = fmax(L.w, L.l);
    real rho = length(lb_disk_cp(L, x, nx, all));
    real s = clamp(R(2) * rho / (area_q * a) - R(1), R(0), R(1));
    real q = length(d - L.n * h) + R(0.5) * a;
    real rfar = sqrt(q * q + h * h);
    real g = rfar > R(0) ? clamp(R(2) - R(2) * fabs(h) / (area_sin * rfar), R(0), R(1)) : R(0);
    s = fmax(g, s);
    return s * s * (R(3) - R(2) * s);
}
