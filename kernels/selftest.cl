/* selftest.cl -- runs the shared math on the device so tests can compare it
 * with the same code compiled on the host (tests/cl/test_kernel_math.cpp).
 * @variants: "" | "-DLB_DOUBLE"
 */
#include "common/lbmath.h"

/* One triangle per work-item: tri[9*i .. 9*i+9) = a, b, c; out[i] = solid angle. */
__kernel void tri_solid_angle(__global const real* tri, __global real* out, int n)
{
    int i = get_global_id(0);
    if (i >= n)
        return;
    __global const real* t = tri + 9 * i;
    out[i] = lb_tri_solid_angle(R3(t[0], t[1], t[2]), R3(t[3], t[4], t[5]), R3(t[6], t[7], t[8]));
}

/* For each receiver point q[3*i..]: clip the scene's light to the receiver's
 * horizon (z > 0 half-space seen from q), then out[4*i..] = solid angle,
 * Lambert irradiance, closest point distance, closest point case. */
__kernel void clip_and_measure(__global const real* P, __global const real* q, __global real* out, int n)
{
    int i = get_global_id(0);
    if (i >= n)
        return;
    lb_light L = lb_scene_light(P);
    real3 x = R3(q[3 * i], q[3 * i + 1], q[3 * i + 2]);
    real3 nx = lb_p3(P, LB_P_NX);
    real3 p[LB_MAXV];
    lb_light_corners(L, p);
    for (int k = 0; k < 4; ++k)
        p[k] -= x;
    int m = lb_clip_polygon(p, 4, nx, R(0));
    int where = -1;
    real dist = R(-1);
    if (m >= 1) {
        real3 cp = lb_closest_point_polygon(p, m, L.n, R3(0, 0, 0), &where);
        dist = length(cp);
    }
    out[4 * i + 0] = lb_polygon_solid_angle(p, m);
    out[4 * i + 1] = lb_polygon_irradiance_lambert(p, m, nx);
    out[4 * i + 2] = dist;
    out[4 * i + 3] = (real)where;
}

/* out[i] = intensity at (C, gamma) = (cg[2i], cg[2i+1]) degrees. */
__kernel void intensity(__global const float* lum, __global const real* cg, __global real* out, int n)
{
    int i = get_global_id(0);
    if (i >= n)
        return;
    out[i] = lb_intensity_cg(lum, cg[2 * i], cg[2 * i + 1]);
}
