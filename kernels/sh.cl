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
 * sum cancels in float); fully there below far_size. lum: the exact table
 * (with LB_SH_NEAR robust's LUT).
 *
 *   LB_SH_L=n        the fit's degree, 0 .. 20 (host: L)
 *   LB_SH_FALLBACK   the fit's error exceeds the threshold (sh:fallback=robust):
 *                    robust's kernel (cubature.cl with robust's defines)
 *                    instead; zc and far_size are unused. Its arguments are
 *                    sh's: robust's, then zc and far_size.
 *   LB_SH_NEAR       the per-pixel blend into robust (sh:near > 0): far_size is
 *                    `near` (radians); where the light's diagonal subtends
 *                    less than 2 near, E blends into robust's general one-pixel
 *                    kernel (cubature.cl with robust's structural defines and
 *                    LB_LUT, lum its LUT, called as a function: it writes
 *                    out[px], which the blend reads), fully robust below near; the
 *                    fit's integral runs only where the light subtends more
 *                    than near (docs/studies/sh-engine.md: the fit's error
 *                    stays where robust converges).
 * @variants: "-DLB_SH_L=0" | "-DLB_SH_L=1" | "-DLB_SH_L=8" | "-DLB_SH_L=16" | "-DLB_SH_L=8 -DLB_LUT" | "-DLB_SH_FALLBACK -DLB_LUT -DLB_CUB_AREA=3" | "-DLB_SH_FALLBACK -DLB_LUT -DLB_CUB_AREA=3 -DLB_CUB_RECT_FAN -DLB_LANES=8" | "-DLB_SH_L=8 -DLB_SH_NEAR -DLB_LUT -DLB_CUB_AREA=3" | "-DLB_SH_L=2 -DLB_SH_NEAR -DLB_LUT -DLB_CUB_AREA=3"
 */
#ifdef LB_SH_FALLBACK
#define CUB_EXTRA_ARGS , __global const real *zc, real far_size
#include "cubature.cl"
#else
#ifdef LB_SH_NEAR
/* robust's general kernel, renamed: sh's render calls it for its pixel (it includes common/lbmath.h) */
#define render lb_sh_robust_render
#include "cubature.cl"
#undef render
#else
#include "common/lbmath.h"
#include "common/entry.h"
#endif
/* sh's arguments: robust's (LB_CUB_ENTRY_ARGS), then zc and far_size */
#undef LB_ENTRY_ARGS
#define LB_ENTRY_ARGS LB_CUB_ENTRY_ARGS, __global const real *zc, real far_size

#ifndef LB_SH_L
#define LB_SH_L 8
#endif
#define SH_TUNABLE_PASS(name) , name

/* The fit's integral over the light x sees (p[0..m), clipped), clamped at 0;
 * where the light's diagonal subtends less than 2 far (radians), blended into
 * the exact table toward the centre times the form factor (engine.cl), fully
 * below far; far = 0: no blend. */
LB_FN real lb_sh_pixel(__global const float* lum, lb_light L, real3 x, real3 nx, __global const real* zc, real far)
{
    const int nb = LB_SH_L + 2, nd = 2 * LB_SH_L + 4; /* host/methods/sh_fit.h shBands, shDirs */
    real3 p[LB_MAXV];
    int m = lb_clipped_light(L, x, nx, p);
    if (m < 3) return R(0);
    real3 pc = L.c - x;
    real size = sqrt(L.w * L.w + L.l * L.l) / length(pc);
    real t = far > R(0) ? clamp((R(2) * far - size) / far, R(0), R(1)) : R(0);
    real esh = R(0), efar = R(0);
    /* the emission direction's hemisphere: in front of the light (gamma < 90) or behind */
    int side = dot(x - L.c, L.n) > R(0) ? 0 : 1;
    if (t < R(1)) esh = fmax(R(0), lb_sh_polygon(p, m, zc + side * (3 * nd + nb * nd), nb, nd));
    if (t > R(0)) efar = lb_radiance_from(lum, L, pc) * lb_polygon_irradiance_lambert(p, m, nx);
    return (R(1) - t) * esh + t * efar;
}

/* One work-item per pixel of rows row0 .. row0 + global height; the
 * arguments between want_stats and zc are robust's (the fallback's and
 * LB_SH_NEAR's; unused otherwise). */
LB_RENDER_KERNEL
{
    (void)want_stats;
    LB_RENDER_RECEIVER;
    x = lb_plane_shift_on_light(L, x, LB_PLANE_EPS);
#ifdef LB_SH_NEAR
    /* t: robust's weight, by the angle the light's diagonal subtends (far_size is near) */
    real size = sqrt(L.w * L.w + L.l * L.l) / length(L.c - x);
    real t = clamp((R(2) * far_size - size) / far_size, R(0), R(1));
    real er = R(0), esh = R(0);
    if (t > R(0)) {
        lb_sh_robust_render(P, lum, out, row0, stats, 0 LB_CUB_TUNABLES(SH_TUNABLE_PASS));
        er = out[px];
    }
    if (t < R(1)) esh = lb_sh_pixel(lum, L, x, nx, zc, R(0)); /* robust takes the far field */
    out[px] = (R(1) - t) * esh + t * er;
#else
    (void)stats;
    out[px] = lb_sh_pixel(lum, L, x, nx, zc, far_size);
#endif
}
#endif
