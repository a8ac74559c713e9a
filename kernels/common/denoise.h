/* denoise.h -- image-space filters run after mc.cl's render kernel, as one
 * method (host/methods/mc_denoise.cpp runs them as post-passes, timed with
 * the render): OpenCL only, included by mc.cl. Images are res x res reals,
 * row-major; every work-item is one pixel of a 2D launch over the image.
 *
 * lb_gauss: one pass of the separable Gaussian (sigma in pixels, taps
 *   -radius .. radius), renormalised over the taps inside the image.
 * lb_atrous: one level of the edge-avoiding a-trous wavelet filter (Dammertz,
 *   Sewtz, Hanika and Lensch 2010), as SVGF runs it: the 5 x 5 B3-spline
 *   kernel at taps `step` pixels apart, each tap weighted by
 *   exp(-|c_p - c_q| / (sigma_l sqrt(var_p) + eps)) with var_p the 3 x 3
 *   Gaussian of the pixels' variances of their MC estimates (mc.cl,
 *   LB_MC_VAR), as SVGF prefilters it; the variance is filtered with the
 *   squared weights for the next level. On the flat receiver there
 *   are no normal or depth edges: the luminance weight is the only stop. */

LB_FN int lb_dn_inside(int c, int r, int res)
{
    return c >= 0 && r >= 0 && c < res && r < res;
}

/* One pass of the separable Gaussian: along rows (vertical = 0) or columns. */
__kernel void lb_gauss(__global const real* in, __global real* out, int res, real sigma, int radius, int vertical)
{
    int c = (int)get_global_id(0), r = (int)get_global_id(1);
    if (c >= res || r >= res)
        return;
    real s = R(0), ws = R(0), k = R(-0.5) / (sigma * sigma);
    for (int d = -radius; d <= radius; ++d) {
        int cc = vertical ? c : c + d, rr = vertical ? r + d : r;
        real w = exp(k * (real)(d * d));
        bool in_ = lb_dn_inside(cc, rr, res);
        s += in_ ? w * in[in_ ? rr * res + cc : r * res + c] : R(0);
        ws += in_ ? w : R(0);
    }
    out[r * res + c] = s / ws;
}

__kernel void lb_atrous(__global const real* in, __global const real* var, __global real* out,
                        __global real* varOut, int res, int step, real sigma_l)
{
    int c = (int)get_global_id(0), r = (int)get_global_id(1);
    if (c >= res || r >= res)
        return;
    const real h[3] = {R(0.375), R(0.25), R(0.0625)};
    real cp = in[r * res + c];
    /* the edge stop's variance: SVGF's 3 x 3 Gaussian of the pixel's
     * neighbourhood, so that two neighbours see about the same scale (a
     * pixel's own 2-sample variance grows with its bright outliers) */
    real vb = R(0), wb = R(0);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            int cc = c + dx, rr = r + dy;
            real k = (dx == 0 ? R(0.5) : R(0.25)) * (dy == 0 ? R(0.5) : R(0.25));
            bool in_ = lb_dn_inside(cc, rr, res);
            vb += in_ ? k * var[in_ ? rr * res + cc : r * res + c] : R(0);
            wb += in_ ? k : R(0);
        }
    real scale = sigma_l * sqrt(fmax(vb / wb, R(0))) + R(1e-10) * fabs(cp) + R(1e-30);
    real s = R(0), ws = R(0), vs = R(0);
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            int cc = c + dx * step, rr = r + dy * step;
            if (!lb_dn_inside(cc, rr, res))
                continue;
            real cq = in[rr * res + cc];
            real w = h[dx < 0 ? -dx : dx] * h[dy < 0 ? -dy : dy] * exp(-fabs(cp - cq) / scale);
            s += w * cq;
            ws += w;
            vs += w * w * var[rr * res + cc];
        }
    out[r * res + c] = s / ws;
    varOut[r * res + c] = vs / (ws * ws);
}
