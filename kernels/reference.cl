/* reference.cl -- the converged reference of docs/design.md section 1: the area form
 *   E(x) = (1/A) int_light I(d) max(0, n_x . w) / r^2 dA = int_[0,1]^2 f(s, t) ds dt
 * (dA = A ds dt) by globally adaptive cubature, one pixel per work-item.
 *
 * The cubature itself is common/area_ref.h (lb_ref_irradiance), shared with
 * the indirect scene's direct light on walls and ceiling.
 * Each cell of the (s, t) square carries a value (the tensor 4x4
 * Gauss-Legendre rule summed over its 4 children) and an error estimate
 * (|rule on the cell - sum of the rules on its children|). Starting from a
 * 2x2 grid of cells, the cell with the largest error is split into its 4
 * children until the summed error is <= rel_tol * |E| (or the cell store /
 * split budget is spent). Choosing the worst cell globally (QUADPACK style)
 * rather than a per-cell tolerance matters here: the bilinear photometric
 * table is only C0 across its grid lines, the integrand's derivative jumps
 * along curves on the light, and a rule straddling such a curve has an error
 * O(h^3) per cell; a global choice refines along the curve until the O(h^2)
 * total is small, where a per-area criterion would demand h ~ tol.
 * The per-pixel error estimate (sum of the cells' errors) is written to err[].
 * Deterministic: no random numbers, a fixed order of operations.
 * @variants: ""
 */
#include "common/lbmath.h"
#include "common/area_ref.h"
#include "common/entry.h"

/* The reference kernels' arguments (common/entry.h); each cell split costs
 * 4 x 80 integrand evaluations. */
#define LB_ENTRY_ARGS LB_REFERENCE_ARGS

LB_RENDER_KERNEL
{
    LB_REFERENCE_OPENING;
    real e = lb_ref_irradiance(lum, L, x, nx, rel_tol, max_splits, &err, &splits);
    LB_REFERENCE_STORE(e, err);
}
