/* mc_sample.h -- sampling the light for Monte Carlo (kernels/mc.cl):
 * per-pixel sequences in [0,1)^2 and the maps from them to directions or
 * points on the light. Compiles as OpenCL C and C++ (vec.h); the host tests
 * (tests/methods/test_mc_sampling.cpp) run this code.
 *
 * Geometry is in the light's frame (u, v, n_L) with the receiver point at the
 * origin: the light's corner (-u, -v) lies at (ou, ov, on) (scene_lanes.inc),
 * a point (s, t) of the light at (ou + W s, ov + L t, on); the receiver
 * normal is (au, av, an) there (lb_receiver_normal_local). */

typedef unsigned int lb_u32;

/* The per-sample code is written with plain arithmetic and selects (no
 * fabs, fmin, fmax, clamp, copysign, mix built-ins), and in float OpenCL
 * with the hardware sqrt / cos / sin: PoCL's CPU library implements the
 * built-ins with 4-wide SSE values, which stops its work-item loop
 * vectoriser (as common/lut.h says; measured here: solid-angle sampling 80x
 * area sampling with them); a few ulp are far below the estimators' noise. */
#define LB_MC_CLAMP(x, lo, hi) ((x) < (lo) ? (lo) : ((x) > (hi) ? (hi) : (x)))

#if defined(__OPENCL_C_VERSION__) && !LB_REAL_IS_DOUBLE
#define LB_MC_SQRT(x) native_sqrt(x)
#define LB_MC_SINCOS(x, c) lb_mc_sincos_poly(x, c)
#else
#define LB_MC_SQRT(x) sqrt(x)
#define LB_MC_SINCOS(x, c) (*(c) = cos(x), sin(x))
#endif

/* ---- integer hashing and sequences ---------------------------------------- */

#include "lanes1.h" /* the lane-generic integer and trig helpers, one pixel */
#include "mc_lanes.inc"
#include "lanes_end.h"

/* (u0, u1) uniform in [0,1]^2 to a point uniform on the disk inscribed in
 * [0,1]^2, in place: Shirley and Chiu's (1997) concentric map, continuous
 * and area-preserving up to a constant (strata stay strata). The disk
 * light's area samples (mc on LB_SHAPE_DISK: on the host for the shared
 * set, in mc.cl's extended path per pixel). */
LB_FN void lb_mc_concentric(real* u0, real* u1)
{
    real a = R(2) * *u0 - R(1), b = R(2) * *u1 - R(1);
    real r = R(0), phi = R(0);
    if (fabs(a) > fabs(b)) {
        r = a;
        phi = R(0.25) * LB_PI * (b / a);
    } else if (b != R(0)) {
        r = b;
        phi = R(0.5) * LB_PI - R(0.25) * LB_PI * (a / b);
    }
    real c, s = LB_MC_SINCOS(phi, &c);
    *u0 = R(0.5) + R(0.5) * r * c;
    *u1 = R(0.5) + R(0.5) * r * s;
}

/* Sobol's first two dimensions of index i as 32-bit fractions (natural
 * order): the van der Corput sequence, and the one with direction numbers
 * v_1 = 1/2, v_k = v_{k-1} ^ (v_{k-1} >> 1). Together a (0, 2)-sequence in
 * base 2: every 2^m consecutive points aligned at a multiple of 2^m are a
 * (0, m, 2)-net. Both loop-free, so that a per-pixel sequence keeps the
 * work-item loop vectorisable. */
LB_FN lb_u32 lb_mc_sobol0(lb_u32 i)
{
    return lb_mc_reverse(i);
}

LB_FN lb_u32 lb_mc_sobol1(lb_u32 i)
{
    /* v_k holds bit r (counting from the top) iff r is a bit-subset of k - 1
     * (Pascal's matrix mod 2, Lucas), so fraction bit r is the parity of the
     * index bits c with r a subset of c: a superset sum over the five bits of
     * the bit position, one shift-and-xor each, then the reversal. */
    lb_u32 z = i;
    z ^= (z >> 1) & 0x55555555U;
    z ^= (z >> 2) & 0x33333333U;
    z ^= (z >> 4) & 0x0f0f0f0fU;
    z ^= (z >> 8) & 0x00ff00ffU;
    z ^= (z >> 16) & 0x0000ffffU;
    return lb_mc_reverse(z);
}

/* The b-th of the 24 permutations of a base-4 digit d, b = h mod 24: the
 * affine maps d -> A d + c over F_2^2 (6 invertible matrices A, 4 offsets c),
 * which are all of S_4. */
LB_FN lb_u32 lb_mc_perm4(lb_u32 d, lb_u32 h)
{
    lb_u32 a = d & 1U, b = (d >> 1) & 1U;
    lb_u32 m = h % 6U, c = (h / 6U) & 3U;
    lb_u32 o0 = (m == 0U || m == 3U) ? a : ((m == 1U || m == 4U) ? b : (a ^ b));
    lb_u32 o1 = (m == 0U || m == 2U) ? b : ((m == 1U || m == 5U) ? a : (a ^ b));
    return ((o1 << 1) | o0) ^ c;
}

/* Bits of x interleaved with zeros (x < 2^16). */
LB_FN lb_u32 lb_mc_spread(lb_u32 x)
{
    x &= 0x0000ffffU;
    x = (x | (x << 8)) & 0x00ff00ffU;
    x = (x | (x << 4)) & 0x0f0f0f0fU;
    x = (x | (x << 2)) & 0x33333333U;
    x = (x | (x << 1)) & 0x55555555U;
    return x;
}

/* ZSobol (Ahmed and Wonka 2020, as pbrt-v4's ZSobolSampler): the Sobol index
 * of sample i of pixel (col, row): the Morton index (morton(col, row) << lg)
 * | i, lg = log2 of the samples per pixel, with every base-4 digit permuted by
 * a hash of the digits above it (and the seed), from the top down; an odd lg
 * leaves one base-2 digit at the bottom, flipped by a hash bit. Each pixel's
 * 2^lg samples stay one aligned block of Sobol indices, so a (0, lg, 2)-net;
 * neighbouring pixels get blocks related like a blue-noise tiling. `digits`
 * is resbits + (lg + 1) / 2 (resbits = bits of the image side); the index has
 * 2 resbits + lg <= 30 bits (the host checks). */
LB_FN lb_u32 lb_mc_zsobol_index(int col, int row, lb_u32 i, int lg, int digits, lb_u32 seed)
{
    lb_u32 morton = (((lb_mc_spread((lb_u32)row) << 1) | lb_mc_spread((lb_u32)col)) << lg) | i;
    int odd = lg & 1;
    lb_u32 idx = 0U;
    /* a fixed trip count (digits <= 15), unrolled: no loop inside the
     * work-item loop */
#ifdef __OPENCL_C_VERSION__
#pragma unroll
#endif
    for (int k = 0; k < 15; ++k) {
        int shift = 2 * k - odd;
        lb_u32 digit = (shift >= 0 ? morton >> shift : 0U) & 3U;
        lb_u32 higher = morton >> (shift + 2);
        lb_u32 d = lb_mc_perm4(digit, lb_mc_hash(higher ^ seed) >> 8) << (shift >= 0 ? shift : 0);
        idx |= k >= odd && k < digits ? d : 0U;
    }
    if (odd)
        idx |= (morton & 1U) ^ (lb_mc_hash((morton >> 1) ^ seed ^ 0x55555555U) & 1U);
    return idx;
}

/* ---- solid angle: spherical rectangles: common/mc_lanes.inc ---- */

/* ---- the bilinear warp (Hart, Pharr, Mueller, Lopes, McGuire, Shirley 2020) */

/* (u0, u1) warped by the density bilinear in the corner weights w00 (at
 * (0, 0)), w10, w01, w11 (all > 0); returns that density at the result. */
LB_FN real lb_mc_linear(real u, real a, real b)
{
    real x = u * (a + b) / (a + LB_MC_SQRT(a * a + u * (b * b - a * a)));
    return x < R(0.99999994) ? x : R(0.99999994);
}

LB_FN real lb_mc_bilinear(real* u0, real* u1, real w00, real w10, real w01, real w11)
{
    real y = lb_mc_linear(*u1, w00 + w10, w01 + w11);
    real x = lb_mc_linear(*u0, w00 + y * (w01 - w00), w10 + y * (w11 - w10));
    *u0 = x;
    *u1 = y;
    return R(4) * ((R(1) - x) * (R(1) - y) * w00 + x * (R(1) - y) * w10 + (R(1) - x) * y * w01 + x * y * w11) /
        (w00 + w10 + w01 + w11);
}

/* ---- projected solid angle (the receiver's cosine as the density) --------
 *
 * A convex polygon above the receiver's horizon, seen from the origin,
 * projects orthographically onto the unit disk of the receiver's tangent
 * plane; cos(theta) d(omega) is area there (Nusselt), so sampling that region
 * uniformly samples the projected solid angle. Each edge projects onto an arc
 * of an ellipse centred at the origin; the area swept from the origin along
 * the arc is |m_z| theta / 2 (theta the arc's angle, m the unit normal of its
 * great circle: the projection of a circular sector of area theta / 2). In
 * polar coordinates (phi, rho) of the disk the region is
 * {rho_in(phi) <= rho <= rho_out(phi)}, rho_in = 0 where the zenith lies
 * inside; its area up to an azimuth phi, A(phi) = sum over edges of
 * (+-) |m_z| theta_k(phi) / 2 (outer arcs +, inner -), is inverted for phi by
 * a bracketed Newton iteration (dA / dphi = (rho_out^2 - rho_in^2) / 2), and
 * rho^2 is then uniform between rho_in^2 and rho_out^2: a bijection of
 * [0,1)^2 onto the region that keeps the sequence's stratification. (Peters
 * 2021 samples the same density; this inversion is the suite's own.)
 *
 * The inversion's cost: an edge whose azimuth range lies wholly below phi
 * adds its whole term, one above adds nothing, so only the one or two arcs
 * that cover phi take trigonometry (one sincos of phi for all, one atan2
 * each); the start is the linear interpolation of A between the vertices'
 * azimuths next to the target (A at each vertex is set up per pixel), which
 * also brackets the root, and the iteration stops once |A - target| is
 * within one ulp of the sum of A's terms (the rounding of A itself: a thin
 * polygon near the horizon is a difference of arcs many times its area). */
#define LB_MC_PV 4 /* edges of the sampled polygon (the rectangle the horizon leaves) */

typedef struct {
    real ax[LB_MC_PV], ay[LB_MC_PV], az[LB_MC_PV]; /* the edge's endpoint at its lower azimuth */
    real bx[LB_MC_PV], by[LB_MC_PV], bz[LB_MC_PV]; /* unit tangent of the great circle there */
    real mx[LB_MC_PV], my[LB_MC_PV], mz[LB_MC_PV]; /* unit normal a x b */
    real lo[LB_MC_PV], hi[LB_MC_PV];              /* the edge's unwrapped azimuth range */
    real th[LB_MC_PV], w[LB_MC_PV];               /* arc angle; +-|m_z| / 2 (0 for no area) */
    real vphi[LB_MC_PV], va[LB_MC_PV];            /* vertex k's unwrapped azimuth, A there */
    real pmin, pmax;                              /* the region's azimuth range */
    real area;                                    /* projected solid angle (sr) */
    real mag;                                     /* sum of |w th|: the scale of A's rounding */
} lb_mc_proj;

/* A(phi) (a), its derivative (da), the squared radii of the inner / outer
 * boundary at phi (rin2 = 0 where no inner arc covers phi), cos and sin of
 * phi (c, s). */
typedef struct {
    real a, da, rin2, rout2, c, s;
} lb_mc_proj_eval;

/* The evaluation at azimuth phi (in pmin .. pmax). */
LB_FN void lb_mc_proj_at(const lb_mc_proj* p, real phi, lb_mc_proj_eval* ev)
{
    real cf, sf = LB_MC_SINCOS(phi, &cf);
    real a = R(0), da = R(0), ri = R(0), ro = R(0);
    for (int k = 0; k < LB_MC_PV; ++k) {
        bool cover = phi >= p->lo[k] && phi <= p->hi[k] && p->w[k] != R(0);
        /* the arc's angle up to phi: all of it below phi, none above */
        real t = phi > p->hi[k] ? p->th[k] : R(0), r2 = R(0);
        if (cover) {
            /* the great circle's point at azimuth phi: m x (-sin phi, cos
             * phi, 0), signed to point along (cos phi, sin phi) */
            real cx = -p->mz[k] * cf, cy = -p->mz[k] * sf, cz = p->mx[k] * cf + p->my[k] * sf;
            real sg = cx * cf + cy * sf >= R(0) ? R(1) : R(-1);
            cx *= sg, cy *= sg, cz *= sg;
            t = atan2(cx * p->bx[k] + cy * p->by[k] + cz * p->bz[k], cx * p->ax[k] + cy * p->ay[k] + cz * p->az[k]);
            t = clamp(t, R(0), p->th[k]);
            real c2 = cx * cx + cy * cy + cz * cz;
            r2 = c2 > R(0) ? (cx * cx + cy * cy) / c2 : R(0);
        }
        a += p->w[k] * t;
        da += cover ? (p->w[k] > R(0) ? R(0.5) : R(-0.5)) * r2 : R(0);
        ro = cover && p->w[k] > R(0) ? fmax(ro, r2) : ro;
        ri = cover && p->w[k] < R(0) ? fmax(ri, r2) : ri;
    }
    ev->a = a, ev->da = da, ev->rin2 = ri, ev->rout2 = ro, ev->c = cf, ev->s = sf;
}

/* Set-up from the polygon's vertices q[0..4) in the receiver's frame (z along
 * the receiver normal), in order (either orientation), all with z >= 0. */
LB_FN lb_mc_proj lb_mc_proj_setup(const real3* q)
{
    lb_mc_proj p;
    real3 d[LB_MC_PV];
    for (int k = 0; k < LB_MC_PV; ++k)
        d[k] = normalize(q[k]);
    real psi = atan2(d[0].y, d[0].x);
    real signedArea = R(0);
    p.mag = R(0);
    p.pmin = psi;
    p.pmax = psi;
    for (int k = 0; k < LB_MC_PV; ++k) {
        real3 s = d[k], e = d[(k + 1) % LB_MC_PV];
        real dlt = atan2(s.x * e.y - s.y * e.x, s.x * e.x + s.y * e.y);
        real next = psi + dlt;
        bool up = dlt >= R(0);
        p.vphi[k] = psi;
        p.lo[k] = up ? psi : next;
        p.hi[k] = up ? next : psi;
        real3 a = up ? s : e, f = up ? e : s;
        real3 c = cross(a, f);
        real lc = length(c);
        p.th[k] = atan2(lc, dot(a, f));
        real3 m = lc > R(0) ? c / lc : R3(0, 0, 0);
        real3 b = cross(m, a);
        p.ax[k] = a.x, p.ay[k] = a.y, p.az[k] = a.z;
        p.bx[k] = b.x, p.by[k] = b.y, p.bz[k] = b.z;
        p.mx[k] = m.x, p.my[k] = m.y, p.mz[k] = m.z;
        /* swept from a to f: counter-clockwise (dlt >= 0) when m_z >= 0 */
        p.w[k] = (up ? R(0.5) : R(-0.5)) * fabs(m.z);
        signedArea += p.w[k] * p.th[k];
        p.mag += fabs(p.w[k] * p.th[k]);
        psi = next;
        p.pmin = fmin(p.pmin, psi);
        p.pmax = fmax(p.pmax, psi);
    }
    /* orientation: outer arcs count positive */
    for (int k = 0; k < LB_MC_PV; ++k)
        p.w[k] = signedArea < R(0) ? -p.w[k] : p.w[k];
    p.area = fabs(signedArea);
    for (int k = 0; k < LB_MC_PV; ++k) {
        lb_mc_proj_eval ev;
        lb_mc_proj_at(&p, p.vphi[k], &ev);
        p.va[k] = ev.a;
    }
    return p;
}

#define LB_MC_NEWTON 12 /* most evaluations of the azimuth inversion */

/* The inversion's start phi for the target area: the vertices' azimuths next
 * to it bracket the root (*lo, *hi), A is interpolated linearly between them. */
LB_FN real lb_mc_proj_start(const lb_mc_proj* p, real target, real* lo, real* hi)
{
    real l = p->pmin, h = p->pmax, al = R(0), ah = p->area;
    for (int k = 0; k < LB_MC_PV; ++k) {
        real vp = p->vphi[k], va = p->va[k];
        bool below = va <= target;
        bool nl = below && vp > l, nh = !below && vp < h;
        l = nl ? vp : l, al = nl ? va : al;
        h = nh ? vp : h, ah = nh ? va : ah;
    }
    /* a vertex's A rounded across the target's: the whole range */
    bool ok = l <= h;
    l = ok ? l : p->pmin, al = ok ? al : R(0);
    h = ok ? h : p->pmax, ah = ok ? ah : p->area;
    *lo = l;
    *hi = h;
    return ah > al ? l + (h - l) * LB_MC_CLAMP((target - al) / (ah - al), R(0), R(1)) : R(0.5) * (l + h);
}

/* The direction (receiver frame, unit) for (u0, u1) in [0,1)^2, distributed
 * with density cos(theta) / p->area in solid angle over the polygon. */
LB_FN real3 lb_mc_proj_sample(const lb_mc_proj* p, real u0, real u1)
{
    real target = u0 * p->area, tol = lb_real_eps() * p->mag;
    real lo, hi;
    real phi = lb_mc_proj_start(p, target, &lo, &hi);
    lb_mc_proj_eval ev;
    for (int it = 1;; ++it) {
        lb_mc_proj_at(p, phi, &ev);
        real g = ev.a - target;
        if (it == LB_MC_NEWTON || fabs(g) <= tol)
            break;
        lo = g <= R(0) ? phi : lo;
        hi = g > R(0) ? phi : hi;
        real next = ev.da > R(0) ? phi - g / ev.da : R(0.5) * (lo + hi);
        phi = next >= lo && next <= hi ? next : R(0.5) * (lo + hi);
    }
    real r2 = mix(ev.rin2, ev.rout2, u1);
    real rho = sqrt(r2);
    return R3(rho * ev.c, rho * ev.s, sqrt(fmax(R(0), R(1) - r2)));
}
