/* specular_reference.cl -- the converged reference of the specular scene
 * (docs/design.md section 8): common/specref.h's adaptive cubature of the area form,
 * one pixel per work-item, with its per-pixel error estimate.
 * Deterministic: no random numbers, a fixed order of operations.
 * @variants: ""
 */
#include "common/lbmath.h"
#include "common/entry.h"

#define LB_ENTRY_ARGS LB_REFERENCE_ARGS

LB_RENDER_KERNEL
{
    LB_REFERENCE_OPENING;
    lb_adapt_report rep;
    real v = lb_specular_reference(lum, L, x, nx, lb_p3(P, LB_P_EYE), P[LB_P_ALPHA],
                                   lb_adapt_goal_of(rel_tol, max_splits), &rep);
    splits = rep.splits;
    LB_REFERENCE_STORE(v, rep.err);
}
