/* entry.h -- the render kernels' entry, written once: their signature, the
 * general kernel's opening, a straight-line form's opening, and the
 * reference kernels' opening and stores. OpenCL only (the kernel files include
 * it after lbmath.h).
 *
 * Every render kernel takes the registry's arguments (host/methods/registry.h)
 * P, lum, out, row0, then its family's own: a kernel file defines
 * LB_ENTRY_ARGS as those (each after a comma, e.g. `, real skew`; empty
 * where there are none; Family::args names them,
 * Runtime.EveryKernelFileBuildsWithEveryVariant holds the two alike) before
 * it opens the kernel with LB_RENDER_KERNEL.
 *
 * The general kernel, one pixel per work-item (the rows row0 .. row0 +
 * global height), opens with LB_RENDER_RECEIVER: the pixel's index px in
 * out, the scene's light L, the receiver point x and its normal nx
 * (lb_work_item_receiver); a work-item without a pixel returns.
 *
 * A straight-line form runs on one or eight pixels of a row per work-item:
 * common/entry_straight.inc is the whole kernel, from the form's value
 * LB_ENTRY_FORM; a kernel that needs more (cubature.cl, mc.cl) is written
 * between common/lanes_kernel.h and lanes_end.h and opens with
 * LB_RENDER_PIXELS: columns col0 .. col0 + LB_NLANES - 1 of `row` in the
 * res x res image, their offsets ou, ov, on (LB_V) from the light's corner
 * and the receiver normal au, av, an in the light's frame
 * (lb_work_item_pixels); LB_STORE (lanes1.h) writes their values. */
#define LB_RENDER_KERNEL                                                                                       \
    __kernel void render(__global const real* P, __global const float* lum, __global real* out,               \
                         int row0 LB_ENTRY_ARGS)

#define LB_RENDER_RECEIVER                                                                                     \
    int px;                                                                                                    \
    lb_light L;                                                                                                \
    real3 x, nx;                                                                                               \
    if (!lb_work_item_receiver(P, row0, &px, &L, &x, &nx))                                                     \
    return

#define LB_RENDER_PIXELS                                                                                       \
    int col0, row, res;                                                                                        \
    LB_VFN(lb_rect_span) pix_span;                                                                             \
    LB_VFN(lb_rect_view) pix_view;                                                                             \
    if (!LB_VFN(lb_work_item_pixels)(P, row0, &col0, &row, &res, &pix_span, &pix_view))                       \
    return

/* LB_RENDER_PIXELS with the plane shift by eps on the pixels that lie on
 * the light (common/scene.h lb_plane_shift_on_light): a straight-line form
 * of a family without a plane_eps tunable defines LB_ENTRY_PLANE_EPS
 * (LB_PLANE_EPS) and entry_straight.inc opens with this. */
#define LB_RENDER_PIXELS_OFF_LIGHT(eps)                                                                        \
    LB_RENDER_PIXELS;                                                                                          \
    pix_view = LB_VFN(lb_rect_view_at)(                                                                        \
        LB_VFN(lb_pixels_off_light)(P, col0, row, pix_span.u0, pix_span.v0, pix_view.h, eps), pix_view.au,    \
        pix_view.av, pix_view.an, pix_view.inv_area)

/* The cubature kernel's arguments (cubature.cl), which sh.cl's kernel also
 * takes (its fallback is that kernel): stats, 2 ints per pixel of the whole
 * image (triangles, flips), written when want_stats != 0, then the
 * continuous tunables (common/cubature.h LB_CUB_TUNABLES), one real each. */
#define LB_CUB_TUNABLE_ARG(name) , real name
#define LB_CUB_ENTRY_ARGS , __global int *stats, int want_stats LB_CUB_TUNABLES(LB_CUB_TUNABLE_ARG)

/* The reference kernels (reference.cl, specular_reference.cl,
 * indirect_reference.cl): one pixel per work-item by an adaptive cubature,
 * their arguments after their own (LB_ENTRY_ARGS ends with
 * LB_REFERENCE_ARGS): errout[pixel] the error estimate, splits_out[pixel]
 * the cell splits made (for the reported counters), rel_tol the target
 * relative error per pixel, max_splits the splits' budget per pixel.
 * LB_REFERENCE_OPENING is LB_RENDER_RECEIVER and the rule's err and
 * splits; LB_REFERENCE_STORE(e, err) writes the pixel's value, its error
 * estimate and splits. */
#define LB_REFERENCE_ARGS , __global real *errout, __global int *splits_out, real rel_tol, int max_splits
#define LB_REFERENCE_OPENING                                                                                   \
    LB_RENDER_RECEIVER;                                                                                        \
    real err;                                                                                                  \
    int splits
#define LB_REFERENCE_STORE(e, err_estimate)                                                                    \
    out[px] = (e);                                                                                             \
    errout[px] = (err_estimate);                                                                               \
    splits_out[px] = splits
