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

#if defined(LB_STRUCT_RECT) && defined(LB_LANES) && LB_LANES == 8 && !defined(LB_DOUBLE)
#include "common/lanes8.h"
#include "common/lanes_all.inc"
#include "common/lanes_end.h"

__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0)
{
    int col0, row, res;
    float8 ou, ov, on;
    real au, av, an;
    if (!lb_work_item_pixels_x8(P, row0, &col0, &row, &res, &ou, &ov, &on, &au, &av, &an))
        return;
    on = lb_pixels_off_plane_x8(P, col0, row, on, LB_PLANE_EPS);
    lb_store_x8(out, row * res + col0, res - col0, lb_structured_rect_x8(lum, ou, ov, on, P[LB_P_W], P[LB_P_L], au, av, an));
}
#elif defined(LB_STRUCT_RECT)
__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0)
{
    int col, row, res;
    real ou, ov, on, au, av, an;
    if (!lb_work_item_pixels(P, row0, &col, &row, &res, &ou, &ov, &on, &au, &av, &an))
        return;
    on = lb_pixels_off_plane(P, col, row, on, LB_PLANE_EPS);
    out[row * res + col] = lb_structured_rect(lum, ou, ov, on, P[LB_P_W], P[LB_P_L], au, av, an);
}
#else

__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0)
{
    int px;
    lb_light L;
    real3 x, nx;
    if (!lb_work_item_receiver(P, row0, &px, &L, &x, &nx))
        return;
    x = lb_plane_shift(L, x, LB_PLANE_EPS);
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
