/* mc.cl -- Monte Carlo integration with one fixed point set for every pixel
 * (MCI-N, thesis 6.5), area form of DESIGN section 1 with N uniform points on
 * the light: E = (1/N) sum_i I(d_i) max(0, n_x . w_i) / r_i^2.
 * st[2i], st[2i+1] in [0,1]^2 are the points' (s, t) along (u, v); the host
 * makes the sets (host/methods/samples.h).
 * @variants: ""
 */
#include "common/lbmath.h"

__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0,
                     __global const real* st, int n)
{
    int col = get_global_id(0);
    int row = row0 + (int)get_global_id(1);
    int res = (int)P[15];
    if (col >= res || row >= res)
        return;
    lb_light L = lb_scene_light(P);
    real3 x = lb_pixel_position(P, row, col);
    real3 nx = lb_p3(P, 16);
    /* Scalar loop: the sample's offset from x is o + s W u + t L v. */
    real3 o = L.c - L.u * (R(0.5) * L.w) - L.v * (R(0.5) * L.l) - x;
    real3 eu = L.u * L.w, ev = L.v * L.l;
    real sum = R(0);
    for (int i = 0; i < n; ++i) {
        real3 w = o + eu * st[2 * i] + ev * st[2 * i + 1];
        real r2 = dot(w, w);
        real cw = dot(nx, w);
        if (cw > R(0) && r2 > R(0))
            sum += lb_intensity_local(lum, lb_to_light_frame(L, -w)) * cw / (r2 * sqrt(r2));
    }
    out[row * res + col] = sum / (real)n;
}
