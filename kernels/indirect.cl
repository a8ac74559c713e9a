/* indirect.cl -- one-bounce indirect light from a reflective shadow map
 * (RSM) of the room's walls and ceiling (docs/design.md section 9, the ACRSM seed):
 * the passes of the methods vpl, kmeans and acrsm
 * (host/methods/family_indirect.cpp runs them, in this order):
 *   rsm            texels over the room's unfolded net (common/indirect.h):
 *                  position, normal, reflected flux rho E_dir area, area; E_dir
 *                  by the direct method chosen by LB_RSM_DIRECT (0 point light
 *                  at the centroid, 1 cubature (common/cubature.h, fan around
 *                  CP), 2 the adaptive reference (common/area_ref.h));
 *   row_sums       flux per texel row (the sampling's first level);
 *   sample         vpl: N texels by flux, stratified (u_k = (k + 1/2) / N),
 *                  each a VPL of flux Phi / N; kmeans: the K first centres;
 *   centres_from   centre attributes (position, normal, radiosity) of texels;
 *   km_assign      Lloyd: each lit texel to its nearest centre by the seed's
 *                  metric (Eq. 4.4 with radiosity for importance);
 *   km_partial,    Lloyd: the clusters' sums per texel row, then per cluster:
 *   km_reduce      new centres and the virtual area lights (VALs);
 *   pyr_base,      acrsm: the importance (flux) pyramid;
 *   pyr_down
 *   ac_evaluate    acrsm: merge and split (seed 4.8, Eq. 4.6-4.8), one work-item;
 *   ac_seed        acrsm: Halton seeds warped through the pyramid (seed 4.4,
 *                  4.5, Alg. 5.3) for the clusters that need one;
 *   ac_map         acrsm: each lit texel to the nearest centre whose window
 *                  holds it (seed 4.6, Eq. 4.5);
 *   render         E_ind at each floor pixel from the virtual lights
 *                  (lb_val_irradiance: VPLs with the 1/r^2 clamp, VALs with
 *                  the point-to-disk form factor).
 * Texels, centres and lights: LB_IND_TEX reals each, laid out as
 * common/indirect.h says (LB_IND_POS, _NRM, _FLUX, _AREA); acrsm's state of a
 * cluster: IND_S_* below, LB_IND_TEX reals too (4 unused).
 * The room is convex and empty: no visibility anywhere (common/indirect.h).
 * @variants: "-DLB_RSM_DIRECT=0" | "-DLB_RSM_DIRECT=1" | "-DLB_RSM_DIRECT=2"
 */
#include "common/lbmath.h"
#include "common/area_ref.h"
#include "common/indirect.h"
#include "common/entry.h"

#ifndef LB_RSM_DIRECT
#define LB_RSM_DIRECT 1
#endif

/* acrsm's state of a cluster (LB_LB_IND_TEX reals; the layout at the top). */
#define IND_S_U 0    /* texel coordinates of the centre */
#define IND_S_V 1
#define IND_S_FLAG 2 /* 0 active, 1 to reseed, 2 seeded by a split, 3 merged */
#define IND_S_GEN 3  /* Halton generation */
/* A cluster's sums over a texel row (km_partial) and over the map (km_reduce):
 * area-weighted position (3), flux-weighted position (3), area-weighted
 * normal (3), flux, area, area-weighted texel coordinates (2), and the
 * largest squared distance of a member from the old centre (a maximum). */
#define IND_PART 16
#define IND_PS_APOS 0
#define IND_PS_FPOS 3
#define IND_PS_ANRM 6
#define IND_PS_FLUX 9
#define IND_PS_AREA 10
#define IND_PS_U 11
#define IND_PS_V 12
#define IND_PS_R2 13
/* b_max of the seed's Eq. 4.4: the room's diagonal. */
#define IND_BMAX sqrt(R(4) * R(LB_ROOM_HALF) * R(LB_ROOM_HALF) * R(2) + R(LB_ROOM_HEIGHT) * R(LB_ROOM_HEIGHT))

/* A texel's radiosity: its flux over its area (0 for a texel off the room). */
LB_FN real ind_radiosity(__global const real* t)
{
    return t[LB_IND_AREA] > R(0) ? t[LB_IND_FLUX] / t[LB_IND_AREA] : R(0);
}

/* Direct irradiance at the wall point p with normal n. visibility: none (the
 * light is inside the convex room). */
LB_FN real ind_direct(__global const float* lum, lb_light L, real3 p, real3 n, real rel_tol, int max_splits,
                      real plane_eps)
{
#if LB_RSM_DIRECT == 0
    real3 w = L.c - p;
    real r2 = dot(w, w);
    real cw = dot(n, w);
    if (!(cw > R(0)) || !(r2 > R(0)))
        return R(0);
    return lb_intensity_local(lum, lb_to_light_frame(L, -w)) * cw / (r2 * sqrt(r2));
#elif LB_RSM_DIRECT == 1
    int nt, nf;
    return lb_cubature_irradiance(lum, L, p, n, lb_cub_paper_options(), lb_cub_plain_tunables(plane_eps, R(0)), &nt,
                                  &nf);
#else
    real err;
    int splits;
    return lb_ref_irradiance(lum, L, p, n, rel_tol, max_splits, &err, &splits);
#endif
}

__kernel void rsm(__global const real* P, __global const float* lum, __global real* tex, int T, real rel_tol,
                  int max_splits, real plane_eps)
{
    int i = get_global_id(0), j = get_global_id(1);
    if (i >= T || j >= T)
        return;
    real cs = lb_net_side() / (real)T;
    real X = ((real)i + R(0.5)) * cs, Y = ((real)j + R(0.5)) * cs;
    real area = lb_net_area((real)i * cs, (real)(i + 1) * cs, (real)j * cs, (real)(j + 1) * cs);
    real3 p, n;
    int k = lb_net_point(X, Y, &p, &n);
    if (k < 0 && area > R(0)) {
        /* centre in a corner square, the texel partly on a band: the nearest
         * band point (the texel's area still counts) */
        real H = R(LB_ROOM_HEIGHT), hi = H + R(2) * R(LB_ROOM_HALF);
        real cx = clamp(X, H, hi), cy = clamp(Y, H, hi);
        if (fabs(cx - X) <= fabs(cy - Y))
            k = lb_net_point(cx, Y, &p, &n);
        else
            k = lb_net_point(X, cy, &p, &n);
    }
    __global real* t = tex + LB_IND_TEX * (j * T + i);
    real flux = R(0);
    if (k >= 0 && area > R(0))
        flux = P[LB_P_ALBEDO] * area * ind_direct(lum, lb_scene_light(P), p, n, rel_tol, max_splits, plane_eps);
    t[LB_IND_POS] = p.x; t[LB_IND_POS + 1] = p.y; t[LB_IND_POS + 2] = p.z;
    t[LB_IND_NRM] = n.x; t[LB_IND_NRM + 1] = n.y; t[LB_IND_NRM + 2] = n.z;
    t[LB_IND_FLUX] = flux;
    t[LB_IND_AREA] = k >= 0 ? area : R(0);
}

__kernel void row_sums(__global const real* tex, int T, __global real* rowsum)
{
    int j = get_global_id(0);
    if (j >= T)
        return;
    real s = R(0);
    for (int i = 0; i < T; ++i)
        s += tex[LB_IND_TEX * (j * T + i) + LB_IND_FLUX];
    rowsum[j] = s;
}

/* N texels by flux: u_k = (k + 1/2) / N of the total, found by the row sums,
 * then along the row. lights[k]: the texel as a VPL of flux total / N;
 * pick[k]: its index. */
__kernel void sample(__global const real* tex, int T, __global const real* rowsum, int N, __global real* lights,
                     __global int* pick)
{
    int k = get_global_id(0);
    if (k >= N)
        return;
    real total = R(0);
    for (int j = 0; j < T; ++j)
        total += rowsum[j];
    real target = ((real)k + R(0.5)) / (real)N * total;
    int j = 0;
    real acc = R(0);
    while (j < T - 1 && acc + rowsum[j] <= target) {
        acc += rowsum[j];
        ++j;
    }
    int i = 0, last = -1;
    for (; i < T; ++i) {
        real f = tex[LB_IND_TEX * (j * T + i) + LB_IND_FLUX];
        if (f > R(0))
            last = i;
        if (f > R(0) && acc + f > target)
            break;
        acc += f;
    }
    if (i >= T)
        i = last >= 0 ? last : 0; /* rounding at the row's end: its last lit texel */
    int idx = j * T + i;
    __global const real* t = tex + LB_IND_TEX * idx;
    __global real* l = lights + LB_IND_TEX * k;
    for (int f = 0; f < 3; ++f) {
        l[LB_IND_POS + f] = t[LB_IND_POS + f];
        l[LB_IND_NRM + f] = t[LB_IND_NRM + f];
    }
    l[LB_IND_FLUX] = total / (real)N;
    l[LB_IND_AREA] = R(0);
    pick[k] = idx;
}

/* Centre k from texel pick[k] (kmeans' restart). */
__kernel void centres_from(__global const real* tex, __global const int* pick, int K, __global real* centres)
{
    int k = get_global_id(0);
    if (k >= K)
        return;
    __global const real* t = tex + LB_IND_TEX * pick[k];
    __global real* c = centres + LB_IND_TEX * k;
    for (int f = 0; f < 3; ++f) {
        c[LB_IND_POS + f] = t[LB_IND_POS + f];
        c[LB_IND_NRM + f] = t[LB_IND_NRM + f];
    }
    c[LB_IND_FLUX] = ind_radiosity(t);
    c[LB_IND_AREA] = R(0);
}

/* The seed's distance (Eq. 4.4): normalized Euclidean distance, 1 - |n_c . n|
 * and, for its importance, the relative difference of radiosity. */
LB_FN real ind_metric(__global const real* c, __global const real* t, real wx, real wn, real wb)
{
    real dx = c[LB_IND_POS] - t[LB_IND_POS], dy = c[LB_IND_POS + 1] - t[LB_IND_POS + 1],
         dz = c[LB_IND_POS + 2] - t[LB_IND_POS + 2];
    real b = ind_radiosity(t);
    real bs = c[LB_IND_FLUX] + b;
    return wx * sqrt(dx * dx + dy * dy + dz * dz) / IND_BMAX +
           wn * (R(1) - fabs(c[LB_IND_NRM] * t[LB_IND_NRM] + c[LB_IND_NRM + 1] * t[LB_IND_NRM + 1] +
                         c[LB_IND_NRM + 2] * t[LB_IND_NRM + 2])) +
           wb * (bs > R(0) ? fabs(c[LB_IND_FLUX] - b) / bs : R(0));
}

/* The K centres a texel may join and the metric's weights (Eq. 4.4). With a
 * state (acrsm) only the active centres (flag 0) whose window of `window`
 * texels (side) holds the texel qualify (Eq. 4.5); kmeans passes none (0):
 * every centre. */
typedef struct {
    __global const real* centres;
    __global const real* state;
    int K;
    real window, wx, wn, wb;
} ind_candidates;

/* The candidate nearest (Eq. 4.4) to texel (i, j) of the T x T map, -1 when
 * the texel is unlit or no centre qualifies. */
LB_FN int ind_nearest(__global const real* tex, int T, int i, int j, const ind_candidates* cs)
{
    __global const real* centres = cs->centres;
    __global const real* state = cs->state;
    int K = cs->K;
    real window = cs->window, wx = cs->wx, wn = cs->wn, wb = cs->wb;
    __global const real* t = tex + LB_IND_TEX * (j * T + i);
    int best = -1;
    if (t[LB_IND_FLUX] > R(0)) {
        real bm = R(0), hw = R(0.5) * window, x = (real)i + R(0.5), y = (real)j + R(0.5);
        for (int k = 0; k < K; ++k) {
            if (state) {
                __global const real* s = state + LB_IND_TEX * k;
                if (s[IND_S_FLAG] != R(0) || fabs(x - s[IND_S_U]) > hw || fabs(y - s[IND_S_V]) > hw)
                    continue;
            }
            real m = ind_metric(centres + LB_IND_TEX * k, t, wx, wn, wb);
            if (best < 0 || m < bm) {
                bm = m;
                best = k;
            }
        }
    }
    return best;
}

__kernel void km_assign(__global const real* tex, int T, __global const real* centres, int K, real wx, real wn,
                        real wb, __global int* label)
{
    int i = get_global_id(0), j = get_global_id(1);
    if (i >= T || j >= T)
        return;
    ind_candidates cs = {centres, 0, K, R(0), wx, wn, wb};
    label[j * T + i] = ind_nearest(tex, T, i, j, &cs);
}

/* Sums of cluster k over texel row j (K x T work-items). */
__kernel void km_partial(__global const real* tex, int T, __global const int* label, int K,
                         __global const real* centres, __global real* partial)
{
    int k = get_global_id(0), j = get_global_id(1);
    if (k >= K || j >= T)
        return;
    real s[IND_PART];
    for (int f = 0; f < IND_PART; ++f)
        s[f] = R(0);
    __global const real* c = centres + LB_IND_TEX * k;
    for (int i = 0; i < T; ++i) {
        int idx = j * T + i;
        if (label[idx] != k)
            continue;
        __global const real* t = tex + LB_IND_TEX * idx;
        real a = t[LB_IND_AREA], phi = t[LB_IND_FLUX];
        for (int f = 0; f < 3; ++f) {
            s[IND_PS_APOS + f] += a * t[LB_IND_POS + f];
            s[IND_PS_FPOS + f] += phi * t[LB_IND_POS + f];
            s[IND_PS_ANRM + f] += a * t[LB_IND_NRM + f];
        }
        s[IND_PS_FLUX] += phi;
        s[IND_PS_AREA] += a;
        s[IND_PS_U] += a * ((real)i + R(0.5));
        s[IND_PS_V] += a * ((real)j + R(0.5));
        real dx = t[LB_IND_POS] - c[LB_IND_POS], dy = t[LB_IND_POS + 1] - c[LB_IND_POS + 1],
             dz = t[LB_IND_POS + 2] - c[LB_IND_POS + 2];
        s[IND_PS_R2] = fmax(s[IND_PS_R2], dx * dx + dy * dy + dz * dz);
    }
    __global real* p = partial + IND_PART * (k * T + j);
    for (int f = 0; f < IND_PART; ++f)
        p[f] = s[f];
}

/* Cluster k's new centre (area-weighted mean position, mean normal,
 * radiosity) and its VAL: the flux-weighted mean position, the summed flux
 * (energy-conserving), area = the members' area (area_mode 0) or pi r_c^2 with
 * r_c the farthest member from the old centre (area_mode 1, the seed's 4.7).
 * stateful (acrsm): also the mean texel coordinates, and an empty cluster is
 * marked for reseeding. */
__kernel void km_reduce(__global const real* partial, int T, int K, __global real* centres, __global real* lights,
                        __global real* state, int stateful, int area_mode)
{
    int k = get_global_id(0);
    if (k >= K)
        return;
    real s[IND_PART];
    for (int f = 0; f < IND_PART; ++f)
        s[f] = R(0);
    for (int j = 0; j < T; ++j) {
        __global const real* p = partial + IND_PART * (k * T + j);
        for (int f = 0; f < IND_PS_R2; ++f)
            s[f] += p[f];
        s[IND_PS_R2] = fmax(s[IND_PS_R2], p[IND_PS_R2]);
    }
    __global real* c = centres + LB_IND_TEX * k;
    __global real* l = lights + LB_IND_TEX * k;
    if (!(s[IND_PS_AREA] > R(0))) {
        for (int f = 0; f < LB_IND_TEX; ++f)
            l[f] = R(0);
        l[LB_IND_NRM + 2] = R(-1); /* a valid normal for a light of no flux */
        if (stateful)
            state[LB_IND_TEX * k + IND_S_FLAG] = R(1);
        return;
    }
    real a = s[IND_PS_AREA], phi = s[IND_PS_FLUX];
    real nl = sqrt(s[IND_PS_ANRM] * s[IND_PS_ANRM] + s[IND_PS_ANRM + 1] * s[IND_PS_ANRM + 1] +
                   s[IND_PS_ANRM + 2] * s[IND_PS_ANRM + 2]);
    for (int f = 0; f < 3; ++f) {
        c[LB_IND_POS + f] = s[IND_PS_APOS + f] / a;
        c[LB_IND_NRM + f] = nl > R(0) ? s[IND_PS_ANRM + f] / nl : R(0);
        l[LB_IND_POS + f] = phi > R(0) ? s[IND_PS_FPOS + f] / phi : c[LB_IND_POS + f];
        l[LB_IND_NRM + f] = c[LB_IND_NRM + f];
    }
    c[LB_IND_FLUX] = phi / a;
    l[LB_IND_FLUX] = phi;
    l[LB_IND_AREA] = area_mode == 0 ? a : LB_PI * s[IND_PS_R2];
    if (stateful) {
        state[LB_IND_TEX * k + IND_S_U] = s[IND_PS_U] / a;
        state[LB_IND_TEX * k + IND_S_V] = s[IND_PS_V] / a;
    }
}

/* ---- acrsm ---- */

/* Importance pyramid: level 0 (T x T) is the texels' flux; level m is
 * (T >> m)^2 at offset off (the host's offsets). */
__kernel void pyr_base(__global const real* tex, int T, __global real* pyr)
{
    int i = get_global_id(0), j = get_global_id(1);
    if (i >= T || j >= T)
        return;
    pyr[j * T + i] = tex[LB_IND_TEX * (j * T + i) + LB_IND_FLUX];
}

__kernel void pyr_down(__global real* pyr, int src_off, int src_n, int dst_off)
{
    int i = get_global_id(0), j = get_global_id(1);
    int n = src_n / 2;
    if (i >= n || j >= n)
        return;
    __global const real* s = pyr + src_off;
    pyr[dst_off + j * n + i] =
        s[(2 * j) * src_n + 2 * i] + s[(2 * j) * src_n + 2 * i + 1] + s[(2 * j + 1) * src_n + 2 * i] +
        s[(2 * j + 1) * src_n + 2 * i + 1];
}

LB_FN real ind_radical_inverse(int b, uint i)
{
    real f = R(1), r = R(0);
    while (i > 0u) {
        f /= (real)b;
        r += f * (real)(i % (uint)b);
        i /= (uint)b;
    }
    return r;
}

LB_FN real ind_unit(uint x)
{
    return (real)(lb_mc_hash(x) >> 8) / R(16777216.0);
}

/* Hierarchical warping (Clarberg et al. 2005, the seed's 4.5 and Alg. 5.3) of
 * the point q in [0, 1)^2 by the pyramid from its 2 x 2 level down to level
 * `stop`: per level, the row (lower / upper half) by the rows' importance,
 * then the column within it, q rescaled into the chosen child. Returns the
 * point in texel coordinates. levels = log2 T. */
LB_FN real2 ind_warp(__global const real* pyr, __global const int* off, int levels, int stop, real2 q)
{
    int cx = 0, cy = 0;
    for (int m = levels - 1; m >= stop; --m) {
        int n = 1 << (levels - m); /* side of level m */
        __global const real* L = pyr + off[m];
        int x0 = 2 * cx, y0 = 2 * cy;
        real q00 = L[y0 * n + x0], q10 = L[y0 * n + x0 + 1], q01 = L[(y0 + 1) * n + x0], q11 = L[(y0 + 1) * n + x0 + 1];
        real r0 = q00 + q10, r1 = q01 + q11;
        int row = 0, col = 0;
        if (r0 + r1 > R(0)) {
            real fy = r0 / (r0 + r1);
            if (q.y < fy) {
                q.y = q.y / fy;
            } else {
                q.y = (q.y - fy) / (R(1) - fy);
                row = 1;
            }
            real a = row ? q01 : q00, b = row ? q11 : q10;
            real fx = a + b > R(0) ? a / (a + b) : R(0.5);
            if (q.x < fx) {
                q.x = q.x / fx;
            } else {
                q.x = (q.x - fx) / (R(1) - fx);
                col = 1;
            }
        } else {
            row = q.y >= R(0.5);
            col = q.x >= R(0.5);
            q.y = R(2) * q.y - (real)row;
            q.x = R(2) * q.x - (real)col;
        }
        q.x = clamp(q.x, R(0), R(0.999999));
        q.y = clamp(q.y, R(0), R(0.999999));
        cx = x0 + col;
        cy = y0 + row;
    }
    int side = 1 << (levels - stop);
    real scale = (real)(1 << levels) / (real)side; /* texels per cell of level stop */
    return R2(((real)cx + q.x) * scale, ((real)cy + q.y) * scale);
}

/* Seeds (frame 0: every cluster; later: those flagged 1 by a merge or an
 * empty mapping, and 2 placed by a split), then every centre's radiosity read
 * anew at its texel (the light moved: the seed's 4.7, flux read at the centre). */
__kernel void ac_seed(__global const real* tex, int T, __global const real* pyr, __global const int* off, int levels,
                      int stop, int K, __global real* state, __global real* centres, int frame)
{
    int k = get_global_id(0);
    if (k >= K)
        return;
    __global real* s = state + LB_IND_TEX * k;
    __global real* c = centres + LB_IND_TEX * k;
    int flag = frame == 0 ? 1 : (int)s[IND_S_FLAG];
    if (frame == 0)
        s[IND_S_GEN] = R(0);
    if (flag == 1) {
        uint gen = (uint)s[IND_S_GEN];
        uint idx = (uint)k + (uint)K * gen + 1u;
        real2 q = R2(ind_radical_inverse(2, idx), ind_radical_inverse(3, idx));
        real2 uv = ind_warp(pyr, off, levels, stop, q);
        s[IND_S_U] = uv.x;
        s[IND_S_V] = uv.y;
        s[IND_S_GEN] = (real)(gen + 1u);
    }
    int i = clamp((int)floor(s[IND_S_U]), 0, T - 1), j = clamp((int)floor(s[IND_S_V]), 0, T - 1);
    __global const real* t = tex + LB_IND_TEX * (j * T + i);
    if (flag == 1 || flag == 2)
        for (int f = 0; f < 3; ++f) {
            c[LB_IND_POS + f] = t[LB_IND_POS + f];
            c[LB_IND_NRM + f] = t[LB_IND_NRM + f];
        }
    c[LB_IND_FLUX] = ind_radiosity(t);
    s[IND_S_FLAG] = R(0);
}

/* Each lit texel to the nearest active centre (Eq. 4.4) among those whose
 * window of `window` texels (side) holds it (Eq. 4.5); -1 when none does. */
__kernel void ac_map(__global const real* tex, int T, __global const real* centres, __global const real* state, int K,
                     real window, real wx, real wn, real wb, __global int* label)
{
    int i = get_global_id(0), j = get_global_id(1);
    if (i >= T || j >= T)
        return;
    ind_candidates cs = {centres, state, K, window, wx, wn, wb};
    label[j * T + i] = ind_nearest(tex, T, i, j, &cs);
}

#define IND_AC_MAXK 1024

/* Cluster k's delta (Eq. 4.6): (A / A_max)(B / B_max), its light's area and its centre's radiosity. */
LB_FN real ind_delta(__global const real* lights, __global const real* centres, int k, real amax, real bmax)
{
    return lights[LB_IND_TEX * k + LB_IND_AREA] / amax * centres[LB_IND_TEX * k + LB_IND_FLUX] / bmax;
}

/* Evaluation (seed 4.8, Eq. 4.6-4.8; one work-item): of a pseudo-random third
 * of the clusters (changing per frame), those whose delta = (A / A_max)(B /
 * B_max) falls below their neighbourhood's self-weighted mean by more than
 * eps_m are merged (freed); then those above it by more than eps_s are split
 * while freed clusters remain: a freed one is placed at a random point within
 * the split cluster's radius (flag 2, no warping). The rest are reseeded
 * (flag 1). Neighbours: the centres within a window of 2 x `window` texels. */
__kernel void ac_evaluate(int K, int T, __global real* state, __global const real* centres,
                          __global const real* lights, int frame, real window, real eps_m, real eps_s)
{
    if (get_global_id(0) != 0)
        return;
    real amax = R(0), bmax = R(0);
    for (int k = 0; k < K; ++k) {
        amax = fmax(amax, lights[LB_IND_TEX * k + LB_IND_AREA]);
        bmax = fmax(bmax, centres[LB_IND_TEX * k + LB_IND_FLUX]);
    }
    if (!(amax > R(0)) || !(bmax > R(0)))
        return;
    real texel = lb_net_side() / (real)T;
    real dbar[IND_AC_MAXK];
    for (int k = 0; k < K; ++k) {
        real num = R(0), den = R(0);
        __global const real* sk = state + LB_IND_TEX * k;
        for (int j = 0; j < K; ++j) {
            __global const real* sj = state + LB_IND_TEX * j;
            if (j == k || sj[IND_S_FLAG] != R(0) || fabs(sj[IND_S_U] - sk[IND_S_U]) > window ||
                fabs(sj[IND_S_V] - sk[IND_S_V]) > window)
                continue;
            real d = ind_delta(lights, centres, j, amax, bmax);
            num += d * d;
            den += d;
        }
        dbar[k] = den > R(0) ? num / den : R(-1);
    }
    int freed[IND_AC_MAXK];
    int nf = 0;
    for (int k = 0; k < K; ++k) {
        __global real* s = state + LB_IND_TEX * k;
        if (s[IND_S_FLAG] != R(0) || dbar[k] < R(0) || lb_mc_hash((uint)frame * 7919u + (uint)k) % 3u != 0u)
            continue;
        real d = ind_delta(lights, centres, k, amax, bmax);
        if (d - dbar[k] < -eps_m) {
            s[IND_S_FLAG] = R(3);
            freed[nf++] = k;
        }
    }
    for (int k = 0; k < K && nf > 0; ++k) {
        __global real* s = state + LB_IND_TEX * k;
        if (s[IND_S_FLAG] != R(0) || dbar[k] < R(0) || lb_mc_hash((uint)frame * 7919u + (uint)k) % 3u != 0u)
            continue;
        real d = ind_delta(lights, centres, k, amax, bmax);
        if (d - dbar[k] > eps_s) {
            int f = freed[--nf];
            real r = sqrt(lights[LB_IND_TEX * k + LB_IND_AREA] / LB_PI) / texel;
            uint h = (uint)frame * 104729u + (uint)k * 31u;
            __global real* sf = state + LB_IND_TEX * f;
            sf[IND_S_U] = clamp(s[IND_S_U] + r * (ind_unit(h) - R(0.5)), R(0), (real)T - R(0.001));
            sf[IND_S_V] = clamp(s[IND_S_V] + r * (ind_unit(h + 1u) - R(0.5)), R(0), (real)T - R(0.001));
            sf[IND_S_FLAG] = R(2);
        }
    }
    for (int i = 0; i < nf; ++i)
        state[LB_IND_TEX * freed[i] + IND_S_FLAG] = R(1);
}

/* ---- evaluation: E_ind at each floor pixel from n virtual lights ---- */
#define LB_ENTRY_ARGS , __global const real *lights, int nlights, real clamp2
LB_RENDER_KERNEL
{
    LB_RENDER_RECEIVER;
    real e = R(0);
    for (int k = 0; k < nlights; ++k) {
        __global const real* l = lights + LB_IND_TEX * k;
        e += lb_val_irradiance(x, nx, R3(l[LB_IND_POS], l[LB_IND_POS + 1], l[LB_IND_POS + 2]),
                               R3(l[LB_IND_NRM], l[LB_IND_NRM + 1], l[LB_IND_NRM + 2]), l[LB_IND_FLUX], l[LB_IND_AREA],
                               clamp2);
    }
    out[px] = e;
}
