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
 *   LB_MC_DISK     (extended path, domain area) the disk light: each point
 *                  (u0, u1) mapped onto the disk (lb_mc_concentric); the shared
 *                  set's points the host maps alike, so the plain path needs
 *                  no variant. With domain solid: directions uniform in solid
 *                  angle over the whole disk (common/disk_sample.h), area
 *                  sampling below min_solid
 *
 * The extended path (-DLB_MC_EXT, mc_ext below; host/methods/mc_options.h
 * sets it for anything but today's MCI): per-pixel sequences (LB_MC_SEQ:
 * shared set, optionally shifted per pixel, LB_MC_SHIFT; hashed random;
 * Owen-scrambled Sobol; ZSobol) and sampling domains (LB_MC_DOMAIN: area,
 * solid angle with LB_MC_WARP the cosine warp, projected solid angle, MIS,
 * the luminaire's table, MIS of table and projected or solid angle), the math in
 * common/mc_sample.h and common/mc_table.h (the table sampler `tab`, built
 * by host/methods/mc_table.cpp); LB_MC_VAR writes each pixel's variance
 * (-1 where it has one sample: no estimate) for the a-trous filter
 * (common/denoise.h, whose kernels this program also holds: the method's
 * post-passes).
 * @variants: "" | "-DLB_LUT" | "-DLB_LUT -DLB_LUT_1D -DLB_NO_HORIZON -DLB_NO_BACK" | "-DLB_MC_EXT -DLB_MC_DOMAIN=1 -DLB_MC_SEQ=2 -DLB_MC_CLIPV -DLB_MC_WARP" | "-DLB_MC_EXT -DLB_MC_DOMAIN=3 -DLB_MC_SEQ=3 -DLB_MC_CLIPV -DLB_MC_VAR -DLB_LUT" | "-DLB_MC_EXT -DLB_MC_DOMAIN=2 -DLB_MC_SEQ=1 -DLB_MC_SHIFT" | "-DLB_MC_EXT -DLB_MC_DOMAIN=4 -DLB_MC_SEQ=2 -DLB_LUT" | "-DLB_MC_EXT -DLB_MC_DOMAIN=5 -DLB_MC_SEQ=1 -DLB_MC_CLIPV" | "-DLB_MC_EXT -DLB_MC_DOMAIN=6 -DLB_MC_SEQ=2 -DLB_MC_CLIPV -DLB_LUT" | "-DLB_MC_EXT -DLB_MC_SEQ=2 -DLB_MC_DISK" | "-DLB_MC_EXT -DLB_MC_DOMAIN=1 -DLB_MC_SEQ=2 -DLB_MC_CLIPV -DLB_MC_VAR -DLB_LUT -DLB_MC_STRAIGHT -DLB_LANES=8" | "-DLB_MC_EXT -DLB_MC_DOMAIN=1 -DLB_MC_SEQ=0 -DLB_MC_SHIFT -DLB_LUT -DLB_NO_BACK -DLB_MC_STRAIGHT" | "-DLB_MC_EXT -DLB_MC_DOMAIN=0 -DLB_MC_SEQ=1 -DLB_LUT -DLB_MC_STRAIGHT -DLB_LANES=8" | "-DLB_MC_EXT -DLB_MC_DOMAIN=2 -DLB_MC_SEQ=2 -DLB_MC_CLIPV -DLB_LUT -DLB_MC_STRAIGHT -DLB_LANES=8" | "-DLB_MC_EXT -DLB_MC_DOMAIN=3 -DLB_MC_SEQ=3 -DLB_MC_CLIPV -DLB_MC_VAR -DLB_LUT -DLB_MC_STRAIGHT" | "-DLB_MC_EXT -DLB_MC_DOMAIN=1 -DLB_MC_SEQ=3 -DLB_MC_WARP -DLB_LUT -DLB_MC_STRAIGHT -DLB_LANES=8" | "-DLB_MC_EXT -DLB_MC_DOMAIN=1 -DLB_MC_SEQ=0 -DLB_MC_SHIFT -DLB_MC_DISK" | "-DLB_MC_EXT -DLB_MC_DOMAIN=1 -DLB_MC_SEQ=3 -DLB_MC_DISK -DLB_MC_VAR -DLB_LUT"
 */
#include "common/lbmath.h"
#include "common/entry.h"

/* After the registry's arguments (common/entry.h): st, n and extra as above;
 * seed, np, lg, min_solid, var and tab the extended path's (mc_ext). */
#define LB_ENTRY_ARGS                                                                                          \
    , __global const real *st, int n, float extra, int seed, int np, int lg, real min_solid, __global real *var, \
        __global const float *tab

/* n_L . (corner(-u,-v) - pixel(col, row)): the pixel lies on or behind the
 * light's plane when >= 0 (the same arithmetic as the kernel's `on`). */
LB_FN real mc_on(__global const real* P, int col, int row)
{
    real ou, ov, on;
    lb_corner_offset(P, (real)col, row, &ou, &ov, &on);
    return on;
}

#ifdef LB_MC_EXT
#ifndef LB_MC_DOMAIN
#define LB_MC_DOMAIN 0
#endif
#ifndef LB_MC_SEQ
#define LB_MC_SEQ 0
#endif

/* The pixel: where it is (for ZSobol's Morton index: lg = log2 N rounded
 * up, digits its base-4 digits with the image's), its hash hp, the seed, and
 * np, mis' projected share of the samples. */
typedef struct {
    int col, row, lg, digits, np;
    lb_u32 hp, seed;
} mc_pixel;

LB_FN_INLINE void mc_pixel_at(int col, int row, int res, lb_u32 seed, int lg, int np, mc_pixel* px)
{
    px->hp = lb_mc_hash(lb_mc_hash(seed * 0x9e3779b9U + 0x632be5abU) ^ (lb_u32)(row * res + col));
    int rb = 0;
    while ((1 << rb) < res)
        ++rb;
    px->col = col, px->row = row, px->lg = lg, px->np = np, px->seed = seed;
    px->digits = rb + (lg + 1) / 2;
}

/* Point j in [0,1)^2 of the pixel's sequence (LB_MC_SEQ: 0 shared, 1 random,
 * 2 sobol, 3 zsobol); i the index into the shared set, salt one per sampling
 * technique (so that the two techniques of mis take independent points). */
LB_FN_INLINE void mc_point(__global const real* st, const mc_pixel* px, int j, int i, lb_u32 salt, real* u0,
                           real* u1)
{
#if LB_MC_SEQ == 0
    real a = st[2 * i], b = st[2 * i + 1];
#ifdef LB_MC_SHIFT
    /* Cranley-Patterson rotation of the shared set by the pixel's hash */
    a += lb_mc_unit(lb_mc_hash(px->hp ^ 0x2545f491U));
    b += lb_mc_unit(lb_mc_hash(px->hp ^ 0x9e3779b9U));
    a = a >= R(1) ? a - R(1) : a;
    b = b >= R(1) ? b - R(1) : b;
#endif
    *u0 = a;
    *u1 = b;
#elif LB_MC_SEQ == 1
    lb_u32 h = lb_mc_hash(px->hp ^ salt);
    *u0 = lb_mc_unit(lb_mc_hash(h ^ lb_mc_hash(2U * (lb_u32)j)));
    *u1 = lb_mc_unit(lb_mc_hash(h ^ lb_mc_hash(2U * (lb_u32)j + 1U)));
#elif LB_MC_SEQ == 2
    lb_u32 h = lb_mc_hash(px->hp ^ salt);
    *u0 = lb_mc_unit(lb_mc_owen(lb_mc_sobol0((lb_u32)j), lb_mc_hash(h ^ 0xa511e9b3U)));
    *u1 = lb_mc_unit(lb_mc_owen(lb_mc_sobol1((lb_u32)j), lb_mc_hash(h ^ 0x63d83595U)));
#else
    lb_u32 sd = lb_mc_hash(px->seed ^ salt);
    lb_u32 idx = lb_mc_zsobol_index(px->col, px->row, (lb_u32)j, px->lg, px->digits, sd);
    *u0 = lb_mc_unit(lb_mc_owen(lb_mc_sobol0(idx), lb_mc_hash(sd ^ 0xa511e9b3U)));
    *u1 = lb_mc_unit(lb_mc_owen(lb_mc_sobol1(idx), lb_mc_hash(sd ^ 0x63d83595U)));
#endif
}

/* The pixel's view of the light, in the light's frame: the offset (ou, ov,
 * on) of corner (-u, -v) from the pixel, the receiver normal (au, av, an),
 * the light's size w x l, and the part above the receiver's horizon (all of
 * it without LB_MC_CLIPV): t in [t0, t0 + tv] along v, i.e. v offsets y0 ..
 * y0 + ey. */
typedef struct {
    real ou, ov, on, au, av, an, w, l, area;
    real t0, tv, y0, ey, on2, an0;
    __global const float* tab; /* the table sampler (common/mc_table.h) */
} mc_view;

LB_FN_INLINE void mc_view_at(__global const real* P, real ou, real ov, real on, real au, real av, real an,
                             mc_view* vw)
{
    real w = P[LB_P_W], l = P[LB_P_L];
    vw->ou = ou, vw->ov = ov, vw->on = on, vw->au = au, vw->av = av, vw->an = an;
    vw->w = w, vw->l = l, vw->area = w * l;
    /* The part of the light above the horizon: n_x . p = av (ov + L t) + an on >= 0. */
    real t0 = R(0), t1 = R(1);
#ifdef LB_MC_CLIPV
    real num = -(av * ov + an * on), den = av * l;
    if (den > R(0))
        t0 = clamp(num / den, R(0), R(1));
    else if (den < R(0))
        t1 = clamp(num / den, R(0), R(1));
    else if (num > R(0))
        t1 = R(0);
#endif
    vw->t0 = t0;
    vw->tv = fmax(t1 - t0, R(0));
    vw->y0 = ov + l * t0, vw->ey = l * vw->tv;
    vw->on2 = on * on, vw->an0 = an * on;
}

/* The sampling domain's per-pixel set-up (LB_MC_DOMAIN: 0 area on the whole
 * light, 1 solid angle, 2 projected solid angle, 3 mis: projected and area by
 * the balance heuristic, 4 table: by the luminaire's intensity table, 5
 * mis_table: projected and table by the balance heuristic, 6 mis_table_solid:
 * solid angle and table by the balance heuristic; 1-6 on the part above the
 * horizon). */
#if LB_MC_DOMAIN == 1 && defined(LB_MC_DISK)
/* Solid angle on the disk (common/disk_sample.h): the whole disk, a sample
 * below the receiver's horizon counts 0 (mc_area_term's max(0, cos)). */
typedef struct {
    lb_mc_sphdisk q;
    real kdisk; /* the estimate's factor 1 / (the disk's area h) for solid-angle samples */
    bool use;   /* solid-angle sampling (else area sampling of the disk) */
} mc_domain;

LB_FN_INLINE void mc_domain_at(const mc_view* vw, real min_solid, mc_domain* dm)
{
    real a = R(0.5) * vw->w, b = R(0.5) * vw->l, h = fabs(vw->on);
    lb_mc_sphdisk_setup(vw->ou + a, vw->ov + b, h, a, b, &dm->q);
    /* solid-angle sampling where the solid angle is not tiny; else area
     * sampling (exact pdf: 1 / the disk's area) */
    dm->use = dm->q.total >= min_solid && dm->q.total > R(0) && h > R(0);
    dm->kdisk = dm->use ? R(1) / (LB_PI * a * b * h) : R(0);
}
#elif LB_MC_DOMAIN == 1 || LB_MC_DOMAIN == 6
typedef struct {
#if LB_MC_DOMAIN == 6
    lb_mc_tabwin tw;
    real omega;
#endif
    lb_mc_sphrect q;
    real ksolid; /* the estimate's factor omega / (|on| area) for solid-angle samples */
    bool use;    /* solid-angle sampling (else area sampling of the same rectangle) */
#ifdef LB_MC_WARP
    real w00, w10, w01, w11; /* the receiver cosines at the corners, the warp's weights */
#endif
} mc_domain;

LB_FN_INLINE void mc_domain_at(const mc_view* vw, real min_solid, mc_domain* dm)
{
    real ou = vw->ou, y0 = vw->y0, on = vw->on, w = vw->w, ey = vw->ey;
    dm->q = lb_mc_sphrect_setup(ou, y0, on, w, ey);
    real omega = dm->q.s; /* the spherical excess, accurate for small ones too */
    /* solid-angle sampling where the solid angle is not tiny; else area
     * sampling of the same rectangle (exact pdf: 1 / its area) */
    dm->use = omega >= min_solid && omega > R(0) && fabs(on) > R(0);
    dm->ksolid = dm->use ? omega / (fabs(on) * vw->area) : R(0);
#if LB_MC_DOMAIN == 6
    dm->omega = omega;
    lb_mc_tabwin_setup(vw->tab, ou, y0, on, w, ey, &dm->tw);
#endif
#ifdef LB_MC_WARP
    real au = vw->au, av = vw->av, an0 = vw->an0;
    real3 c0 = R3(ou, y0, on), c1 = R3(ou + w, y0, on), c2 = R3(ou + w, y0 + ey, on), c3 = R3(ou, y0 + ey, on);
    real nl0 = R(1) / length(c0), nl1 = R(1) / length(c1), nl2 = R(1) / length(c2), nl3 = R(1) / length(c3);
    dm->w00 = fmax(R(0.01), (au * c0.x + av * c0.y + an0) * nl0);
    dm->w10 = fmax(R(0.01), (au * c1.x + av * c1.y + an0) * nl1);
    dm->w11 = fmax(R(0.01), (au * c2.x + av * c2.y + an0) * nl2);
    dm->w01 = fmax(R(0.01), (au * c3.x + av * c3.y + an0) * nl3);
#endif
}
#elif LB_MC_DOMAIN == 4
typedef struct {
    lb_mc_tabwin tw;
    bool lit; /* some of the light above the horizon */
} mc_domain;

LB_FN_INLINE void mc_domain_at(const mc_view* vw, real min_solid, mc_domain* dm)
{
    lb_mc_tabwin_setup(vw->tab, vw->ou, vw->y0, vw->on, vw->w, vw->ey, &dm->tw);
    dm->lit = vw->tv > R(0);
}
#elif LB_MC_DOMAIN >= 2
typedef struct {
#if LB_MC_DOMAIN == 5
    lb_mc_tabwin tw;
#endif
    lb_mc_proj pj;
    real t1u, t1v, t1n, t2u, t2v, t2n; /* the receiver's tangent frame in the light's */
    real kproj;                        /* projected solid angle / light area */
    bool lit;                          /* some of the light above the horizon */
} mc_domain;

LB_FN_INLINE void mc_domain_at(const mc_view* vw, real min_solid, mc_domain* dm)
{
    real au = vw->au, av = vw->av, an = vw->an, on = vw->on;
    /* the receiver's tangent frame (T1, T2, n_x) in the light's frame */
    real t1u = R(1) - au * au, t1v = -au * av, t1n = -au * an;
    real tl = R(1) / sqrt(t1u * t1u + t1v * t1v + t1n * t1n);
    t1u *= tl, t1v *= tl, t1n *= tl;
    real t2u = av * t1n - an * t1v, t2v = an * t1u - au * t1n, t2n = au * t1v - av * t1u;
    real qx[4], qy[4], qz[4];
    real cu[4] = {vw->ou, vw->ou + vw->w, vw->ou + vw->w, vw->ou}, cv[4] = {vw->y0, vw->y0, vw->y0 + vw->ey,
                                                                              vw->y0 + vw->ey};
    for (int k = 0; k < 4; ++k) {
        qx[k] = t1u * cu[k] + t1v * cv[k] + t1n * on, qy[k] = t2u * cu[k] + t2v * cv[k] + t2n * on;
        qz[k] = fmax(R(0), au * cu[k] + av * cv[k] + vw->an0);
    }
    dm->pj = lb_mc_proj_setup(qx, qy, qz);
    dm->lit = vw->tv > R(0) && dm->pj.area > R(0);
    dm->kproj = dm->lit ? dm->pj.area / vw->area : R(0);
    dm->t1u = t1u, dm->t1v = t1v, dm->t1n = t1n, dm->t2u = t2u, dm->t2v = t2v, dm->t2n = t2n;
#if LB_MC_DOMAIN == 5
    lb_mc_tabwin_setup(vw->tab, vw->ou, vw->y0, on, vw->w, vw->ey, &dm->tw);
#endif
}

/* The projected sample's direction for (u0, u1), in the light's frame. */
LB_FN_INLINE void mc_domain_dir(const mc_view* vw, const mc_domain* dm, real u0, real u1, real* wu, real* wv,
                                 real* wn)
{
    real x, y, z;
    lb_mc_proj_sample(&dm->pj, u0, u1, &x, &y, &z);
    *wu = x * dm->t1u + y * dm->t2u + z * vw->au;
    *wv = x * dm->t1v + y * dm->t2v + z * vw->av;
    *wn = x * dm->t1n + y * dm->t2n + z * vw->an;
}
#else
typedef struct {
    int none;
} mc_domain;

LB_FN_INLINE void mc_domain_at(const mc_view* vw, real min_solid, mc_domain* dm)
{
    dm->none = 0;
}
#endif

/* The area form's numerator at the light point (pu, pv) (offsets from the
 * pixel): I(d) max(0, n_x . w); *ri = 1 / r (0 at r = 0). */
LB_FN_INLINE real mc_area_term(__global const float* lum, const mc_view* vw, real pu, real pv, real* ri)
{
    real r2 = pu * pu + pv * pv + vw->on2;
    real cw = vw->au * pu + vw->av * pv + vw->an0;
    cw = cw > R(0) ? cw : R(0);
    *ri = r2 > R(0) ? R(1) / LB_MC_SQRT(r2) : R(0);
    return LB_INTENSITY3(lum, -pu, -pv, -vw->on) * cw;
}

#if LB_MC_DOMAIN == 1 && defined(LB_MC_DISK)
/* One sample's estimate for the point (u0, u1): I(d) cos_x / r^2 over the
 * density's conversion, as the area samples'. */
LB_FN_INLINE real mc_disk_eval(__global const float* lum, const mc_view* vw, const mc_domain* dm, real u0, real u1)
{
    real sx, sy, ri;
    real wt = lb_mc_sphdisk_sample(&dm->q, u0, u1, &sx, &sy);
    real cu = u0, cv = u1;
    lb_mc_concentric(&cu, &cv);
    real pu = dm->use ? sx : vw->ou + vw->w * cu;
    real pv = dm->use ? sy : vw->ov + vw->l * cv;
    real f = mc_area_term(lum, vw, pu, pv, &ri);
    return f * (dm->use ? wt * dm->kdisk : ri * ri * ri);
}
#endif

#if LB_MC_DOMAIN >= 4
/* The solid-angle form's integrand at the unit emission direction (dx, dy,
 * dz): I(d) cos_x / (area |d_z|) (luminance times the receiver cosine, over
 * the light's area as the kernel's estimates), 0 where the direction misses
 * the part of the light above the horizon. *cw: the receiver cosine. */
LB_FN_INLINE real mc_dir_term(__global const float* lum, const mc_view* vw, real dx, real dy, real dz, real* cw)
{
    /* the light point -t d, t = -on / dz > 0 */
    real sc = dz != R(0) ? vw->on / dz : R(0);
    real pu = dx * sc, pv = dy * sc;
    *cw = -(vw->au * dx + vw->av * dy + vw->an * dz);
    bool hit = sc < R(0) && *cw > R(0) && pu >= vw->ou && pu <= vw->ou + vw->w && pv >= vw->y0 &&
        pv <= vw->y0 + vw->ey;
    real az = dz < R(0) ? -dz : dz;
    return hit ? LB_INTENSITY3(lum, dx, dy, dz) * *cw / (vw->area * az) : R(0);
}
#endif

#if LB_MC_DOMAIN == 4
/* One table sample's estimate for the point (u0, u1). */
LB_FN_INLINE real mc_eval(__global const float* lum, const mc_view* vw, const mc_domain* dm, real u0, real u1)
{
    real dx, dy, dz, cw;
    real pt = lb_mc_tab_sample(&dm->tw, u0, u1, &dx, &dy, &dz);
    real f = mc_dir_term(lum, vw, dx, dy, dz, &cw);
    return dm->lit && pt > R(0) ? f / pt : R(0);
}
#elif LB_MC_DOMAIN == 5
/* One mis_table sample's estimate, m samples of which np projected: a
 * projected sample (proj) or a table sample for the point (u0, u1), weighted
 * by the balance heuristic (densities in solid angle: cos_x / projected solid
 * angle, and the table's). */
LB_FN_INLINE real mc_eval_tmis(__global const float* lum, const mc_view* vw, const mc_domain* dm, int m, int np,
                               bool proj, real u0, real u1)
{
    real dx, dy, dz, pt, cw;
    /* i is the same in every work-item: a uniform branch */
    if (proj) {
        real wu, wv, wn;
        mc_domain_dir(vw, dm, u0, u1, &wu, &wv, &wn);
        dx = -wu, dy = -wv, dz = -wn;
        pt = lb_mc_tab_pdf(&dm->tw, dx, dy, dz);
    } else {
        pt = lb_mc_tab_sample(&dm->tw, u0, u1, &dx, &dy, &dz);
    }
    real f = mc_dir_term(lum, vw, dx, dy, dz, &cw);
    real den = (real)(m - np) * pt + (real)np * cw / dm->pj.area;
    return dm->lit && f > R(0) && den > R(0) ? (real)m * f / den : R(0);
}
#elif LB_MC_DOMAIN == 6
/* One mis_table_solid sample's estimate, m samples of which np by solid
 * angle (or by area below min_solid): a solid-angle sample (sol) or a table
 * sample for the point (u0, u1), weighted by the balance heuristic
 * (densities in solid angle: 1 / omega, or on^2 / (area |d_z|^3) for area
 * samples, and the table's). */
LB_FN_INLINE real mc_eval_smis(__global const float* lum, const mc_view* vw, const mc_domain* dm, int m, int np,
                               bool sol, real u0, real u1)
{
    real dx, dy, dz, pt, cw;
    /* i is the same in every work-item: a uniform branch */
    if (sol) {
        real sx, sy;
        lb_mc_sphrect_sample(&dm->q, u0, u1, &sx, &sy);
        real pu = dm->use ? sx : vw->ou + vw->w * u0, pv = dm->use ? sy : vw->y0 + vw->ey * u1;
        real ri = R(1) / LB_MC_SQRT(pu * pu + pv * pv + vw->on2);
        dx = -pu * ri, dy = -pv * ri, dz = -vw->on * ri;
        pt = lb_mc_tab_pdf(&dm->tw, dx, dy, dz);
    } else {
        pt = lb_mc_tab_sample(&dm->tw, u0, u1, &dx, &dy, &dz);
    }
    real f = mc_dir_term(lum, vw, dx, dy, dz, &cw);
    real az = dz < R(0) ? -dz : dz;
    real ps = dm->use ? R(1) / dm->omega : vw->on2 / (vw->w * vw->ey * az * az * az);
    real den = (real)(m - np) * pt + (real)np * ps;
    return vw->tv > R(0) && f > R(0) && den > R(0) ? (real)m * f / den : R(0);
}
#elif LB_MC_DOMAIN != 3
/* One sample's estimate for the point (u0, u1) (domains 0-2). */
LB_FN_INLINE real mc_eval(__global const float* lum, const mc_view* vw, const mc_domain* dm, real u0, real u1)
{
#if LB_MC_DOMAIN == 0
    real ri;
#ifdef LB_MC_DISK
    lb_mc_concentric(&u0, &u1); /* uniform on the disk inscribed in the W x L box */
#endif
    real f = mc_area_term(lum, vw, vw->ou + vw->w * u0, vw->ov + vw->l * u1, &ri);
    return f * (ri * ri * ri);
#elif LB_MC_DOMAIN == 1 && defined(LB_MC_DISK)
    return mc_disk_eval(lum, vw, dm, u0, u1);
#elif LB_MC_DOMAIN == 1
    real wu0 = u0, wu1 = u1, bp = R(1);
#ifdef LB_MC_WARP
    bp = lb_mc_bilinear(&wu0, &wu1, dm->w00, dm->w10, dm->w01, dm->w11);
#endif
    real sx, sy, ri;
    lb_mc_sphrect_sample(&dm->q, wu0, wu1, &sx, &sy);
    real pu = dm->use ? sx : vw->ou + vw->w * u0;
    real pv = dm->use ? sy : vw->y0 + vw->ey * u1;
    real f = mc_area_term(lum, vw, pu, pv, &ri);
    real kw = dm->use ? dm->ksolid / bp : vw->tv * ri * ri * ri;
    return f * kw;
#else
    real wu, wv, wn;
    mc_domain_dir(vw, dm, u0, u1, &wu, &wv, &wn);
    return dm->lit && wn != R(0) ? dm->kproj * LB_INTENSITY3(lum, -wu, -wv, -wn) / (wn < R(0) ? -wn : wn) : R(0);
#endif
}
#else
/* One mis sample's estimate, m samples of which np projected: a projected
 * sample (proj) or an area sample for the point (u0, u1), weighted by the
 * balance heuristic. */
LB_FN_INLINE real mc_eval_mis(__global const float* lum, const mc_view* vw, const mc_domain* dm, int m, int np,
                              bool proj, real u0, real u1)
{
    /* i is the same in every work-item: a uniform branch skips the
     * projected sampler for the area samples */
    real wu = vw->au, wv = vw->av, wn = vw->an;
    if (proj)
        mc_domain_dir(vw, dm, u0, u1, &wu, &wv, &wn);
    real on = vw->on;
    /* the sample's point on the light: the direction's hit (projected
     * samples) or the area point (area samples) */
    real sc = wn != R(0) ? on / wn : R(0);
    real pu = proj ? wu * sc : vw->ou + vw->w * u0;
    real pv = proj ? wv * sc : vw->y0 + vw->ey * u1;
    real r2 = pu * pu + pv * pv + vw->on2;
    real cw = vw->au * pu + vw->av * pv + vw->an0;
    cw = cw > R(0) ? cw : R(0);
    real r = LB_MC_SQRT(r2);
    /* f / (na p_area + np p_proj) in area measure, times r^4 A above and below */
    real den = (real)(m - np) * r2 * r2 / vw->tv + (real)np * cw * (on < R(0) ? -on : on) * vw->area / dm->pj.area;
    bool ok = dm->lit && den > R(0) && (!proj || sc > R(0));
    return ok ? (real)m * LB_INTENSITY3(lum, -pu, -pv, -on) * cw * r / den : R(0);
}
#endif

/* Sample i of the pixel's m (its point, its estimate). */
LB_FN_INLINE real mc_sample(__global const float* lum, __global const real* st, const mc_pixel* px,
                            const mc_view* vw, const mc_domain* dm, int i, int m)
{
    real u0, u1;
#if LB_MC_DOMAIN == 3 || LB_MC_DOMAIN == 5 || LB_MC_DOMAIN == 6
    bool proj = i < px->np;
    mc_point(st, px, proj ? i : i - px->np, i, proj ? 0x5bd1e995U : 0x27d4eb2fU, &u0, &u1);
#if LB_MC_DOMAIN == 3
    return mc_eval_mis(lum, vw, dm, m, px->np, proj, u0, u1);
#elif LB_MC_DOMAIN == 5
    return mc_eval_tmis(lum, vw, dm, m, px->np, proj, u0, u1);
#else
    return mc_eval_smis(lum, vw, dm, m, px->np, proj, u0, u1);
#endif
#else
    mc_point(st, px, i, i, 0U, &u0, &u1);
    return mc_eval(lum, vw, dm, u0, u1);
#endif
}

/* The pixel's estimate with m samples; *ev: the variance of the estimate (the
 * sample variance / m; -1 with one sample). One barrier per sample, as the
 * main loop. */
LB_FN_INLINE real mc_ext(__global const float* lum, __global const real* st, const mc_pixel* px,
                         const mc_view* vw, int m, real min_solid, real* ev)
{
    mc_domain dm;
    mc_domain_at(vw, min_solid, &dm);
    /* the variance from the samples' offsets to the first one: sums of e^2
     * would cancel to their rounding (float: a relative spread ~ 1e-4) where
     * the samples agree */
    real sum = R(0), e0 = R(0), d1 = R(0), d2 = R(0);
    for (int i = 0; i < m; ++i) {
        real e = mc_sample(lum, st, px, vw, &dm, i, m);
        sum += e;
        e0 = i == 0 ? e : e0;
        d1 += e - e0;
        d2 += (e - e0) * (e - e0);
#ifndef LB_MC_NOBARRIER
        barrier(CLK_LOCAL_MEM_FENCE);
#endif
    }
    *ev = m > 1 ? fmax(R(0), d2 - d1 * d1 / (real)m) / ((real)m * (real)(m - 1)) : R(-1);
    return sum / (real)m;
}
#endif

#ifdef LB_NO_BACK
/* Every direction d = -w to a pixel with on >= 0 has d . n_L <= 0: no light.
 * The barrier in the sample loop needs the whole work-group to take the same
 * path, so the group skips only when its whole tile lies behind the light's
 * plane: on is linear in the pixel position, so the tile's 4 corner pixels
 * decide, computed from group-uniform values only (so every work-item gets
 * the same bits). */
LB_FN_INLINE bool mc_tile_behind(__global const real* P, int row0)
{
    int c0 = (int)(get_group_id(0) * get_local_size(0));
    int r0 = row0 + (int)(get_group_id(1) * get_local_size(1));
    int c1 = c0 + (int)get_local_size(0) - 1, r1 = r0 + (int)get_local_size(1) - 1;
    real m = fmin(fmin(mc_on(P, c0, r0), mc_on(P, c1, r0)), fmin(mc_on(P, c0, r1), mc_on(P, c1, r1)));
    return m >= R(0);
}
#endif

/* The work-group's sample count: n, or n + 1 (the set stored after the n
 * points, *st moved there) for the share `extra` of the tiles, spread evenly
 * over the image. */
LB_FN_INLINE int mc_tile_count(int n, float extra, int row0, int res, int lanes, __global const real** st)
{
    if (extra > 0.0f) {
        /* tile index, row-major over the whole image (launches come in bands
         * of rows: row0 counts); a tile is `lanes` times the group's columns wide */
        int ls0 = (int)get_local_size(0) * lanes, ls1 = (int)get_local_size(1);
        int tile_row = (row0 + (int)(get_group_id(1) * get_local_size(1))) / ls1;
        float g = (float)(tile_row * ((res + ls0 - 1) / ls0) + (int)get_group_id(0));
        if (floor((g + 1.0f) * extra) > floor(g * extra)) {
            *st += 2 * n;
            return n + 1;
        }
    }
    return n;
}

#ifdef LB_MC_STRAIGHT
/* The straight-line form of the extended path (host/methods/family_mc.cpp
 * picks it): domain area, solid angle (with or without the cosine warp),
 * projected or mis, every sequence, the rectangle light, the trig-free
 * table. No barrier, no loop but the samples' (and the projected sampler's
 * inversion, run to the slowest lane), every other branch uniform over the
 * lanes: eight pixels of a row per work-item in float8 where the host asks
 * for LB_LANES=8 (CPUs, float), else one. The same sequences, set-up and
 * estimates as mc_ext (common/mc_lanes.inc and proj_lanes.inc hold the
 * samplers for both; tests/methods/test_mc_straight.cpp holds the form to
 * mc_ext). */
#include "common/lanes_kernel.h"

/* The pixels' view of the light, as mc_view, and the domain's set-up, as
 * mc_domain. */
typedef struct {
    LB_V ou, ov, on, y0, ey, tv, on2, an0;
    real au, av, an, w, l, area;
#if LB_MC_DOMAIN == 1
    LB_VFN(lb_mc_sphrect) q;
    LB_V ksolid;
    LB_M use;
#ifdef LB_MC_WARP
    LB_V w00, w10, w01, w11; /* the receiver cosines at the corners, the warp's weights */
#endif
#elif LB_MC_DOMAIN == 2 || LB_MC_DOMAIN == 3
    LB_VFN(lb_mc_proj) pj;
    real t1u, t1v, t1n, t2u, t2v, t2n; /* the receiver's tangent frame in the light's */
    LB_V kproj;                        /* projected solid angle / light area */
    LB_M lit;                          /* some of the light above the horizon */
#endif
} LB_VFN(mcs_view);

#ifdef LB_MC_WARP
/* The warp's weight at the light point (x, y): the receiver cosine, >= 0.01. */
LB_FN LB_V LB_VFN(mcs_corner_cos)(const LB_VFN(mcs_view) * vw, LB_V x, LB_V y)
{
    LB_V c = (vw->au * x + vw->av * y + vw->an0) / LB_MC_SQRT(x * x + y * y + vw->on2);
    return c > R(0.01) ? c : R(0.01);
}
#endif

#if LB_MC_DOMAIN == 2 || LB_MC_DOMAIN == 3
/* The projected sampler's set-up, as mc_domain_at: the part of the light
 * above the horizon in the receiver's tangent frame (T1, T2, n_x). */
LB_FN void LB_VFN(mcs_proj_at)(LB_VFN(mcs_view) * vw)
{
    real au = vw->au, av = vw->av, an = vw->an;
    real t1u = R(1) - au * au, t1v = -au * av, t1n = -au * an;
    real tl = R(1) / sqrt(t1u * t1u + t1v * t1v + t1n * t1n);
    t1u *= tl, t1v *= tl, t1n *= tl;
    real t2u = av * t1n - an * t1v, t2v = an * t1u - au * t1n, t2n = au * t1v - av * t1u;
    LB_V qx[4], qy[4], qz[4];
    LB_V cu[4] = {vw->ou, vw->ou + vw->w, vw->ou + vw->w, vw->ou};
    LB_V cv[4] = {vw->y0, vw->y0, vw->y0 + vw->ey, vw->y0 + vw->ey};
    for (int k = 0; k < 4; ++k) {
        qx[k] = t1u * cu[k] + t1v * cv[k] + t1n * vw->on, qy[k] = t2u * cu[k] + t2v * cv[k] + t2n * vw->on;
        LB_V z = au * cu[k] + av * cv[k] + vw->an0;
        qz[k] = z > R(0) ? z : R(0) * z;
    }
    vw->pj = LB_VFN(lb_mc_proj_setup)(qx, qy, qz);
    vw->lit = vw->tv > R(0) && vw->pj.area > R(0);
    vw->kproj = vw->lit ? vw->pj.area / vw->area : R(0) * vw->tv;
    vw->t1u = t1u, vw->t1v = t1v, vw->t1n = t1n, vw->t2u = t2u, vw->t2v = t2v, vw->t2n = t2n;
}

/* A projected sample's direction for (u0, u1), in the light's frame. */
LB_FN void LB_VFN(mcs_proj_dir)(const LB_VFN(mcs_view) * vw, LB_V u0, LB_V u1, LB_V* wu, LB_V* wv, LB_V* wn)
{
    LB_V x, y, z;
    LB_VFN(lb_mc_proj_sample)(&vw->pj, u0, u1, &x, &y, &z);
    *wu = x * vw->t1u + y * vw->t2u + z * vw->au;
    *wv = x * vw->t1v + y * vw->t2v + z * vw->av;
    *wn = x * vw->t1n + y * vw->t2n + z * vw->an;
}
#endif

LB_FN void LB_VFN(mcs_view_at)(__global const real* P, LB_V ou, LB_V ov, LB_V on, real min_solid,
                               LB_VFN(mcs_view) * vw)
{
    real w = P[LB_P_W], l = P[LB_P_L], an;
    lb_receiver_normal_local(P, &vw->au, &vw->av, &an);
    vw->an = an;
    vw->ou = ou, vw->ov = ov, vw->on = on, vw->w = w, vw->l = l, vw->area = w * l;
    LB_V t0 = R(0), t1 = R(1);
#ifdef LB_MC_CLIPV
    /* the part above the horizon, as mc_view_at */
    LB_V num = -(vw->av * ov + an * on);
    real den = vw->av * l;
    if (den > R(0))
        t0 = LB_MC_CLAMP(num / den, R(0), R(1));
    else if (den < R(0))
        t1 = LB_MC_CLAMP(num / den, R(0), R(1));
    else
        t1 = num > R(0) ? R(0) * t1 : t1;
#endif
    LB_V tv = t1 - t0;
    vw->tv = tv > R(0) ? tv : R(0) * tv;
    vw->y0 = ov + l * t0, vw->ey = l * vw->tv;
    vw->on2 = on * on, vw->an0 = an * on;
#if LB_MC_DOMAIN == 1
    vw->q = LB_VFN(lb_mc_sphrect_setup)(ou, vw->y0, on, w, vw->ey);
    LB_V omega = vw->q.s, aon = on < R(0) ? -on : on;
    /* solid-angle sampling where the solid angle is not tiny; else area
     * sampling of the same rectangle (exact pdf: 1 / its area), as mc_domain_at */
    vw->use = omega >= min_solid && omega > R(0) && aon > R(0);
    vw->ksolid = vw->use ? omega / (aon * vw->area) : R(0) * omega;
#ifdef LB_MC_WARP
    LB_V x1 = ou + w, y1 = vw->y0 + vw->ey;
    vw->w00 = LB_VFN(mcs_corner_cos)(vw, ou, vw->y0), vw->w10 = LB_VFN(mcs_corner_cos)(vw, x1, vw->y0);
    vw->w11 = LB_VFN(mcs_corner_cos)(vw, x1, y1), vw->w01 = LB_VFN(mcs_corner_cos)(vw, ou, y1);
#endif
#elif LB_MC_DOMAIN == 2 || LB_MC_DOMAIN == 3
    LB_VFN(mcs_proj_at)(vw);
    (void)min_solid;
#else
    (void)min_solid;
#endif
}

#if LB_MC_DOMAIN == 3
/* One mis sample's estimate, m samples of which np projected, as mc_eval_mis:
 * a projected sample (proj, the same in every lane) or an area sample for
 * the point (u0, u1), weighted by the balance heuristic. */
LB_FN LB_V LB_VFN(mcs_eval_mis)(__global const float* lum, const LB_VFN(mcs_view) * vw, int m, int np, bool proj,
                                LB_V u0, LB_V u1)
{
    LB_V wu = vw->au + R(0) * u0, wv = vw->av + R(0) * u0, wn = vw->an + R(0) * u0;
    if (proj)
        LB_VFN(mcs_proj_dir)(vw, u0, u1, &wu, &wv, &wn);
    LB_V on = vw->on;
    /* the sample's point on the light: the direction's hit (projected
     * samples) or the area point (area samples) */
    LB_V sc = wn != R(0) ? on / wn : R(0) * wn;
    LB_V pu = proj ? wu * sc : vw->ou + vw->w * u0;
    LB_V pv = proj ? wv * sc : vw->y0 + vw->ey * u1;
    LB_V r2 = pu * pu + pv * pv + vw->on2;
    LB_V cw = vw->au * pu + vw->av * pv + vw->an0;
    cw = cw > R(0) ? cw : R(0) * cw;
    LB_V r = LB_MC_SQRT(r2), aon = on < R(0) ? -on : on;
    /* f / (na p_area + np p_proj) in area measure, times r^4 A above and below */
    LB_V den = (real)(m - np) * r2 * r2 / vw->tv + (real)np * cw * aon * vw->area / vw->pj.area;
    LB_M ok = vw->lit && den > R(0);
    if (proj)
        ok = ok && sc > R(0);
    LB_V f = LB_VINTENSITY3(lum, -pu, -pv, -on) * cw * r;
    return ok ? (real)m * f / den : R(0) * f;
}
#else
/* One sample's estimate for the point (u0, u1), as mc_eval (domains 0-2). */
LB_FN LB_V LB_VFN(mcs_eval)(__global const float* lum, const LB_VFN(mcs_view) * vw, LB_V u0, LB_V u1)
{
#if LB_MC_DOMAIN == 2
    LB_V wu, wv, wn;
    LB_VFN(mcs_proj_dir)(vw, u0, u1, &wu, &wv, &wn);
    LB_V awn = wn < R(0) ? -wn : wn;
    LB_V f = LB_VINTENSITY3(lum, -wu, -wv, -wn);
    return vw->lit && awn > R(0) ? vw->kproj * f / awn : R(0) * f;
#else
#if LB_MC_DOMAIN == 1
    LB_V wu0 = u0, wu1 = u1, sx, sy;
#ifdef LB_MC_WARP
    LB_V bp = LB_VFN(lb_mc_bilinear)(&wu0, &wu1, vw->w00, vw->w10, vw->w01, vw->w11);
#endif
    LB_VFN(lb_mc_sphrect_sample)(&vw->q, wu0, wu1, &sx, &sy);
    LB_V pu = vw->use ? sx : vw->ou + vw->w * u0;
    LB_V pv = vw->use ? sy : vw->y0 + vw->ey * u1;
#else
    LB_V pu = vw->ou + vw->w * u0, pv = vw->ov + vw->l * u1;
#endif
    LB_V r2 = pu * pu + pv * pv + vw->on2;
    LB_V cw = vw->au * pu + vw->av * pv + vw->an0;
    cw = cw > R(0) ? cw : R(0) * cw;
    LB_V ri = r2 > R(0) ? R(1) / LB_MC_SQRT(r2) : R(0) * r2;
    LB_V f = LB_VINTENSITY3(lum, -pu, -pv, -vw->on) * cw;
#if LB_MC_DOMAIN == 1 && defined(LB_MC_WARP)
    return f * (vw->use ? vw->ksolid / bp : vw->tv * ri * ri * ri);
#elif LB_MC_DOMAIN == 1
    return f * (vw->use ? vw->ksolid : vw->tv * ri * ri * ri);
#else
    return f * (ri * ri * ri);
#endif
#endif
}
#endif

/* The pixels' sequence state (mc_point's, per pixel): the Sobol scrambles,
 * the random hash, the shift of the shared set, ZSobol's pixel and seed. */
typedef struct {
    LB_U k0, k1, col;
    LB_V sa, sb;
    lb_u32 sd;
    int row, lg, digits;
} LB_VFN(mcs_seq);

/* The pixels (columns col of row, hash hp) as mc_pixel_at, their points of
 * the technique `salt` (as mc_point's). */
LB_FN LB_VFN(mcs_seq) LB_VFN(mcs_seq_at)(LB_U hp, LB_U col, int row, lb_u32 seed, int lg, int res, lb_u32 salt)
{
    LB_VFN(mcs_seq) q;
    LB_U h = LB_VFN(lb_mc_hash)(hp ^ salt);
    q.k0 = h, q.k1 = h, q.col = col, q.row = row, q.lg = lg, q.sd = 0U;
    int rb = 0;
    while ((1 << rb) < res)
        ++rb;
    q.digits = rb + (lg + 1) / 2;
#if LB_MC_SEQ == 2
    q.k0 = LB_VFN(lb_mc_hash)(h ^ 0xa511e9b3U);
    q.k1 = LB_VFN(lb_mc_hash)(h ^ 0x63d83595U);
#elif LB_MC_SEQ == 3
    q.sd = lb_mc_hash(seed ^ salt);
    q.k0 = q.k0 * 0U + lb_mc_hash(q.sd ^ 0xa511e9b3U);
    q.k1 = q.k1 * 0U + lb_mc_hash(q.sd ^ 0x63d83595U);
#endif
    (void)seed;
    q.sa = R(0) * LB_U_TO_V(h), q.sb = q.sa;
#if LB_MC_SEQ == 0 && defined(LB_MC_SHIFT)
    q.sa = LB_VFN(lb_mc_unit)(LB_VFN(lb_mc_hash)(hp ^ 0x2545f491U));
    q.sb = LB_VFN(lb_mc_unit)(LB_VFN(lb_mc_hash)(hp ^ 0x9e3779b9U));
#endif
    return q;
}

/* Point j of the pixels' sequences (i: the index into the shared set), as
 * mc_point. */
LB_FN void LB_VFN(mcs_point)(__global const real* st, const LB_VFN(mcs_seq) * q, int j, int i, LB_V* u0, LB_V* u1)
{
#if LB_MC_SEQ == 0
    LB_V a = st[2 * i] + q->sa, b = st[2 * i + 1] + q->sb;
    *u0 = a >= R(1) ? a - R(1) : a;
    *u1 = b >= R(1) ? b - R(1) : b;
#elif LB_MC_SEQ == 1
    lb_u32 hj0 = lb_mc_hash(2U * (lb_u32)j), hj1 = lb_mc_hash(2U * (lb_u32)j + 1U);
    *u0 = LB_VFN(lb_mc_unit)(LB_VFN(lb_mc_hash)(q->k0 ^ hj0));
    *u1 = LB_VFN(lb_mc_unit)(LB_VFN(lb_mc_hash)(q->k0 ^ hj1));
#elif LB_MC_SEQ == 2
    *u0 = LB_VFN(lb_mc_unit)(LB_VFN(lb_mc_owen)((LB_U)(lb_mc_sobol0((lb_u32)j)), q->k0));
    *u1 = LB_VFN(lb_mc_unit)(LB_VFN(lb_mc_owen)((LB_U)(lb_mc_sobol1((lb_u32)j)), q->k1));
#else
    LB_U idx = LB_VFN(lb_mc_zsobol_index)(q->col, q->row, (lb_u32)j, q->lg, q->digits, q->sd);
    *u0 = LB_VFN(lb_mc_unit)(LB_VFN(lb_mc_owen)(LB_VFN(lb_mc_sobol0)(idx), q->k0));
    *u1 = LB_VFN(lb_mc_unit)(LB_VFN(lb_mc_owen)(LB_VFN(lb_mc_sobol1)(idx), q->k1));
#endif
    (void)i, (void)j;
}

LB_RENDER_KERNEL
{
    (void)np, (void)tab, (void)var;
    LB_RENDER_PIXELS;
    LB_V ou = pix_span.u0, ov = pix_span.v0, on = pix_view.h;
    int m = mc_tile_count(n, extra, row0, res, LB_NLANES, &st);
    LB_V sum = R(0) * ou, d1 = sum, d2 = sum;
#ifdef LB_NO_BACK
    /* every pixel on or behind the light's plane: no light (mc_tile_behind) */
    if (LB_ANY(on < R(0))) {
#else
    {
#endif
        LB_VFN(mcs_view) vw;
        LB_VFN(mcs_view_at)(P, ou, ov, on, min_solid, &vw);
        LB_U col = LB_TO_U(LB_TO_I(LB_LANE_INDEX) + col0);
        LB_U hp = LB_VFN(lb_mc_hash)(lb_mc_hash((lb_u32)seed * 0x9e3779b9U + 0x632be5abU) ^
                                     ((lb_u32)(row * res) + col));
#if LB_MC_DOMAIN == 3
        /* mis: the projected samples' points and the area samples' (mc_sample's salts) */
        LB_VFN(mcs_seq) q = LB_VFN(mcs_seq_at)(hp, col, row, (lb_u32)seed, lg, res, 0x5bd1e995U);
        LB_VFN(mcs_seq) qa = LB_VFN(mcs_seq_at)(hp, col, row, (lb_u32)seed, lg, res, 0x27d4eb2fU);
#else
        LB_VFN(mcs_seq) q = LB_VFN(mcs_seq_at)(hp, col, row, (lb_u32)seed, lg, res, 0U);
#endif
        /* the variance from the samples' offsets to the first one, as mc_ext */
        LB_V e0 = sum;
        for (int i = 0; i < m; ++i) {
            LB_V u0, u1;
#if LB_MC_DOMAIN == 3
            bool proj = i < np; /* the same in every lane */
            LB_VFN(mcs_point)(st, proj ? &q : &qa, proj ? i : i - np, i, &u0, &u1);
            LB_V e = LB_VFN(mcs_eval_mis)(lum, &vw, m, np, proj, u0, u1);
#else
            LB_VFN(mcs_point)(st, &q, i, i, &u0, &u1);
            LB_V e = LB_VFN(mcs_eval)(lum, &vw, u0, u1);
#endif
            sum += e;
            e0 = i == 0 ? e : e0;
            d1 += e - e0;
            d2 += (e - e0) * (e - e0);
        }
    }
    LB_STORE(out, row * res + col0, res - col0, sum / (real)m);
#ifdef LB_MC_VAR
    LB_V ev = d2 - d1 * d1 / (real)m;
    ev = ev > R(0) ? ev : R(0) * ev;
    LB_STORE(var, row * res + col0, res - col0, m > 1 ? ev / ((real)m * (real)(m - 1)) : R(0) * ev - R(1));
#endif
}
#include "common/lanes_end.h"

#else
LB_RENDER_KERNEL
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
    if (mc_tile_behind(P, row0)) {
        if (inside) {
            out[row * res + col] = R(0);
#ifdef LB_MC_VAR
            var[row * res + col] = R(0); /* the a-trous edge stop reads it */
#endif
        }
        return;
    }
#endif
    /* Receiver cosine (unnormalised): n_x . w = au (ou + W s) + av (ov + L t) + an on. */
    int m = mc_tile_count(n, extra, row0, res, 1, &st);
    real au, av, an;
    lb_receiver_normal_local(P, &au, &av, &an);
#ifdef LB_MC_EXT
    mc_pixel px;
    mc_pixel_at(col, row, res, (lb_u32)seed, lg, np, &px);
    mc_view vw;
    mc_view_at(P, ou, ov, on, au, av, an, &vw);
    vw.tab = tab;
    real ev;
    real e = mc_ext(lum, st, &px, &vw, m, min_solid, &ev);
    if (inside) {
        out[row * res + col] = e;
#ifdef LB_MC_VAR
        var[row * res + col] = ev;
#endif
    }
    return;
#endif
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
#endif /* LB_MC_STRAIGHT */

#include "common/denoise.h"
