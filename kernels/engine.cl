/* engine.cl -- the game engines' rect-light baseline (docs/design.md section 4):
 * the exact form factor Phi of the horizon-clipped light (Lambert / Baum,
 * common/spherical.h; on a disk Phi of its visible part, common/disk.h) times
 * the luminaire's radiance g = I(d_c) / (A |cos gamma_c|) toward the light's
 * centre: E = Phi g(d_c). What Unreal ships for a rect light with an IES
 * profile. Exact for a Lambertian emitter (g is then constant).
 * Straight-line form (common/engine_lanes.inc; the host decides,
 * methods/straight.h): LB_ENG_RECT where nothing is clipped, one pixel per
 * work-item, or with LB_LANES=8 and LB_LUT in float eight.
 * @variants: "" | "-DLB_LUT" | "-DLB_ENG_RECT" | "-DLB_ENG_RECT -DLB_LUT" | "-DLB_ENG_RECT -DLB_LUT -DLB_LUT_1D" | "-DLB_ENG_RECT -DLB_LUT -DLB_LANES=8"
 */
#include "common/lbmath.h"

#define LB_ENG_CALL(s) lb_engine_rect##s(lum, P, ou, ov, on, au, av, an)

#if defined(LB_ENG_RECT) && defined(LB_LANES) && LB_LANES == 8 && !defined(LB_DOUBLE)
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
    lb_store_x8(out, row * res + col0, res - col0, LB_ENG_CALL(_x8));
}
#elif defined(LB_ENG_RECT)
__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0)
{
    int col, row, res;
    real ou, ov, on, au, av, an;
    if (!lb_work_item_pixels(P, row0, &col, &row, &res, &ou, &ov, &on, &au, &av, &an))
        return;
    on = lb_pixels_off_plane(P, col, row, on, LB_PLANE_EPS);
    out[row * res + col] = LB_ENG_CALL();
}
#else
/* One work-item per pixel of rows row0 .. row0 + global height. */
__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0)
{
    int px;
    lb_light L;
    real3 x, nx;
    if (!lb_work_item_receiver(P, row0, &px, &L, &x, &nx))
        return;
    x = lb_plane_shift(L, x, LB_PLANE_EPS);
    real e = R(0);
    if (L.shape == LB_SHAPE_DISK) {
        lb_disk_view w = lb_disk_visible_arc(L, x, nx);
        if (w.vis)
            e = lb_radiance_from(lum, L, L.c - x) * lb_disk_phi(L, x, nx, w);
    } else {
        real3 p[LB_MAXV];
        int m = lb_clipped_light(L, x, nx, p);
        if (m >= 3)
            e = lb_radiance_from(lum, L, L.c - x) * lb_polygon_irradiance_lambert(p, m, nx);
    }
    out[px] = e;
}
#endif
