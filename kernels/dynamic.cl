/* dynamic.cl -- single-sample baselines (DESIGN section 4):
 *   -DLB_DYN_POINT  one photometric point light at the light's centroid,
 *                   area form E = I(d) max(0, cos) / r^2;
 *   -DLB_DYN_CP / -DLB_DYN_NP / -DLB_DYN_MRP  one dynamic sample (paper 4.2,
 *                   thesis 4.2) on the horizon-clipped light, with the
 *                   structured estimator at N = 1: E = Omega_L L_e(d) cos.
 * @variants: "-DLB_DYN_POINT" | "-DLB_DYN_CP" | "-DLB_DYN_NP" | "-DLB_DYN_MRP"
 */
#include "common/lbmath.h"

/* One work-item per pixel of rows row0 .. row0 + global height. skew: the NP
 * skew of lb_normal_point (only NP and MRP read it). */
__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0, real skew)
{
    int col = get_global_id(0);
    int row = row0 + (int)get_global_id(1);
    int res = (int)P[15];
    if (col >= res || row >= res)
        return;
    lb_light L = lb_scene_light(P);
    real3 x = lb_pixel_position(P, row, col);
    real3 nx = lb_p3(P, 16);
    real e = R(0);
#ifdef LB_DYN_POINT
    real3 pc = L.c - x;
    real r2 = dot(pc, pc);
    real cosx = fmax(R(0), dot(nx, pc)) / sqrt(r2);
    e = lb_intensity_local(lum, lb_to_light_frame(L, -pc)) * cosx / r2;
#else
    real3 p[LB_MAXV];
    int m = lb_clipped_light(L, x, nx, p);
    if (m >= 3) {
        int where = 0;
        real3 s = lb_closest_point_polygon(p, m, L.n, R3(0, 0, 0), &where);
#if defined(LB_DYN_NP) || defined(LB_DYN_MRP)
        real3 np = lb_normal_point(p, m, L.n, nx, skew);
#ifdef LB_DYN_NP
        s = np;
#else
        s = lb_mrp(p, m, L.n, s, np);
#endif
#endif
        real omega = lb_polygon_solid_angle(p, m);
        real cosx = fmax(R(0), dot(nx, normalize(s)));
        e = omega * lb_radiance_from(lum, L, s) * cosx;
    }
#endif
    out[row * res + col] = e;
}
