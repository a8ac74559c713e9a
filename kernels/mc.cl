/* mc.cl -- Monte Carlo integration with one fixed point set for every pixel
 * (MCI-N, thesis 6.5), area form of DESIGN section 1 with N uniform points on
 * the light: E = (1/N) sum_i I(d_i) max(0, n_x . w_i) / r_i^2.
 * st[2i], st[2i+1] in [0,1]^2 are the points' (s, t) along (u, v); the host
 * makes the sets (host/methods/samples.h).
 *
 * Written for speed (issue 9; the straightforward version is kernels/naive.cl):
 * everything is done in the light's orthonormal frame (u, v, n_L), where a
 * sample's offset from the pixel is (ou + W s, ov + L t, on) with ou, ov, on
 * fixed per pixel, so a sample costs two fmas for its position, two for r^2
 * and two for the receiver cosine, in scalar code the loop vectoriser takes.
 *
 * Structural variants (host/methods/specialize.h decides them per scene):
 *   LB_LUT         trig-free intensity table (common/lut.h) instead of the
 *                  exact acos/atan2 + binary-search lookup; `lum` is the LUT
 *   LB_LUT_1D      rotationally symmetric luminaire: 1D table over gamma
 *   LB_NO_HORIZON  the light lies above every receiver's horizon: no max(0, cos)
 *   LB_NO_BACK     the luminaire emits nothing at gamma >= 90 deg: pixels
 *                  behind the light's plane are 0 without a loop
 * @variants: "" | "-DLB_LUT" | "-DLB_LUT -DLB_LUT_1D" | "-DLB_LUT -DLB_NO_HORIZON -DLB_NO_BACK" | "-DLB_NO_HORIZON"
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
    /* Offset of corner (-u, -v) from the pixel, in the light frame. */
    real3 o = L.c - L.u * (R(0.5) * L.w) - L.v * (R(0.5) * L.l) - x;
    real ou = dot(o, L.u), ov = dot(o, L.v), on = dot(o, L.n);
    real w = L.w, l = L.l;
#ifdef LB_NO_BACK
    /* Every direction d = -w to this pixel has d . n_L = -on <= 0. */
    if (on >= R(0)) {
        out[row * res + col] = R(0);
        return;
    }
#endif
    /* Receiver cosine (unnormalised): n_x . w = au (ou + W s) + av (ov + L t) + an on. */
    real au = dot(nx, L.u), av = dot(nx, L.v), an0 = dot(nx, L.n) * on;
    real on2 = on * on;
    real sum = R(0);
    for (int i = 0; i < n; ++i) {
        real wu = ou + w * st[2 * i];
        real wv = ov + l * st[2 * i + 1];
        real r2 = wu * wu + wv * wv + on2;
        real cw = au * wu + av * wv + an0;
#ifdef LB_NO_HORIZON
        real ri = R(1) / sqrt(r2);
#else
        cw = fmax(cw, R(0));
        real ri = r2 > R(0) ? R(1) / sqrt(r2) : R(0);
#endif
        sum += lb_intensity_local(lum, R3(-wu, -wv, -on)) * cw * (ri * ri * ri);
    }
    out[row * res + col] = sum / (real)n;
}
