/* denoise_math.h -- the image filters' math per pixel, OpenCL C and C++: the
 * kernels of common/denoise.h run it on their border pixels (and in eight
 * lanes in the interior), the host tests hold the kernels to it.
 *
 * Images are res x res reals, row-major.
 *
 * lb_exp2_neg: the edge stop's 2^x for x <= 0 without a library exp, from
 *   the bits (Schraudolph 1999): 2^n (1 + f) for x = n + f, n = floor(x), f
 *   in [0, 1): the mantissa linear in f between the powers of 2, which are
 *   exact (2^0 = 1); 1 to 1.0615 times 2^x (the most at f = 1 / ln 2 - 1),
 *   never below: every weight of a tap that differs from the centre is at
 *   most 6.2 % above SVGF's exp; x below -24 is -24.
 * lb_gauss_px: one tap sum of the separable Gaussian along a row or a column,
 *   weights w[|d|] for d = -radius .. radius (the host's table, summing to 1),
 *   renormalised over the taps inside the image.
 * lb_atrous_k: the a-trous edge stop's factor at a pixel, -log2(e) / (sigma_l
 *   sqrt(var_p) + eps), var_p the 3 x 3 Gaussian of the neighbourhood's
 *   variances (SVGF's prefilter, once per pixel and level); a tap q weighs
 *   h(dx) h(dy) 2^(k |c_p - c_q|) = h h exp(-|c_p - c_q| / scale).
 * lb_atrous_px: one level of the edge-avoiding a-trous wavelet filter at a
 *   pixel: the 5 x 5 B3-spline taps `step` pixels apart; *vo the variance
 *   filtered with the squared weights for the next level.
 * lb_var_spatial_px: SVGF's spatial variance where a pixel has none (one
 *   sample): the 7 x 7 box of the luminance's first and second moments,
 *   E[c^2] - E[c]^2, over the pixels inside the image.
 * lb_upsample_px: bilinear upsampling of an rin x rin image to rout x rout
 *   pixels of the same square (MC rendered below one sample per pixel, mc's
 *   scale): pixel centres aligned, the output centre (c + 1/2) rin / rout -
 *   1/2 in input pixels, clamped to the input's outer centres (constant
 *   beyond them). An affine image comes back exactly between those centres. */

#ifdef __OPENCL_C_VERSION__
#define LB_DN_CONST __constant
#else
#define LB_DN_CONST
#endif

/* 2^x from the bits: x 2^p (p the mantissa's bits) truncated to an integer,
 * plus the exponent's bias shifted into place, read as a real; below x =
 * -24 the value is 2^-24 */
#undef LB_EXP2_SCALE /* the host includes this file once per precision */
#undef LB_EXP2_BIAS
#if LB_REAL_IS_DOUBLE
#define LB_EXP2_SCALE R(4503599627370496.0)
#define LB_EXP2_BIAS ((long)1023 << 52)
#else
#define LB_EXP2_SCALE R(8388608.0)
#define LB_EXP2_BIAS (127 << 23)
#endif
/* 2^-24: a weight 6e-8 of the centre's at most, and no smaller one, whose
 * square (the variance's weight) would be a denormal float (slow on x86) */
#define LB_EXP2_CUT 24
#define LB_LOG2E 1.4426950408889634
#define LB_DN_VAR_RADIUS 3

LB_FN real lb_exp2_neg(real x)
{
    x = x < R(-LB_EXP2_CUT) ? R(-LB_EXP2_CUT) : x;
#ifdef __OPENCL_C_VERSION__
#if LB_REAL_IS_DOUBLE
    return as_double((long)(x * LB_EXP2_SCALE) + LB_EXP2_BIAS);
#else
    return as_float((int)(x * LB_EXP2_SCALE) + LB_EXP2_BIAS);
#endif
#else
    /* the same value: the integer's high bits the exponent, its low bits the
     * mantissa's fraction */
    const int p = LB_REAL_IS_DOUBLE ? 52 : 23;
    const long long i = (long long)(x * LB_EXP2_SCALE), frac = i & ((1LL << p) - 1);
    return std::ldexp(R(1) + (real)frac / LB_EXP2_SCALE, (int)((i - frac) >> p));
#endif
}

LB_FN int lb_dn_inside(int c, int r, int res) { return c >= 0 && r >= 0 && c < res && r < res; }

LB_FN real lb_gauss_px(__global const real* in, LB_DN_CONST const real* w, int res, int radius, int c, int r,
                       int vertical)
{
    real s = R(0), ws = R(0);
    for (int d = -radius; d <= radius; ++d) {
        int cc = vertical ? c : c + d, rr = vertical ? r + d : r;
        if (!lb_dn_inside(cc, rr, res)) continue;
        real wd = w[d < 0 ? -d : d];
        s += wd * in[rr * res + cc];
        ws += wd;
    }
    return s / ws;
}

/* B3-spline weight of a tap |d| = 0, 1, 2 */
LB_FN real lb_atrous_h(int d)
{
    d = d < 0 ? -d : d;
    return d == 0 ? R(0.375) : d == 1 ? R(0.25) : R(0.0625);
}

LB_FN real lb_atrous_k(__global const real* in, __global const real* var, int res, int c, int r, real sigma_l)
{
    /* row by row, as the kernels' eight lanes sum it */
    real vb = R(0), wb = R(0);
    for (int dy = -1; dy <= 1; ++dy) {
        if (!lb_dn_inside(c, r + dy, res)) continue;
        real row = R(0), wrow = R(0);
        for (int dx = -1; dx <= 1; ++dx)
            if (lb_dn_inside(c + dx, r + dy, res)) {
                real k = dx == 0 ? R(0.5) : R(0.25);
                row += k * var[(r + dy) * res + c + dx];
                wrow += k;
            }
        real ky = dy == 0 ? R(0.5) : R(0.25);
        vb += ky * row;
        wb += ky * wrow;
    }
    real cp = in[r * res + c];
    return R(-LB_LOG2E) / (sigma_l * sqrt(fmax(vb / wb, R(0))) + R(1e-10) * fabs(cp) + R(1e-30));
}

LB_FN real lb_atrous_px(__global const real* in, __global const real* var, int res, int c, int r, int step,
                        real sigma_l, real* vo)
{
    real k = lb_atrous_k(in, var, res, c, r, sigma_l), cp = in[r * res + c];
    real s = R(0), ws = R(0), vs = R(0);
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            int cc = c + dx * step, rr = r + dy * step;
            if (!lb_dn_inside(cc, rr, res)) continue;
            real cq = in[rr * res + cc];
            real w = lb_atrous_h(dx) * lb_atrous_h(dy) * (dx == 0 && dy == 0 ? R(1) : lb_exp2_neg(k * fabs(cp - cq)));
            s += w * cq;
            ws += w;
            vs += w * w * var[rr * res + cc];
        }
    *vo = vs / (ws * ws);
    return s / ws;
}

LB_FN real lb_var_spatial_px(__global const real* in, int res, int c, int r)
{
    real s1 = R(0), s2 = R(0), n = R(0);
    for (int dy = -LB_DN_VAR_RADIUS; dy <= LB_DN_VAR_RADIUS; ++dy)
        for (int dx = -LB_DN_VAR_RADIUS; dx <= LB_DN_VAR_RADIUS; ++dx) {
            if (!lb_dn_inside(c + dx, r + dy, res)) continue;
            real x = in[(r + dy) * res + c + dx];
            s1 += x;
            s2 += x * x;
            n += R(1);
        }
    s1 /= n;
    return fmax(s2 / n - s1 * s1, R(0));
}

LB_FN real lb_upsample_px(__global const real* in, int rin, int rout, int c, int r)
{
    const real s = (real)rin / (real)rout, top = (real)(rin - 1);
    const real x = fmin(fmax(((real)c + R(0.5)) * s - R(0.5), R(0)), top);
    const real y = fmin(fmax(((real)r + R(0.5)) * s - R(0.5), R(0)), top);
    const int x0 = (int)x, y0 = (int)y; /* x, y >= 0: truncation is floor */
    const int x1 = x0 + 1 < rin ? x0 + 1 : x0, y1 = y0 + 1 < rin ? y0 + 1 : y0;
    const real fx = x - (real)x0, fy = y - (real)y0;
    const real a = in[y0 * rin + x0] + fx * (in[y0 * rin + x1] - in[y0 * rin + x0]);
    const real b = in[y1 * rin + x0] + fx * (in[y1 * rin + x1] - in[y1 * rin + x0]);
    return a + fy * (b - a);
}
