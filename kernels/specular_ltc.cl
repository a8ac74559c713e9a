/* specular_ltc.cl -- specular shading of the glossy receiver (paper Sec. 7):
 *   L_s(x, w_o) = Lbar_e * LTC(x, w_o, A)                      (paper Eq. 12)
 * with the energy-equivalent radiance of a diffuse emitter
 *   Lbar_e = int L_e(-w) (w . n_x) dw / G_Omega,  G_Omega = int (w . n_x) dw
 * (Eq. 13-14) over the horizon-clipped light, both integrals by the same
 * estimator (Eq. 15-16), and LTC(...) = norm * int_A D the LTC integral of
 * the whole light polygon (common/ltc.h, the suite's fitted table `ltc`).
 *
 * Structural variants (-D):
 *   LB_LTC_RADIANCE  0 cubature (common/cubature.h lb_cubature_setup: weights
 *                    w_i with sum_i w_i L_i the diffuse estimate and sum_i w_i
 *                    its G_Omega, paper Eq. 15); 1 structured (corners +
 *                    barycentre: sum L_i cos_i / sum cos_i); 2 cp (L_e at the
 *                    closest point); 3 point (L_e towards the light's centre)
 *   LB_CUB_TRI       cubature: 0 fan around CP | 1 Delaunay over CP + barycentre
 *   LB_LTC_EXACT_G   G_Omega exact: the clipped polygon's Lambert irradiance at
 *                    unit radiance (spherical.h) divides the diffuse estimate
 *   LB_LUT           trig-free intensity table (common/lut.h), `lum` is the LUT
 *   LB_LTC_RECT      the straight-line form (radiance=point, or cubature with the
 *                    fan, LB_CUB_RECT_CLIP where the horizon cuts along u;
 *                    common/ltc_lanes.inc),
 *                    one pixel per work-item or, with LB_LANES=8 (float, LUT),
 *                    eight in float8; tests/specular/test_ltc_lanes.cpp holds it
 *                    to the general kernel
 * Continuous tunables (arguments): plane_eps, horizon_eps (cubature, as in
 * kernels/cubature.cl).
 * @variants: "" | "-DLB_LUT" | "-DLB_LUT -DLB_LTC_RADIANCE=3 -DLB_LTC_RECT" | "-DLB_LUT -DLB_LTC_RADIANCE=3 -DLB_LTC_RECT -DLB_LANES=8" | "-DLB_LUT -DLB_LTC_RECT" | "-DLB_LUT -DLB_LTC_RECT -DLB_LANES=8" | "-DLB_LUT -DLB_LTC_RECT -DLB_CUB_RECT_CLIP -DLB_LANES=8" | "-DLB_LUT -DLB_CUB_TRI=1 -DLB_LTC_EXACT_G" | "-DLB_CUB_TRI=1" | "-DLB_LTC_EXACT_G" | "-DLB_LTC_RADIANCE=1" | "-DLB_LTC_RADIANCE=2" | "-DLB_LTC_RADIANCE=3" | "-DLB_LTC_RADIANCE=1 -DLB_LTC_EXACT_G"
 */
#include "common/lbmath.h"
#include "common/entry.h"

#ifndef LB_LTC_RADIANCE
#define LB_LTC_RADIANCE 0
#endif
#ifndef LB_CUB_TRI
#define LB_CUB_TRI LB_CUB_FAN
#endif

#define LB_ENTRY_ARGS , __global const float *ltc, real plane_eps, real horizon_eps

#ifdef LB_LTC_RECT
#define LB_ENTRY_FORM                                                                                          \
    LB_VFN(lb_ltc_rect_shade)(P, lum, ltc, LB_LANE_INDEX + (real)col0, row, &pix_span, &pix_view,             \
                              lb_cub_plain_tunables(plane_eps, horizon_eps))
#include "common/entry_straight.inc"
#else
LB_RENDER_KERNEL
{
    LB_RENDER_RECEIVER;
    real3 wo = normalize(lb_p3(P, LB_P_EYE) - x);
    real alpha = P[LB_P_ALPHA];
    real ls = R(0);
    if (dot(nx, wo) > R(0)) {
        real e = R(0), g = R(0); /* diffuse estimate and its G_Omega */
#if defined(LB_LTC_EXACT_G) || LB_LTC_RADIANCE != 0
        real3 p[LB_MAXV];
        int m = lb_clipped_light(L, x, nx, p);
#endif
#if LB_LTC_RADIANCE == 0
        lb_cub T;
        real w[LB_CUB_MAXS];
        real elam;
        lb_cub_options opt = lb_cub_paper_options();
        opt.triangulation = LB_CUB_TRI;
        opt.dynamic = LB_CUB_TRI == LB_CUB_DELAUNAY ? (LB_CUB_CP | LB_CUB_BARY) : LB_CUB_CP;
        lb_cubature_setup(&T, L, x, nx, opt, lb_cub_plain_tunables(plane_eps, horizon_eps), w, &elam);
        for (int i = 0; i < T.ns; ++i) {
            if (w[i] != R(0))
                e += w[i] * lb_radiance_from(lum, L, T.p[i]);
            g += w[i];
        }
#elif LB_LTC_RADIANCE == 1
        if (m >= 3) {
            real3 b = lb_polygon_centroid(p, m);
            real cb = fmax(R(0), dot(nx, normalize(b)));
            real sum = lb_radiance_from(lum, L, b) * cb, cs = cb;
            for (int i = 0; i < m; ++i) {
                real ci = fmax(R(0), dot(nx, normalize(p[i])));
                sum += lb_radiance_from(lum, L, p[i]) * ci;
                cs += ci;
            }
            real om = lb_polygon_solid_angle(p, m) / (real)(m + 1);
            e = om * sum;
            g = om * cs;
        }
#elif LB_LTC_RADIANCE == 2
        if (m >= 3) {
            int where = 0;
            real3 s = lb_closest_point_polygon(p, m, L.n, R3(0, 0, 0), &where);
            real k = lb_polygon_solid_angle(p, m) * fmax(R(0), dot(nx, normalize(s)));
            e = k * lb_radiance_from(lum, L, s);
            g = k;
        }
#else
        {
            real3 pc = L.c - x;
            real r2 = dot(pc, pc);
            real cosx = fmax(R(0), dot(nx, pc)) / sqrt(r2);
            /* E = I cos / r^2 = L_e(centre) * (A |n_L . d| / r^2) cos: G of
             * the point light is its solid angle times cos */
            real k = L.w * L.l * fabs(dot(L.n, pc)) / (r2 * sqrt(r2)) * cosx;
            e = k * lb_radiance_from(lum, L, pc);
            g = k;
        }
#endif
#ifdef LB_LTC_EXACT_G
        g = m >= 3 ? lb_polygon_irradiance_lambert(p, m, nx) : R(0);
#endif
        real lbar = g > R(0) ? e / g : R(0);
        if (lbar > R(0)) {
            real3 q[4];
            lb_light_corners(L, q);
            for (int i = 0; i < 4; ++i)
                q[i] -= x;
            ls = lbar * lb_ltc_brdf_polygon(ltc, q, 4, nx, wo, alpha);
        }
    }
    out[px] = ls;
}
#endif
