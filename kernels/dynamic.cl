/* dynamic.cl -- single-sample baselines (docs/design.md section 4):
 *   -DLB_DYN_POINT  one photometric point light at the light's centroid,
 *                   area form E = I(d) max(0, cos) / r^2;
 *   -DLB_DYN_CP / -DLB_DYN_NP / -DLB_DYN_MRP  one dynamic sample (paper 4.2,
 *                   thesis 4.2) on the horizon-clipped light, with the
 *                   structured estimator at N = 1: E = Omega_L L_e(d) cos;
 *                   on a disk (LB_SHAPE_DISK) E = L_e(d) Phi, Phi the
 *                   disk's projected solid angle (common/disk.h), since the
 *                   disk has no closed-form solid angle and Phi is exact for a
 *                   constant radiance.
 * Straight-line forms (common/dynamic_lanes.inc; the host decides,
 * methods/straight.h): LB_DYN_RECT with LB_DYN_POINT (any scene) or
 * LB_DYN_CP, LB_DYN_NP, LB_DYN_MRP (nothing clipped), one pixel per
 * work-item, or with LB_LANES=8 and LB_LUT in float eight (the host launches
 * ceil(N / 8) work-items per row).
 * @variants: "-DLB_DYN_POINT" | "-DLB_DYN_CP" | "-DLB_DYN_NP" | "-DLB_DYN_MRP" | "-DLB_DYN_POINT -DLB_DYN_RECT" | "-DLB_DYN_CP -DLB_DYN_RECT -DLB_LUT" | "-DLB_DYN_POINT -DLB_DYN_RECT -DLB_LUT -DLB_LANES=8" | "-DLB_DYN_CP -DLB_DYN_RECT -DLB_LUT -DLB_LANES=8" | "-DLB_DYN_NP -DLB_DYN_RECT" | "-DLB_DYN_MRP -DLB_DYN_RECT -DLB_LUT" | "-DLB_DYN_NP -DLB_DYN_RECT -DLB_LUT -DLB_LANES=8" | "-DLB_DYN_MRP -DLB_DYN_RECT -DLB_LUT -DLB_LANES=8"
 */
#include "common/lbmath.h"

/* LB_DYN_RECT_CALL(fn): the straight-line form fn (or fn_x8) on the pixel's
 * rectangle; np and mrp also take the skew. */
#ifdef LB_DYN_RECT
#if defined(LB_DYN_POINT)
#define LB_DYN_RECT_FN(s) lb_point_rect##s
#elif defined(LB_DYN_CP)
#define LB_DYN_RECT_FN(s) lb_cp_rect##s
#elif defined(LB_DYN_NP)
#define LB_DYN_RECT_FN(s) lb_np_rect##s
#define LB_DYN_SKEW , skew
#elif defined(LB_DYN_MRP)
#define LB_DYN_RECT_FN(s) lb_mrp_rect##s
#define LB_DYN_SKEW , skew
#endif
#ifndef LB_DYN_SKEW
#define LB_DYN_SKEW
#endif
#define LB_DYN_RECT_CALL(s) LB_DYN_RECT_FN(s)(lum, ou, ov, on, P[LB_P_W], P[LB_P_L], au, av, an LB_DYN_SKEW)
#endif

#if defined(LB_DYN_RECT) && defined(LB_LANES) && LB_LANES == 8 && !defined(LB_DOUBLE)
#include "common/lanes8.h"
#include "common/lanes_all.inc"
#include "common/lanes_end.h"

__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0, real skew)
{
    int col0, row, res;
    float8 ou, ov, on;
    real au, av, an;
    if (!lb_work_item_pixels_x8(P, row0, &col0, &row, &res, &ou, &ov, &on, &au, &av, &an))
        return;
    on = lb_pixels_off_plane_x8(P, col0, row, on, LB_PLANE_EPS);
    lb_store_x8(out, row * res + col0, res - col0, LB_DYN_RECT_CALL(_x8));
}
#elif defined(LB_DYN_RECT)
__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0, real skew)
{
    int col, row, res;
    real ou, ov, on, au, av, an;
    if (!lb_work_item_pixels(P, row0, &col, &row, &res, &ou, &ov, &on, &au, &av, &an))
        return;
    on = lb_pixels_off_plane(P, col, row, on, LB_PLANE_EPS);
    out[row * res + col] = LB_DYN_RECT_CALL();
}
#else

/* One work-item per pixel of rows row0 .. row0 + global height. skew: the NP
 * skew of lb_normal_point (only NP and MRP read it). */
__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0, real skew)
{
    int px;
    lb_light L;
    real3 x, nx;
    if (!lb_work_item_receiver(P, row0, &px, &L, &x, &nx))
        return;
    x = lb_plane_shift(L, x, LB_PLANE_EPS);
    real e = R(0);
#ifdef LB_DYN_POINT
    real3 pc = L.c - x;
    real r2 = dot(pc, pc);
    real cosx = fmax(R(0), dot(nx, pc)) / sqrt(r2);
    e = lb_intensity_local(lum, lb_to_light_frame(L, -pc)) * cosx / r2;
#else
    real3 p[LB_MAXV];
    if (L.shape == LB_SHAPE_DISK) {
        lb_disk_view w = lb_disk_visible_arc(L, x, nx);
        if (w.vis) {
            real3 s = lb_disk_cp(L, x, nx, w);
#if defined(LB_DYN_NP) || defined(LB_DYN_MRP)
            int m = lb_disk_hexagon(L, x, nx, p);
            real3 np = m >= 3 ? lb_normal_point(p, m, L.n, nx, skew) : s;
#ifdef LB_DYN_NP
            s = np;
#else
            s = m >= 3 ? lb_mrp(p, m, L.n, s, np) : s;
#endif
#endif
            e = lb_radiance_from(lum, L, s) * lb_disk_phi(L, x, nx, w);
        }
        out[px] = e;
        return;
    }
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
    out[px] = e;
}
#endif
