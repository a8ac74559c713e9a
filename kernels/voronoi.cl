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
#include "common/entry.h"

/* tab: tres x tres x 6 cell fractions for the scene's W x L light. */
#define LB_ENTRY_ARGS , __global const float *tab, int tres, real plane_eps

#ifdef LB_VOR_RECT
#define LB_ENTRY_FORM LB_VFN(lb_voronoi_rect)(lum, tab, tres, &pix_span, &pix_view, plane_eps)
#include "common/entry_straight.inc"
#else
LB_RENDER_KERNEL
{
    LB_RENDER_RECEIVER;
    out[px] = lb_voronoi_irradiance(lum, tab, tres, L, x, nx, plane_eps);
}
#endif
