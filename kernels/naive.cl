/* naive.cl -- the deliberately straightforward MC kernel that `lumibench bench`
 * compares mc.cl against. Same arguments and result as mc.cl's
 * render (up to rounding), written the obvious way: float3 arithmetic in
 * world space, normalisation, acos + atan2 and two binary searches of the
 * exact table per sample. Not a method: only the benchmark and its test use it.
 * @variants: ""
 */
#include "common/lbmath.h"
#include "common/entry.h"

#define LB_ENTRY_ARGS , __global const real *st, int n

LB_RENDER_KERNEL
{
    LB_RENDER_RECEIVER;
    real3 corner = L.c - L.u * (R(0.5) * L.w) - L.v * (R(0.5) * L.l);
    real sum = R(0);
    for (int i = 0; i < n; ++i) {
        real3 p = corner + L.u * (L.w * st[2 * i]) + L.v * (L.l * st[2 * i + 1]);
        real3 wv = p - x;
        real r = length(wv);
        real3 w = wv / r;
        real cw = dot(nx, w);
        if (cw > R(0)) {
            real3 d = -w;
            real gamma = acos(clamp(dot(d, L.n), R(-1), R(1))) * LB_DEG;
            real c = atan2(dot(d, L.v), dot(d, L.u)) * LB_DEG;
            if (c < R(0))
                c += R(360);
            sum += lb_intensity_cg(lum, c, gamma) * cw / (r * r);
        }
    }
    out[px] = sum / (real)n;
}
