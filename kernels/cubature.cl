/* cubature.cl -- scattered-sampling cubature (paper Sec. 5, thesis 5.2): the
 * general kernel runs lb_cubature_irradiance of common/cubature.h, one
 * work-item per pixel; the straight-line forms (below) are those of
 * common/cubature_lanes.inc, one or eight pixels per work-item.
 *
 * Structural variants (-D, defaults = the paper's method):
 *   LB_CUB_TRI        0 fan around the first dynamic point | 1 delaunay (Lawson flips)
 *   LB_CUB_WEIGHT     0 sample (paper Eq. 9) | 1 average (Eq. 10) | 2 dotout
 *   LB_CUB_NORMALIZE  0 none | 1 formfactor (thesis Eq. 5.11)
 *   LB_CUB_DYNAMIC    bit set of dynamic points: 1 cp, 2 np, 4 mrp, 8 barycentre (0: corners only)
 *   LB_CUB_STATIC     0 .. 4 static samples at the tunables (s_k, t_k) of the light's unit
 *                     square (with dynamic=cp also in the straight-line form LB_CUB_RECT_DELST)
 *   LB_CUB_RECT_FAN   nothing clipped, fan around CP or corner 0 (or Delaunay over corners + CP,
 *                     which never flips there):
 *                     the straight-line lb_cub_rect_fan (host/methods/specialize.h
 *                     decides it per scene)
 *   LB_CUB_RECT_DEL   nothing clipped, Delaunay over corners + CP + barycentre: the
 *                     straight-line lb_cub_rect_del
 *   LB_CUB_RECT_DELALL nothing clipped, receiver normal perpendicular to u, Delaunay over
 *                     corners + CP + NP + MRP + barycentre: the straight-line
 *                     lb_cub_rect_delall
 *   LB_CUB_RECT_DELST nothing clipped, Delaunay over corners + CP + LB_CUB_STATIC static
 *                     samples (each at least 1 % inside the light): the straight-line
 *                     lb_cub_rect_delst: lb_cub_rect_delst1 (one) or lb_cub_rect_delstk (2 to 4)
 *   LB_CUB_RECT_CLIP  with LB_CUB_RECT_FAN or _DEL: the horizon cuts the light, along
 *                     its u edges (receiver normal perpendicular to u, as in every
 *                     normalized scene): the forms run on the rectangle it leaves
 *                     (lb_cub_rect_clip)
 *   LB_CUB_BLEND      with a straight-line form: some pixel lies beyond blend_dist, so
 *                     the far-field blend into the 3 x 3 grid MC is applied
 *                     (lb_cub_rect_blend); without it no pixel blends
 *   LB_LANES=8        with LB_CUB_RECT_FAN or _DEL and LB_LUT, float: eight pixels
 *                     per work-item in float8 (host/methods: lanes; CPUs by default)
 *   LB_LUT            trig-free intensity table (common/lut.h), `lum` is the LUT
 *   LB_CUB_DISK       the disk light (common/disk.h): the fan around the closest point with
 *                     exact sector form factors; with LB_CUB_AREA the polar Gauss rule
 *   LB_CUB_DISK_STRAIGHT with LB_CUB_DISK: the same in straight-line form
 *                     (common/disk_lanes.inc), one pixel or with LB_LANES=8 eight
 *   LB_CUB_AREA=n     blend in the area form by the n x n Gauss-Legendre rule (n = 2, 3;
 *                     common/cubature/clip_blend.inc lb_area_gauss_rect), in every form
 * Continuous tunables (kernel arguments, common/cubature.h LB_CUB_TUNABLES, one
 * lb_cub_tunables per work-item): plane_eps, horizon_eps (metres),
 * corner_inset, dyn_weight (common/cubature.h lb_cubature_irradiance; 0, 1 = plain),
 * blend_dist (m): beyond it the result blends into a 3 x 3 grid MC (lb_blend_weight;
 * fully MC, without the cubature, from 1.5 blend_dist on); area_q, area_sin: with
 * LB_CUB_AREA = n (2 or 3) the n x n Gauss rule of the area form is blended in
 * away from the light and towards its plane (lb_area_weight).
 *
 * @variants: registry (host/methods/specialize.h cubatureVariants: the general
 * kernel's structures, and each straight-line form of the host's form table with and
 * without the LUT, eight lanes, LB_CUB_BLEND, LB_CUB_RECT_CLIP and LB_CUB_AREA; the disk's
 * general kernel and its straight-line form in one and eight lanes, with LB_CUB_AREA)
 */
#include "common/lbmath.h"
#include "common/entry.h"

#ifndef LB_CUB_TRI
#define LB_CUB_TRI LB_CUB_FAN
#endif
#ifndef LB_CUB_WEIGHT
#define LB_CUB_WEIGHT LB_CUB_AVERAGE
#endif
#ifndef LB_CUB_NORMALIZE
#define LB_CUB_NORMALIZE 0
#endif
#ifndef LB_CUB_DYNAMIC
#define LB_CUB_DYNAMIC LB_CUB_CP
#endif

/* The registry's convention (common/entry.h), then the cubature's arguments
 * LB_CUB_ENTRY_ARGS (stats: pass any small buffer where want_stats is 0).
 * Each form of the kernel below opens with this signature and CUB_PROLOGUE. */
#define CUB_TUNABLE_SET(name) tun.name = name;
/* CUB_EXTRA_ARGS: arguments a file that includes this one (sh.cl's fallback)
 * appends to the signature, unused here. */
#ifndef CUB_EXTRA_ARGS
#define CUB_EXTRA_ARGS
#endif
#define LB_ENTRY_ARGS LB_CUB_ENTRY_ARGS CUB_EXTRA_ARGS
/* opt: the structural variant (the -D flags above); tun: the arguments */
#define CUB_PROLOGUE                                                                                           \
    lb_cub_options opt;                                                                                        \
    opt.triangulation = LB_CUB_TRI;                                                                            \
    opt.weighting = LB_CUB_WEIGHT;                                                                             \
    opt.formfactor = LB_CUB_NORMALIZE;                                                                         \
    opt.dynamic = LB_CUB_DYNAMIC;                                                                              \
    opt.nstatic = LB_CUB_STATIC;                                                                               \
    lb_cub_tunables tun;                                                                                       \
    LB_CUB_TUNABLES(CUB_TUNABLE_SET)

/* The straight-line form of the -D define (LB_CUB_RECT_FAN, _DEL, _DELALL,
 * _DELST): its file under common/cubature/ makes it LB_CUB_FORM, called
 * once below with the signature every form has. It runs on the rectangle
 * [ou, ou + W] x [v0c, v0c + lc] at height hc: the light, or with
 * LB_CUB_RECT_CLIP what the horizon leaves of it (lb_cub_rect_clip). rect:
 * that rectangle (lb_rect_span), view: the receiver at hc (lb_rect_view). */
#define CUB_NAME_(name, s) name##s
#define CUB_NAME(name, s) CUB_NAME_(name, s)
#ifdef LB_CUB_RECT_CLIP
#define CUB_CLIP() LB_VFN(lb_cub_rect_clip)(ov, hc, P[LB_P_L], av, an, tun.horizon_eps, &v0c, &lc)
#else
#define CUB_CLIP() (void)0
#endif

#if defined(LB_CUB_FORM) || defined(LB_CUB_DISK_STRAIGHT)
/* One or eight pixels of a row per work-item (common/lanes_kernel.h). */
#include "common/lanes_kernel.h"
#if LB_NLANES == 8
#define CUB_FORM CUB_NAME(LB_CUB_FORM, _x8)
#else
#define CUB_FORM LB_CUB_FORM
#endif
#ifdef LB_CUB_DISK_STRAIGHT
#include "common/disk_lanes.inc"
#endif

/* The pixels' results: e, and with want_stats the (triangles, flips) pairs. */
LB_FN void LB_VFN(cub_store)(__global real* out, __global int* stats, int want_stats, int i, int left, LB_V e,
                             LB_I nt, LB_I nf)
{
#if LB_NLANES == 8
    lb_store_x8(out, i, left, e);
    if (!want_stats)
        return;
    int nv[8], fv[8];
    vstore8(nt, 0, nv);
    vstore8(nf, 0, fv);
    for (int j = 0; j < 8 && j < left; ++j) {
        stats[2 * (i + j)] = nv[j];
        stats[2 * (i + j) + 1] = fv[j];
    }
#else
    (void)left;
    out[i] = e;
    if (want_stats) {
        stats[2 * i] = nt;
        stats[2 * i + 1] = nf;
    }
#endif
}

#ifdef LB_CUB_DISK_STRAIGHT
/* The disk's straight-line form (common/disk_lanes.inc): the same method as
 * the one-pixel disk kernel below, with fixed sectors and nodes for every
 * lane; where every lane takes the area form alone the fan is not run. */
LB_RENDER_KERNEL
{
    CUB_PROLOGUE
    (void)opt;
    LB_RENDER_PIXELS;
    LB_V ou = pix_span.u0, ov = pix_span.v0;
    LB_V on = LB_VFN(lb_pixels_off_plane)(P, col0, row, pix_view.h, tun.plane_eps);
    real au = pix_view.au, av = pix_view.av, an = pix_view.an;
    LB_VFN(lb_dsl_pixel) px = LB_VFN(lb_dsl_pixel_at)(P[LB_P_W], P[LB_P_L], ou, ov, on, au, av, an);
    LB_V e = R(0), ta = R(0);
#ifdef LB_CUB_AREA
    ta = LB_VFN(lb_dsl_area_weight)(&px, tun.area_q, tun.area_sin);
#endif
    if (LB_ANY(ta < R(1)))
        e = LB_VFN(lb_dsl_irradiance)(lum, &px);
    e = ta < R(1) ? e : R(0);
#ifdef LB_CUB_AREA
    if (LB_ANY(ta > R(0))) {
        LB_V g = LB_VFN(lb_dsl_area_gauss)(lum, &px, LB_CUB_AREA);
        e = ta > R(0) ? (R(1) - ta) * e + ta * g : e;
    }
#endif
    LB_I nt = ta < R(1) ? (LB_I)(LB_DISK_FAN) : (LB_I)(0);
    LB_VFN(cub_store)(out, stats, want_stats, row * res + col0, res - col0, e, nt, (LB_I)(0));
}
#else
/* The scene needs no clip (or, with LB_CUB_RECT_CLIP, one along the u
 * edges): without LB_CUB_RECT_CLIP horizon_eps is unused, the host chose
 * the form because it clips nothing. */
LB_RENDER_KERNEL
{
    CUB_PROLOGUE
    LB_RENDER_PIXELS;
    LB_V ou = pix_span.u0, ov = pix_span.v0, on = pix_view.h;
    real au = pix_view.au, av = pix_view.av, an = pix_view.an;
    LB_V hc = LB_VFN(lb_plane_shift_h)(on, LB_VFN(lb_plane_distance)(P, LB_LANE_INDEX + (real)col0, row),
                                        tun.plane_eps);
    LB_V v0c = ov, lc = (LB_V)(P[LB_P_L]);
    CUB_CLIP();
    const real inv_area = R(1) / (P[LB_P_W] * P[LB_P_L]);
    LB_VFN(lb_rect_span) rect = LB_VFN(lb_rect_span_at)(ou, v0c, P[LB_P_W], lc);
    LB_VFN(lb_rect_view) view = LB_VFN(lb_rect_view_at)(hc, au, av, an, inv_area);
    /* the pixels as the blends see the light: at their own height (no plane shift) */
    LB_VFN(lb_rect_view) vw = LB_VFN(lb_rect_view_at)(on, au, av, an, inv_area);
    LB_VFN(lb_cub_count) cnt;
    cnt.want_flips = want_stats;
#ifdef LB_CUB_AREA
    /* the area form's weight; where every lane takes the area form alone the
     * cubature is not evaluated (a far-field row costs only the area rule) */
    LB_V ta = LB_VFN(lb_area_weight)(rect, on, tun.area_q, tun.area_sin);
    LB_V e = R(0);
    cnt.ntri = 0;
    cnt.nflips = 0;
    if (LB_ANY(ta < R(1)))
        e = CUB_FORM(lum, &rect, &view, &opt, &tun, &cnt);
#else
    LB_V e = CUB_FORM(lum, &rect, &view, &opt, &tun, &cnt);
#endif
    LB_I nt = cnt.ntri, nf = cnt.nflips;
    /* the blends in the general kernel's order: the grid MC's, then the area form's */
#ifdef LB_CUB_BLEND
    LB_V t;
    e = LB_VFN(lb_cub_rect_blend)(lum, e, LB_VFN(lb_rect_span_at)(ou, ov, P[LB_P_W], (LB_V)(P[LB_P_L])), vw,
                                  tun.blend_dist, &t);
    nt = t >= R(1) ? 0 : nt; /* no cubature where the grid MC alone counts */
    nf = t >= R(1) ? 0 : nf;
#endif
#ifdef LB_CUB_AREA
    e = LB_VFN(lb_area_blend)(lum, e, ta, rect, vw);
    nt = ta >= R(1) ? 0 : nt;
    nf = ta >= R(1) ? 0 : nf;
#endif
    LB_VFN(cub_store)(out, stats, want_stats, row * res + col0, res - col0, e, nt, nf);
}
#endif
#include "common/lanes_end.h"
#elif defined(LB_CUB_DISK)
/* The disk (LB_SHAPE_DISK), the general kernel: the fan of common/disk.h
 * around the closest point, and with LB_CUB_AREA = n the polar Gauss rule
 * of the area form blended in by lb_disk_area_weight. The rectangle's structural options and
 * corner tunables have no meaning here (the host refuses them). */
LB_RENDER_KERNEL
{
    CUB_PROLOGUE
    (void)opt;
    LB_RENDER_RECEIVER;
    x = lb_plane_shift(L, x, tun.plane_eps);
    real e = R(0), ta = R(0);
#ifdef LB_CUB_AREA
    ta = lb_disk_area_weight(L, x, nx, tun.area_q, tun.area_sin);
#endif
    if (ta < R(1))
        e = lb_disk_irradiance(lum, L, x, nx);
#ifdef LB_CUB_AREA
    if (ta > R(0))
        e = (R(1) - ta) * e + ta * lb_disk_area_gauss(lum, L, x, nx, LB_CUB_AREA);
#endif
    out[px] = e;
    if (want_stats) {
        stats[2 * px] = ta < R(1) ? LB_DISK_FAN : 0;
        stats[2 * px + 1] = 0;
    }
}
#else
LB_RENDER_KERNEL
{
    CUB_PROLOGUE
    int col, row, px;
    lb_light L;
    real3 x, nx;
    if (!lb_work_item_receiver_cell(P, row0, &col, &row, &px, &L, &x, &nx))
        return;
    int nt = 0, nf = 0;
    real t = lb_blend_weight(length(x - L.c), tun.blend_dist);
    real e = R(0);
    if (t < R(1))
        e = lb_cubature_irradiance(lum, L, x, nx, opt, tun, &nt, &nf);
    if (t > R(0))
        e = (R(1) - t) * e + t * lb_grid_mc_irradiance(lum, L, x, nx, 3);
#ifdef LB_CUB_AREA
    {
        /* the straight-line forms' area blend: on the rectangle the horizon
         * leaves when it cuts along the u edges (every normalized scene), else
         * on the whole rectangle (max(0, n_x . w) in the rule) */
        real ou, ov, on, au, av, an;
        lb_corner_offset(P, (real)col, row, &ou, &ov, &on);
        lb_receiver_normal_local(P, &au, &av, &an);
        real v0c = ov, lc = P[LB_P_L];
        if (au == R(0)) {
            real hc = lb_plane_shift_h(on, lb_plane_distance(P, (real)col, row), tun.plane_eps);
            lb_cub_rect_clip(ov, hc, P[LB_P_L], av, an, tun.horizon_eps, &v0c, &lc);
        }
        lb_rect_span seen = lb_rect_span_at(ou, v0c, P[LB_P_W], lc);
        real ta = lb_area_weight(seen, on, tun.area_q, tun.area_sin);
        e = lb_area_blend(lum, e, ta, seen, lb_rect_view_at(on, au, av, an, R(1) / (P[LB_P_W] * P[LB_P_L])));
        nt = ta >= R(1) ? 0 : nt;
        nf = ta >= R(1) ? 0 : nf;
    }
#endif
    out[px] = e;
    if (want_stats) {
        stats[2 * px] = nt;
        stats[2 * px + 1] = nf;
    }
}
#endif
