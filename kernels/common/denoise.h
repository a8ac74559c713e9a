/* denoise.h -- image-space filters run after mc.cl's render kernel, as one
 * method (host/methods/mc_denoise.cpp runs them as post-passes, timed with
 * the render): OpenCL only, included by mc.cl. The math per pixel is
 * common/denoise_math.h's; here each work-item filters eight pixels of a row
 * (columns 8 g0 .. 8 g0 + 7, row g1; a 2D launch over ceil(res / 8) x res):
 * in the interior, where every tap of the eight is inside the image, in eight
 * lanes with contiguous loads and no border tests; elsewhere (the border, a
 * last partial group of columns) pixel by pixel through denoise_math.h, but
 * for the a-trous level, which runs every full group in eight lanes (taps
 * outside the image weighted 0, gathered only where a column leaves it).
 *
 * lb_gauss: one pass of the separable Gaussian, along rows (vertical = 0) or
 *   columns; w[0 .. radius] the host's weights (constant memory, summing to 1
 *   over the 2 radius + 1 taps, so the interior needs no renormalisation).
 * lb_atrous: one level of the edge-avoiding a-trous wavelet filter (Dammertz,
 *   Sewtz, Hanika and Lensch 2010), as SVGF runs it (denoise_math.h). On the
 *   flat receiver there are no normal or depth edges: the luminance weight is
 *   the only stop.
 * lb_var_spatial: where the render left a pixel no variance (one sample: mc.cl
 *   writes -1), SVGF's spatial estimate from the 7 x 7 moments; in place.
 * lb_upsample: the image rendered at rin pixels per side (mc's scale),
 *   bilinear to rout (denoise_math.h); eight pixels of a row per work-item
 *   as the filters (the row's input rows and weight computed once). */

#if LB_REAL_IS_DOUBLE
typedef double8 lb_dn8;
#define LB_DN8_BITS(x) as_double8(convert_long8(x) + LB_EXP2_BIAS)
#else
typedef float8 lb_dn8;
#define LB_DN8_BITS(x) as_float8(convert_int8(x) + LB_EXP2_BIAS)
#endif

/* lb_exp2_neg in eight lanes: the same cut and bits */
LB_FN_INLINE lb_dn8 lb_exp2_neg8(lb_dn8 x)
{
    x = x < R(-LB_EXP2_CUT) ? (lb_dn8)R(-LB_EXP2_CUT) : x;
    return LB_DN8_BITS(x * LB_EXP2_SCALE);
}

/* the work-item's first column, its row and its pixel count (0: none) */
LB_FN int lb_dn_lanes(int res, int* c0, int* r)
{
    *c0 = 8 * (int)get_global_id(0);
    *r = (int)get_global_id(1);
    return *r < res && *c0 < res ? min(8, res - *c0) : 0;
}

__kernel void lb_gauss(__global const real* in, __global real* out, int res, __constant const real* w, int radius,
                       int vertical)
{
    int c0, r, n = lb_dn_lanes(res, &c0, &r);
    bool interior = n == 8 && (vertical ? r >= radius && r + radius < res : c0 >= radius && c0 + 8 + radius <= res);
    if (!interior) {
        for (int i = 0; i < n; ++i) out[r * res + c0 + i] = lb_gauss_px(in, w, res, radius, c0 + i, r, vertical);
        return;
    }
    __global const real* p = in + r * res + c0;
    int stride = vertical ? res : 1;
    lb_dn8 s = w[0] * vload8(0, p);
    for (int d = 1; d <= radius; ++d) s += w[d] * (vload8(0, p - d * stride) + vload8(0, p + d * stride));
    vstore8(s, 0, out + r * res + c0);
}

/* the edge stop's factor of eight pixels whose columns are inside
 * (lb_atrous_k; rows outside the image are left out, uniformly) */
LB_FN_INLINE lb_dn8 lb_atrous_k8(__global const real* p, __global const real* v, int res, int r, real sigma_l)
{
    lb_dn8 vb = (lb_dn8)R(0);
    real wb = R(0);
    for (int dy = -1; dy <= 1; ++dy) {
        if (r + dy < 0 || r + dy >= res)
            continue;
        __global const real* q = v + dy * res;
        lb_dn8 row = R(0.25) * vload8(0, q - 1) + R(0.5) * vload8(0, q) + R(0.25) * vload8(0, q + 1);
        real ky = dy == 0 ? R(0.5) : R(0.25);
        vb += ky * row;
        wb += ky;
    }
    return R(-LB_LOG2E) / (sigma_l * sqrt(fmax(vb / wb, (lb_dn8)R(0))) + R(1e-10) * fabs(vload8(0, p)) + R(1e-30));
}

/* the taps' values and variances at columns c0 + 8 lanes, row rr, where some
 * leave the image (clamped; *ok 0 there, else 1) */
LB_FN void lb_atrous_gather8(__global const real* in, __global const real* var, int res, int at, int cc0,
                             lb_dn8* cq, lb_dn8* vq, lb_dn8* ok)
{
    real a[8], b[8], m[8];
    for (int i = 0; i < 8; ++i) {
        int cc = clamp(cc0 + i, 0, res - 1);
        a[i] = in[at + cc];
        b[i] = var[at + cc];
        m[i] = cc == cc0 + i ? R(1) : R(0);
    }
    *cq = vload8(0, a);
    *vq = vload8(0, b);
    *ok = vload8(0, m);
}

/* Pixel by pixel only in a last partial group of columns; a tap row outside
 * the image is left out by all eight lanes alike, a tap column outside by its
 * lane (weight 0: the sums of denoise_math.h, which skips it). withVar 0 (the
 * last level, whose variance nothing reads): the variance is not filtered. */
__kernel void lb_atrous(__global const real* in, __global const real* var, __global real* out,
                        __global real* varOut, int res, int step, real sigma_l, int withVar)
{
    int c0, r, n = lb_dn_lanes(res, &c0, &r);
    if (n < 8) {
        for (int i = 0; i < n; ++i) {
            real vo;
            out[r * res + c0 + i] = lb_atrous_px(in, var, res, c0 + i, r, step, sigma_l, &vo);
            if (withVar) varOut[r * res + c0 + i] = vo;
        }
        return;
    }
    const int at = r * res + c0;
    const bool edge = c0 < 2 * step || c0 + 8 + 2 * step > res;
    lb_dn8 cp = vload8(0, in + at), k;
    if (c0 >= 1 && c0 + 8 < res) {
        k = lb_atrous_k8(in + at, var + at, res, r, sigma_l);
    } else {
        real kk[8];
        for (int i = 0; i < 8; ++i)
            kk[i] = lb_atrous_k(in, var, res, c0 + i, r, sigma_l);
        k = vload8(0, kk);
    }
    lb_dn8 s = (lb_dn8)R(0), ws = s, vs = s;
    for (int dy = -2; dy <= 2; ++dy) {
        int rr = r + dy * step;
        if (rr < 0 || rr >= res)
            continue;
        real hy = lb_atrous_h(dy);
        for (int dx = -2; dx <= 2; ++dx) {
            int cc0 = c0 + dx * step;
            lb_dn8 cq, vq = (lb_dn8)R(0), h = (lb_dn8)(hy * lb_atrous_h(dx));
            if (!edge || (cc0 >= 0 && cc0 + 8 <= res)) {
                cq = vload8(0, in + rr * res + cc0);
                if (withVar) vq = vload8(0, var + rr * res + cc0);
            } else {
                lb_dn8 ok;
                lb_atrous_gather8(in, var, res, rr * res, cc0, &cq, &vq, &ok);
                h *= ok;
            }
            lb_dn8 wq = dx == 0 && dy == 0 ? h : h * lb_exp2_neg8(k * fabs(cp - cq));
            s += wq * cq;
            ws += wq;
            if (withVar) vs += wq * wq * vq;
        }
    }
    vstore8(s / ws, 0, out + at);
    if (withVar) vstore8(vs / (ws * ws), 0, varOut + at);
}

__kernel void lb_var_spatial(__global const real* in, __global real* var, int res)
{
    int c0, r, n = lb_dn_lanes(res, &c0, &r);
    const int e = LB_DN_VAR_RADIUS;
    if (n < 8 || c0 < e || c0 + 8 + e > res || r < e || r + e >= res) {
        for (int i = 0; i < n; ++i)
            if (var[r * res + c0 + i] < R(0)) var[r * res + c0 + i] = lb_var_spatial_px(in, res, c0 + i, r);
        return;
    }
    const int at = r * res + c0;
    lb_dn8 v = vload8(0, var + at);
    if (!any(v < R(0))) return;
    lb_dn8 s1 = (lb_dn8)R(0), s2 = s1;
    for (int dy = -e; dy <= e; ++dy)
        for (int dx = -e; dx <= e; ++dx) {
            lb_dn8 x = vload8(0, in + at + dy * res + dx);
            s1 += x;
            s2 += x * x;
        }
    const real inv = R(1) / (real)((2 * e + 1) * (2 * e + 1));
    s1 *= inv;
    lb_dn8 est = fmax(s2 * inv - s1 * s1, (lb_dn8)R(0));
    vstore8(v < R(0) ? est : v, 0, var + at);
}

__kernel void lb_upsample(__global const real* in, int rin, __global real* out, int rout)
{
    int c0, r, n = lb_dn_lanes(rout, &c0, &r);
    if (n < 8 || rin < 2) {
        for (int i = 0; i < n; ++i) out[r * rout + c0 + i] = lb_upsample_px(in, rin, rout, c0 + i, r);
        return;
    }
    /* the row's two input rows and weight, uniform over the lanes; the
     * columns' as lb_upsample_px computes them, lane by lane */
    const real s = (real)rin / (real)rout, top = (real)(rin - 1);
    const real y = fmin(fmax(((real)r + R(0.5)) * s - R(0.5), R(0)), top);
    const int y0 = (int)y, y1 = y0 + 1 < rin ? y0 + 1 : y0;
    const real fy = y - (real)y0;
    __global const real* ra = in + y0 * rin;
    __global const real* rb = in + y1 * rin;
    real v[8];
    for (int i = 0; i < 8; ++i) {
        const real x = fmin(fmax(((real)(c0 + i) + R(0.5)) * s - R(0.5), R(0)), top);
        const int x0 = (int)x, x1 = x0 + 1 < rin ? x0 + 1 : x0;
        const real fx = x - (real)x0;
        const real a = ra[x0] + fx * (ra[x1] - ra[x0]);
        const real b = rb[x0] + fx * (rb[x1] - rb[x0]);
        v[i] = a + fy * (b - a);
    }
    vstore8(vload8(0, v), 0, out + r * rout + c0);
}
