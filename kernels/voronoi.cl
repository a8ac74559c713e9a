/* voronoi.cl -- Voronoi-cell cubature of thesis 5.1, one work-item per pixel:
 * corners + barycentre + closest point, weights from the precomputed table
 * (host/methods/voronoi_table.h), math in common/voronoi.h.
 * @variants: ""
 */
#include "common/lbmath.h"

/* P: scene parameters; lum: packed luminaire; tab: res x res x 6 cell
 * fractions for the scene's W x L light; out: N x N lux. */
__kernel void voronoi(__global const real* P, __global const float* lum, __global const float* tab, int res,
                      __global real* out, real plane_eps)
{
    int col = get_global_id(0);
    int row = get_global_id(1);
    int n = (int)P[15];
    if (col >= n || row >= n)
        return;
    lb_light L = lb_scene_light(P);
    out[row * n + col] =
        lb_voronoi_irradiance(lum, tab, res, L, lb_pixel_position(P, row, col), lb_p3(P, 16), plane_eps);
}
