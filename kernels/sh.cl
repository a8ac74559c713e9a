/* sh.cl -- the analytic spherical-harmonics method (docs/design.md section 4):
 * the luminaire's radiance fitted once in real SH of degree LB_SH_L per
 * hemisphere of the light (host/methods/sh_fit.h), times the receiver cosine
 * (degree LB_SH_L + 1, projected per scene on the host), integrated exactly
 * over the horizon-clipped light's spherical polygon (common/sh.h): the
 * geometry is exact at any distance, the only error the fit's band limit.
 * zc: the scene's zonal lobes, the front hemisphere's (pixels in front of
 * the light) then the back's, each in common/sh.h's layout. E below 0 (the
 * fit's ringing) is clamped to 0. far_size (radians): where the light's
 * diagonal subtends less than twice it, E blends into engine.cl's exact
 * form factor times the table's radiance toward the centre (the far field,
 * where the fit's error in the one direction the light is seen from would
 * stay while every other method converges, and where a tiny polygon's edge
 * sum cancels in float); fully there below far_size. lum: the exact table.
 *
 *   LB_SH_L=n        the fit's degree, 0 .. 20 (host: L)
 *   LB_SH_FALLBACK   the fit's error exceeds the threshold (sh:fallback=robust):
 *                    robust's kernel (cubature.cl with robust's defines)
 *                    instead; zc and far_size are unused. Its arguments are
 *                    sh's: robust's, then zc and far_size.
 * @variants: "-DLB_SH_L=0" | "-DLB_SH_L=1" | "-DLB_SH_L=8" | "-DLB_SH_L=16" | "-DLB_SH_L=8 -DLB_LUT" | "-DLB_SH_FALLBACK -DLB_LUT -DLB_CUB_AREA=3" | "-DLB_SH_FALLBACK -DLB_LUT -DLB_CUB_AREA=3 -DLB_CUB_RECT_FAN -DLB_LANES=8"
 */
/* sh's arguments after robust's (LB_CUB_ENTRY_ARGS), in both kernels */
#define CUB_EXTRA_ARGS , __global const real *zc, real far_size
#ifdef LB_SH_FALLBACK
#include "cubature.cl"
#else
#include "common/lbmath.h"
#include "common/entry.h"

#ifndef LB_SH_L
#define LB_SH_L 8
#endif
#define LB_ENTRY_ARGS LB_CUB_ENTRY_ARGS CUB_EXTRA_ARGS

/* One work-item per pixel; robust's arguments (stats .. the tunables) are
 * unused. */
LB_RENDER_KERNEL
{
    (void)stats;
    (void)want_stats;
    LB_RENDER_RECEIVER;
    x = lb_plane_shift_on_light(L, x, LB_PLANE_EPS);
    const int nb = LB_SH_L + 2, nd = 2 * LB_SH_L + 4; /* host/methods/sh_fit.h shBands, shDirs */
    real3 p[LB_MAXV];
    int m = lb_clipped_light(L, x, nx, p);
    real e = R(0);
    if (m >= 3) {
        /* the far field: where the light's diagonal subtends less than 2 far_size
         * (radians) the exact table toward the centre times the form factor
         * (engine.cl) takes over, fully below far_size */
        real3 pc = L.c - x;
        real size = sqrt(L.w * L.w + L.l * L.l) / length(pc);
        real t = clamp((R(2) * far_size - size) / far_size, R(0), R(1));
        real esh = R(0), efar = R(0);
        /* the emission direction's hemisphere: in front of the light (gamma < 90) or behind */
        int side = dot(x - L.c, L.n) > R(0) ? 0 : 1;
        if (t < R(1))
            esh = fmax(R(0), lb_sh_polygon(p, m, zc + side * (3 * nd + nb * nd), nb, nd));
        if (t > R(0))
            efar = lb_radiance_from(lum, L, pc) * lb_polygon_irradiance_lambert(p, m, nx);
        e = (R(1) - t) * esh + t * efar;
    }
    out[px] = e;
}
#endif
