/* voronoi.cl -- Voronoi-cell cubature of thesis 5.1: corners + barycentre +
 * closest point, weights from the precomputed table
 * (host/methods/voronoi_table.h), math in common/voronoi.h.
 *
 * Structural variants (host/methods/family_voronoi.cpp decides them):
 *   LB_VOR_RECT   the straight-line form (common/voronoi_lanes.inc); the
 *                 general kernel (float3, loops) without it
 *   LB_LANES=8    with LB_VOR_RECT and LB_LUT, float: eight pixels per
 *                 work-item in float8 (the host launches ceil(N / 8) per row)
 *   LB_LUT        trig-free intensity table (common/lut.h), `lum` is the LUT
 * @variants: "" | "-DLB_VOR_RECT" | "-DLB_LUT -DLB_VOR_RECT" | "-DLB_LUT -DLB_VOR_RECT -DLB_LANES=8"
 */
#include "common/lbmath.h"

/* The registry's convention (host/methods/registry.h): P scene parameters;
 * lum packed luminaire; out N x N lux, rows row0 .. row0 + global height.
 * tab: tres x tres x 6 cell fractions for the scene's W x L light. */
#if defined(LB_VOR_RECT) && defined(LB_LANES) && LB_LANES == 8 && !defined(LB_DOUBLE)
#include "common/lanes8.h"
#include "common/lanes_all.inc"
#include "common/lanes_end.h"

__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0,
                     __global const float* tab, int tres, real plane_eps)
{
    int col0, row, res;
    lb_rect_span_x8 sp;
    lb_rect_view_x8 vw;
    if (!lb_work_item_pixels_x8(P, row0, &col0, &row, &res, &sp, &vw))
        return;
    float8 e = lb_voronoi_rect_x8(lum, tab, tres, &sp, &vw, plane_eps);
    lb_store_x8(out, row * res + col0, res - col0, e);
}
#elif defined(LB_VOR_RECT)
__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0,
                     __global const float* tab, int tres, real plane_eps)
{
    int col, row, res;
    lb_rect_span sp;
    lb_rect_view vw;
    if (!lb_work_item_pixels(P, row0, &col, &row, &res, &sp, &vw))
        return;
    out[row * res + col] = lb_voronoi_rect(lum, tab, tres, &sp, &vw, plane_eps);
}
#else
__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0,
                     __global const float* tab, int tres, real plane_eps)
{
    int px;
    lb_light L;
    real3 x, nx;
    if (!lb_work_item_receiver(P, row0, &px, &L, &x, &nx))
        return;
    out[px] = lb_voronoi_irradiance(lum, tab, tres, L, x, nx, plane_eps);
}
#endif
