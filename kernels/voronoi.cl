/* voronoi.cl -- Voronoi-cell cubature of thesis 5.1, one work-item per pixel:
 * corners + barycentre + closest point, weights from the precomputed table
 * (host/methods/voronoi_table.h), math in common/voronoi.h.
 * @variants: ""
 */
#include "common/lbmath.h"

/* The registry's convention (host/methods/registry.h): P scene parameters;
 * lum packed luminaire; out N x N lux, rows row0 .. row0 + global height.
 * tab: res x res x 6 cell fractions for the scene's W x L light. */
__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0,
                     __global const float* tab, int res, real plane_eps)
{
    int col = get_global_id(0);
    int row = row0 + (int)get_global_id(1);
    int n = (int)P[15];
    if (col >= n || row >= n)
        return;
    lb_light L = lb_scene_light(P);
    out[row * n + col] =
        lb_voronoi_irradiance(lum, tab, res, L, lb_pixel_position(P, row, col), lb_p3(P, 16), plane_eps);
}
