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
#include "common/entry.h"

/* skew: the NP skew of lb_normal_point (only NP and MRP read it). */
#define LB_ENTRY_ARGS , real skew

#ifdef LB_DYN_RECT
/* The straight-line form: np and mrp also take the skew. */
#if defined(LB_DYN_POINT)
#define LB_DYN_RECT_FN LB_VFN(lb_point_rect)
#elif defined(LB_DYN_CP)
#define LB_DYN_RECT_FN LB_VFN(lb_cp_rect)
#elif defined(LB_DYN_NP)
#define LB_DYN_RECT_FN LB_VFN(lb_np_rect)
#define LB_DYN_SKEW , skew
#elif defined(LB_DYN_MRP)
#define LB_DYN_RECT_FN LB_VFN(lb_mrp_rect)
#define LB_DYN_SKEW , skew
#endif
#ifndef LB_DYN_SKEW
#define LB_DYN_SKEW
#endif
#define LB_ENTRY_PLANE_EPS LB_PLANE_EPS
#define LB_ENTRY_FORM LB_DYN_RECT_FN(lum, &pix_span, &pix_view LB_DYN_SKEW)
#include "common/entry_straight.inc"
#else
LB_RENDER_KERNEL
{
    LB_RENDER_RECEIVER;
    x = lb_plane_shift_on_light(L, x, LB_PLANE_EPS);
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
