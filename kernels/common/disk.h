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
 * form; it is integrated by Gauss-Legendre, 8 nodes per arc of the fan
 * (two 4-node panels), exact for the straight edges and to ~1e-6 relative
 * where x is farther from the arc than the arc is long (tests/math/test_disk).
 *
 * The horizon of the receiver (n_x . r > 0) leaves of the rim one arc; the
 * region it bounds with its chord is what every method integrates
 * (lb_disk_visible_arc). Include after adaptive.h (lb_gl4_*) and dynamic.h. */

#define LB_DISK_FAN 8 /* sectors of the fan over the visible arc (lb_disk_fan) */

/* The rim point at angle phi relative to x. */
LB_FN real3 lb_disk_rim(lb_light L, real3 x, real phi)
{
    return L.c - x + L.u * (R(0.5) * L.w * cos(phi)) + L.v * (R(0.5) * L.l * sin(phi));
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
        real d = acos(clamp(-g0 / rho, R(-1), R(1)));
        w.phi0 = atan2(b, a) - d;
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
    return atan2(lc, ab) * dot(nx, c) / lc;
}

/* Twice the arc phi0 -> phi1's part of Phi: int n_x . (r x r') / |r|^2 dphi
 * by two 4-node Gauss-Legendre panels. */
LB_FN real lb_disk_arc(lb_light L, real3 x, real3 nx, real phi0, real phi1)
{
    real3 du = L.u * (R(0.5) * L.w), dv = L.v * (R(0.5) * L.l);
    real h = R(0.5) * (phi1 - phi0), s = R(0);
    for (int k = 0; k < 8; ++k) {
        real phi = phi0 + h * ((real)(k >> 2) + lb_gl4_x(k & 3));
        real cp = cos(phi), sp = sin(phi);
        real3 r = L.c - x + du * cp + dv * sp;
        real3 dr = dv * cp - du * sp;
        s += lb_gl4_w(k & 3) * dot(nx, cross(r, dr)) / dot(r, r);
    }
    return s * h;
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
    for (int k = 0; k < 6; ++k)
        p[k] = lb_disk_rim(L, x, LB_PI / R(3) * (real)k);
    return lb_clip_polygon(p, 6, nx, R(0));
}

/* Phi of the visible part w of the disk: its arc in LB_DISK_FAN pieces and,
 * when clipped, its chord. */
LB_FN real lb_disk_phi(lb_light L, real3 x, real3 nx, lb_disk_view w)
{
    const real dphi = w.span / (real)LB_DISK_FAN;
    real e = R(0);
    for (int i = 0; i < LB_DISK_FAN; ++i)
        e += lb_disk_arc(L, x, nx, w.phi0 + dphi * (real)i, w.phi0 + dphi * (real)(i + 1));
    if (w.vis == 2)
        e += lb_disk_edge(lb_disk_rim(L, x, w.phi0 + w.span), lb_disk_rim(L, x, w.phi0), nx);
    return R(0.5) * fabs(e);
}

/* E (lux) at x, normal nx, from the visible part w of the disk by the
 * cubature on a fan: LB_DISK_FAN sectors from the apex s (relative to x,
 * inside the visible region) over the visible arc, and, when clipped, the
 * triangle of the apex and the chord; each sector's Phi (exact up to the
 * arc's Gauss rule) times the mean radiance of its apex and its two rim
 * points (paper Eq. 10). */
LB_FN real lb_disk_fan(__global const float* lum, lb_light L, real3 x, real3 nx, real3 s, lb_disk_view w)
{
    const real ls = lb_radiance_from(lum, L, s);
    const real dphi = w.span / (real)LB_DISK_FAN;
    const int closed = w.vis == 1;
    const real3 start = lb_disk_rim(L, x, w.phi0);
    const real lstart = lb_radiance_from(lum, L, start);
    real3 a = start;
    real la = lstart, e = R(0);
    for (int i = 0; i < LB_DISK_FAN; ++i) {
        const int wrap = closed && i + 1 == LB_DISK_FAN;
        real p1 = w.phi0 + dphi * (real)(i + 1);
        real3 b = wrap ? start : lb_disk_rim(L, x, p1);
        real lbv = wrap ? lstart : lb_radiance_from(lum, L, b);
        real phi = lb_disk_edge(s, a, nx) + lb_disk_arc(L, x, nx, p1 - dphi, p1) + lb_disk_edge(b, s, nx);
        e += phi * (ls + la + lbv);
        a = b;
        la = lbv;
    }
    if (!closed) /* the triangle of the apex, the arc's end a and its start */
        e += (lb_disk_edge(s, a, nx) + lb_disk_edge(a, start, nx) + lb_disk_edge(start, s, nx)) *
             (ls + la + lstart);
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
            real phi = LB_PI * ((real)j + R(0.5)) / (real)n;
            real3 p = L.c - x + hu * (r * cos(phi)) + hv * (r * sin(phi));
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
