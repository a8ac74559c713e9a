/* specular_reference.cl -- the converged reference of the specular scene
 * (docs/design.md section 8): common/specref.h's adaptive cubature of the area form,
 * one pixel per work-item, with its per-pixel error estimate.
 * Deterministic: no random numbers, a fixed order of operations.
 * @variants: ""
 */
#include "common/lbmath.h"

__kernel void render(__global const real* P, __global const float* lum, __global real* out, int row0,
                     __global real* errout, __global int* splits_out, real rel_tol, int max_splits)
{
    int px;
    lb_light L;
    real3 x, nx;
    if (!lb_work_item_receiver(P, row0, &px, &L, &x, &nx))
        return;
    lb_adapt_report rep;
    real v = lb_specular_reference(lum, L, x, nx, lb_p3(P, LB_P_EYE), P[LB_P_ALPHA],
                                   lb_adapt_goal_of(rel_tol, max_splits), &rep);
    out[px] = v;
    errout[px] = rep.err;
    splits_out[px] = rep.splits;
}
