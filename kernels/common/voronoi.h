/* voronoi.h -- Voronoi-cell cubature weights (thesis 5.1). Compiles as OpenCL
 * C and C++ (see vec.h).
 *
 * Samples on the rectangular light of size w x l, in its plane coordinates
 * (s, t) centred on it: the four corners (in lb_light_corners order), the
 * barycentre and one dynamic point p. Each sample's weight is the area of its
 * planar Voronoi cell on the rectangle divided by the rectangle's area: the
 * thesis precomputed these areas in a texture over p's position (the host
 * builds that table with this code, the kernel looks it up), and used them
 * as fractions of the light's solid angle, E = Omega_L sum_i frac_i L_i G_i
 * (thesis Eq. 5.4 with |T_i| ~ frac_i Omega_L: the planar cells, not the
 * projected ones, the approximation the thesis names).
 * Coincident samples (p on a corner or the barycentre) share their cell
 * equally. */

#define LB_VOR_SITES 6

LB_FN void lb_voronoi_sites(real2 p, real w, real l, real2* s)
{
    s[0] = R2(-R(0.5) * w, -R(0.5) * l);
    s[1] = R2(R(0.5) * w, -R(0.5) * l);
    s[2] = R2(R(0.5) * w, R(0.5) * l);
    s[3] = R2(-R(0.5) * w, R(0.5) * l);
    s[4] = R2(R(0), R(0));
    s[5] = p;
}

/* frac[0..6): cell area fractions of the six sites for the dynamic point p. */
LB_FN void lb_voronoi_fractions(real2 p, real w, real l, real* frac)
{
    real2 s[LB_VOR_SITES];
    lb_voronoi_sites(p, w, l, s);
    real tol = R(1e-6) * (w + l);
    for (int i = 0; i < LB_VOR_SITES; ++i) {
        real3 c[LB_MAXV];
        c[0] = R3(-R(0.5) * w, -R(0.5) * l, R(0));
        c[1] = R3(R(0.5) * w, -R(0.5) * l, R(0));
        c[2] = R3(R(0.5) * w, R(0.5) * l, R(0));
        c[3] = R3(-R(0.5) * w, R(0.5) * l, R(0));
        int n = 4, mult = 1;
        for (int j = 0; j < LB_VOR_SITES && n > 0; ++j) {
            if (j == i)
                continue;
            real2 d = s[i] - s[j];
            if (length(d) <= tol) {
                ++mult; /* coincident: the same cell, shared */
                continue;
            }
            /* keep the points nearer to s_i: x . d >= (s_i + s_j)/2 . d */
            n = lb_clip_polygon(c, n, R3(d.x, d.y, R(0)), dot((s[i] + s[j]) * R(0.5), d));
        }
        frac[i] = n >= 3 ? length(lb_polygon_vector_area(c, n)) / (w * l * (real)mult) : R(0);
    }
}

/* The table the kernel reads: res x res nodes over the dynamic point's
 * position (a, b) in [0, 1]^2 on the light (s = (a - 1/2) w, t = (b - 1/2) l),
 * six fractions per node: tab[(jb * res + ia) * 6 + k]. Bilinear lookup;
 * the host fills it with lb_voronoi_fractions at the nodes. */
LB_FN void lb_voronoi_lookup(__global const float* tab, int res, real a, real b, real* frac)
{
    real fa = clamp(a, R(0), R(1)) * (real)(res - 1);
    real fb = clamp(b, R(0), R(1)) * (real)(res - 1);
    int ia = LB_IMIN((int)fa, res - 2), ib = LB_IMIN((int)fb, res - 2);
    real ta = fa - (real)ia, tb = fb - (real)ib;
    __global const float* r0 = tab + (ib * res + ia) * LB_VOR_SITES;
    __global const float* r1 = r0 + res * LB_VOR_SITES;
    for (int k = 0; k < LB_VOR_SITES; ++k)
        frac[k] = mix(mix((real)r0[k], (real)r0[k + LB_VOR_SITES], ta), mix((real)r1[k], (real)r1[k + LB_VOR_SITES], ta),
                      tb);
}

/* Voronoi cubature irradiance (lux) at x (thesis 5.1): samples = corners,
 * barycentre and the closest point on the (unclipped) light, weights = the
 * tabulated cell fractions times the light's solid angle,
 *   E = Omega_L sum_k frac_k L_k max(0, nx . w_k).
 * The table is for the whole rectangle (the thesis' limitation): a light cut
 * by the receiver's horizon keeps its full solid angle and its samples below
 * the horizon count 0 (never the case in the normalized scene). plane_eps as
 * in the cubature (paper 5.3). */
LB_FN real lb_voronoi_irradiance(__global const float* lum, __global const float* tab, int res, lb_light L, real3 x,
                                 real3 nx, real plane_eps)
{
    real s0 = dot(L.n, x - L.c);
    if (fabs(s0) < plane_eps)
        x += L.n * ((s0 >= R(0) ? plane_eps : -plane_eps) - s0);
    real3 p[LB_MAXV];
    lb_light_corners(L, p);
    for (int i = 0; i < 4; ++i)
        p[i] -= x;
    int where;
    real3 cp = lb_closest_point_polygon(p, 4, L.n, R3(0, 0, 0), &where);
    real3 c = L.c - x;
    real frac[LB_VOR_SITES];
    lb_voronoi_lookup(tab, res, dot(cp - c, L.u) / L.w + R(0.5), dot(cp - c, L.v) / L.l + R(0.5), frac);
    p[4] = c;
    p[5] = cp;
    real e = R(0);
    for (int k = 0; k < LB_VOR_SITES; ++k) {
        real g = dot(nx, p[k]) / length(p[k]);
        if (g > R(0) && frac[k] > R(0))
            e += frac[k] * g * lb_radiance_from(lum, L, p[k]);
    }
    return lb_polygon_solid_angle(p, 4) * e;
}

/* The straight-line form for one pixel (lb_voronoi_rect): voronoi_lanes.inc. */
#include "lanes1.h"
#include "voronoi_lanes.inc"
#include "lanes_end.h"
