/* structured.cl -- structured sampling (paper Eq. 4, thesis 4.1): the corners
 * of the horizon-clipped light plus its barycentre (area centroid), with
 * E = (Omega_L / N) sum_i L_e(d_i) cos_i, L_e(d) = I(d) / (A |n_L . d|).
 * On a disk: the corners and barycentre of its inscribed hexagon, E = (Phi / N)
 * sum_i L_e(d_i), Phi the disk's projected solid angle (common/disk.h).
 * Straight-line form (common/dynamic_lanes.inc lb_structured_rect;
 * the host uses it when nothing is clipped, methods/straight.h): LB_STRUCT_RECT,
 * one pixel per work-item, or with LB_LANES=8 and LB_LUT in float eight.
 * @variants: "" | "-DLB_STRUCT_RECT" | "-DLB_STRUCT_RECT -DLB_LUT -DLB_LANES=8"
 */
#include "common/lbmath.h"
#include "common/entry.h"

#define LB_ENTRY_ARGS

#define LB_ENTRY_PLANE_EPS LB_PLANE_EPS
#ifdef LB_STRUCT_RECT
#define LB_ENTRY_FORM LB_VFN(lb_structured_rect)(lum, &pix_span, &pix_view)
#include "common/entry_straight.inc"
#else
LB_RENDER_KERNEL
{
    LB_RENDER_RECEIVER;
    x = lb_plane_shift_on_light(L, x, LB_PLANE_EPS);
    real3 p[LB_MAXV];
    real e = R(0);
    if (L.shape == LB_SHAPE_DISK) {
        /* the inscribed hexagon's (clipped) corners and barycentre, each
         * radiance weighted alike, times the disk's Phi */
        lb_disk_view w = lb_disk_visible_arc(L, x, nx);
        int m = lb_disk_hexagon(L, x, nx, p);
        if (w.vis && m >= 3) {
            real sum = lb_radiance_from(lum, L, lb_polygon_centroid(p, m));
            for (int i = 0; i < m; ++i)
                sum += lb_radiance_from(lum, L, p[i]);
            e = lb_disk_phi(L, x, nx, w) * sum / (real)(m + 1);
        }
        out[px] = e;
        return;
    }
    int m = lb_clipped_light(L, x, nx, p);
    if (m >= 3) {
        real3 b = lb_polygon_centroid(p, m);
        real sum = lb_radiance_from(lum, L, b) * fmax(R(0), dot(nx, normalize(b)));
        for (int i = 0; i < m; ++i)
            sum += lb_radiance_from(lum, L, p[i]) * fmax(R(0), dot(nx, normalize(p[i])));
        e = lb_polygon_solid_angle(p, m) * sum / (real)(m + 1);
    }
    out[px] = e;
}
#endif
