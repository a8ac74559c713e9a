/* structured.cl -- structured sampling (paper Eq. 4, thesis 4.1): the corners
 * of the horizon-clipped light plus its barycentre (area centroid), with
 * E = (Omega_L / N) sum_i L_e(d_i) cos_i, L_e(d) = I(d) / (A |n_L . d|).
 * @variants: ""
 */
#include "common/lbmath.h"

__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0)
{
    int col = get_global_id(0);
    int row = row0 + (int)get_global_id(1);
    int res = (int)P[15];
    if (col >= res || row >= res)
        return;
    lb_light L = lb_scene_light(P);
    real3 x = lb_pixel_position(P, row, col);
    real3 nx = lb_p3(P, 16);
    real3 p[LB_MAXV];
    int m = lb_clipped_light(L, x, nx, p);
    real e = R(0);
    if (m >= 3) {
        real3 b = lb_polygon_centroid(p, m);
        real sum = lb_radiance_from(lum, L, b) * fmax(R(0), dot(nx, normalize(b)));
        for (int i = 0; i < m; ++i)
            sum += lb_radiance_from(lum, L, p[i]) * fmax(R(0), dot(nx, normalize(p[i])));
        e = lb_polygon_solid_angle(p, m) * sum / (real)(m + 1);
    }
    out[row * res + col] = e;
}
