/* scene.h -- the light and the image grid of DESIGN section 2, shared by host
 * and kernels. Kernels receive the scene as a small array of reals (one buffer,
 * so float and double kernels take the same argument list):
 *   P[0..3)  light centre      P[3..6)  u (width axis)   P[6..9)  v (length axis)
 *   P[9..12) n_L               P[12] W  P[13] L           P[14] extent S   P[15] resolution N
 *   P[16..19) receiver normal n_x
 * The receiver is the plane z = 0 seen from above. */

#define LB_SCENE_SIZE 20

typedef struct {
    real3 c, u, v, n; /* centre and frame: n_L points where the light emits; v = cross(u, n) */
    real w, l;        /* width along u, length along v */
} lb_light;

LB_FN real3 lb_p3(__global const real* P, int i)
{
    return R3(P[i], P[i + 1], P[i + 2]);
}

LB_FN lb_light lb_scene_light(__global const real* P)
{
    lb_light L;
    L.c = lb_p3(P, 0);
    L.u = lb_p3(P, 3);
    L.v = lb_p3(P, 6);
    L.n = lb_p3(P, 9);
    L.w = P[12];
    L.l = P[13];
    return L;
}

/* Corners in the order (-u,-v), (+u,-v), (+u,+v), (-u,+v). */
LB_FN void lb_light_corners(lb_light L, real3* p)
{
    real3 hu = L.u * (R(0.5) * L.w);
    real3 hv = L.v * (R(0.5) * L.l);
    p[0] = L.c - hu - hv;
    p[1] = L.c + hu - hv;
    p[2] = L.c + hu + hv;
    p[3] = L.c - hu + hv;
}

/* Receiver point at the centre of pixel (row, col), row 0 at the top (+y). */
LB_FN real3 lb_pixel_position(__global const real* P, int row, int col)
{
    real s = P[14];
    real n = P[15];
    return R3(-R(0.5) * s + ((real)col + R(0.5)) * s / n,
              R(0.5) * s - ((real)row + R(0.5)) * s / n,
              R(0));
}

/* Direction d (world) expressed in the luminaire's photometric frame (u, v, n). */
LB_FN real3 lb_to_light_frame(lb_light L, real3 d)
{
    return R3(dot(d, L.u), dot(d, L.v), dot(d, L.n));
}

/* The receiver normal n_x (P[16..19)) in the light's frame (u, v, n_L). */
LB_FN void lb_receiver_normal_local(__global const real* P, real* au, real* av, real* an)
{
    real nxx = P[16], nxy = P[17], nxz = P[18];
    *au = nxx * P[3] + nxy * P[4] + nxz * P[5];
    *av = nxx * P[6] + nxy * P[7] + nxz * P[8];
    *an = nxx * P[9] + nxy * P[10] + nxz * P[11];
}

/* lb_corner_offset(P, col, row, &ou, &ov, &on): scene_lanes.inc. */
#include "lanes1.h"
#include "scene_lanes.inc"
#include "lanes_end.h"

#if defined(__OPENCL_C_VERSION__) && !LB_REAL_IS_DOUBLE
/* Stores the eight pixels e of one row of an 8-lane kernel (lanes8.h) at
 * out[i ..], only the first `left` of them at the row's end. */
LB_FN void lb_store_x8(__global real* out, int i, int left, float8 e)
{
    if (left >= 8) {
        vstore8(e, 0, out + i);
        return;
    }
    float ev[8];
    vstore8(e, 0, ev);
    for (int j = 0; j < left; ++j)
        out[i + j] = ev[j];
}
#endif
