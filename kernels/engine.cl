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
#include "common/entry.h"

#define LB_ENTRY_ARGS

#define LB_ENTRY_PLANE_EPS LB_PLANE_EPS
#ifdef LB_ENG_RECT
#define LB_ENTRY_FORM LB_VFN(lb_engine_rect)(lum, &pix_span, &pix_view)
#include "common/entry_straight.inc"
#else
LB_RENDER_KERNEL
{
    LB_RENDER_RECEIVER;
    x = lb_plane_shift_on_light(L, x, LB_PLANE_EPS);
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
