/* mc.cl -- Monte Carlo integration with one fixed point set for every pixel
 * (MCI-N, thesis 6.5), area form of docs/design.md section 1 with N uniform points on
 * the light: E = (1/N) sum_i I(d_i) max(0, n_x . w_i) / r_i^2.
 * st[2i], st[2i+1] in [0,1]^2 are the points' (s, t) along (u, v); the host
 * makes the sets (host/methods/samples.h).
 *
 * A fractional sample count N + extra (0 <= extra < 1), so that MCI's time can
 * match another method's within a few per cent where one point more is a
 * 25-50 % step (docs/design.md section 6): the share `extra` of the work-group tiles, spread
 * evenly over the image, takes the N + 1 point set stored after the N points
 * (st[2N ..]); the rest the N points. Each pixel is still an MCI-N or
 * MCI-(N+1) estimate, so the image's mean squared error and the time are the
 * mixtures of those two with weights 1 - extra and extra. The count is the
 * same for the whole work-group, as the barrier in the loop requires.
 *
 * Written for speed (the straightforward version is kernels/naive.cl):
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
 *   LB_NO_BACK     the luminaire emits nothing at gamma >= 90 deg: work-groups
 *                  whose tile lies behind the light's plane are 0 without a loop
 * @variants: "" | "-DLB_LUT" | "-DLB_LUT -DLB_LUT_1D -DLB_NO_HORIZON -DLB_NO_BACK"
 */
#include "common/lbmath.h"

/* n_L . (corner(-u,-v) - pixel(col, row)): the pixel lies on or behind the
 * light's plane when >= 0 (the same arithmetic as the kernel's `on`). */
LB_FN real mc_on(__global const real* P, int col, int row)
{
    real ou, ov, on;
    lb_corner_offset(P, (real)col, row, &ou, &ov, &on);
    return on;
}

__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0,
                     __global const real* st, int n, float extra)
{
    int col = get_global_id(0);
    int row = row0 + (int)get_global_id(1);
    int res = (int)P[LB_P_RES];
    /* No per-pixel early return (so not the shared prologue of the other
     * kernels, lb_work_item_receiver): every work-item of a group reaches the
     * barrier below equally often. */
    bool inside = col < res && row < res;
    /* All scalar (common/scene_lanes.inc): float3 values in the loop body
     * stop PoCL's work-item loop vectoriser. Offset of corner (-u, -v) from
     * the pixel, in the light frame. */
    real ou, ov, on;
    lb_corner_offset(P, (real)col, row, &ou, &ov, &on);
    real w = P[LB_P_W], l = P[LB_P_L];
#ifdef LB_NO_BACK
    /* Every direction d = -w to a pixel with on >= 0 has d . n_L <= 0: no
     * light. The barrier below needs the whole work-group to take the same
     * path, so the group skips only when its whole tile lies behind the
     * light's plane: on is linear in the pixel position, so the tile's 4
     * corner pixels decide, computed from group-uniform values only (so
     * every work-item gets the same bits). */
    {
        int c0 = (int)(get_group_id(0) * get_local_size(0));
        int r0 = row0 + (int)(get_group_id(1) * get_local_size(1));
        int c1 = c0 + (int)get_local_size(0) - 1, r1 = r0 + (int)get_local_size(1) - 1;
        real m = fmin(fmin(mc_on(P, c0, r0), mc_on(P, c1, r0)), fmin(mc_on(P, c0, r1), mc_on(P, c1, r1)));
        if (m >= R(0)) {
            if (inside)
                out[row * res + col] = R(0);
            return;
        }
    }
#endif
    /* Receiver cosine (unnormalised): n_x . w = au (ou + W s) + av (ov + L t) + an on. */
    int m = n;
    if (extra > 0.0f) {
        /* tile index, row-major over the whole image (launches come in bands
         * of rows: row0 counts) */
        int ls0 = (int)get_local_size(0), ls1 = (int)get_local_size(1);
        int tile_row = (row0 + (int)(get_group_id(1) * get_local_size(1))) / ls1;
        float g = (float)(tile_row * ((res + ls0 - 1) / ls0) + (int)get_group_id(0));
        if (floor((g + 1.0f) * extra) > floor(g * extra)) {
            st += 2 * n;
            m = n + 1;
        }
    }
    real au, av, an;
    lb_receiver_normal_local(P, &au, &av, &an);
    real an0 = an * on;
    real on2 = on * on;
    real sum = R(0);
    for (int i = 0; i < m; ++i) {
        real wu = ou + w * st[2 * i];
        real wv = ov + l * st[2 * i + 1];
        real r2 = wu * wu + wv * wv + on2;
        real cw = au * wu + av * wv + an0;
#ifdef LB_NO_HORIZON
        real ri = LB_LUT_RSQRT(r2);
#else
        cw = cw > R(0) ? cw : R(0);
        real ri = r2 > R(0) ? LB_LUT_RSQRT(r2) : R(0);
#endif
        sum += LB_INTENSITY3(lum, -wu, -wv, -on) * cw * (ri * ri * ri);
        /* A barrier per sample makes PoCL put its work-item loop inside this
         * one, where LLVM's loop vectoriser runs it across 8 pixels at once
         * (POCL_VECTORIZER_REMARKS=1: "vectorized loop (vectorization width:
         * 8)"); on GPUs it costs little (the whole group runs the same n).
         * Plain arithmetic and selects only: see common/lut.h. */
        barrier(CLK_LOCAL_MEM_FENCE);
    }
    if (inside)
        out[row * res + col] = sum / (real)m;
}
