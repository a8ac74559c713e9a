/* specular_mc.cl -- Monte Carlo baselines of the specular scene (docs/design.md
 * section 8), L_s = (1/A) int I(d) f_r(w, w_o) max(0, n_x . w) / r^2 dA:
 *   LB_SMC_SAMPLING 0  light: the same N points (s, t) on the light for every
 *                      pixel (as kernels/mc.cl), L_s = (1/N) sum I f_r cos / r^2
 *                   1  vndf: N GGX visible-normal samples per pixel (ggx.h),
 *                      decorrelated between pixels (a hash of the pixel and
 *                      the seed), w_i = reflect(w_o, m), the ray to the light:
 *                      L_s = (1/N) sum L_e(-w_i) G2 / G1(w_o) over the hits
 *                   2  mis: both sets of N, balance heuristic (Veach): each
 *                      sample weighted by its density over the sum of both
 *                      densities in solid angle, p_light = r^2 / (A |n_L . w|)
 * st[2i], st[2i+1]: the light points (host/methods/samples.h); seed: the
 * pixel hash's seed. LB_LUT: the trig-free intensity table (common/lut.h),
 * `lum` is the LUT. LB_SMC_RECT: the straight-line form of sampling=light
 * (common/smc_lanes.inc), one pixel per work-item or, with LB_LANES=8 (float,
 * LUT), eight in float8; tests/specular/test_smc_lanes.cpp holds it to the
 * general kernel.
 * @variants: "" | "-DLB_LUT -DLB_SMC_RECT" | "-DLB_LUT -DLB_SMC_RECT -DLB_LANES=8" | "-DLB_SMC_RECT" | "-DLB_SMC_SAMPLING=1" | "-DLB_SMC_SAMPLING=2" | "-DLB_LUT" | "-DLB_LUT -DLB_SMC_SAMPLING=2"
 */
#include "common/lbmath.h"
#include "common/entry.h"

#ifndef LB_SMC_SAMPLING
#define LB_SMC_SAMPLING 0
#endif

/* 32-bit hash (PCG output permutation of an LCG step): uniform floats in
 * [0, 1) from (pixel, sample, seed). */
LB_FN uint lb_smc_hash(uint v)
{
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

LB_FN real lb_smc_u01(uint h)
{
    return (real)(h >> 8) * R(5.9604644775390625e-8); /* 2^-24: < 1 in float */
}

#define LB_ENTRY_ARGS , __global const real *st, int n, int seed

#ifdef LB_SMC_RECT
#define LB_ENTRY_FORM LB_VFN(lb_smc_rect_light)(P, lum, st, n, &pix_span, &pix_view)
#include "common/entry_straight.inc"
#else
LB_RENDER_KERNEL
{
    LB_RENDER_RECEIVER;
    real3 wo = normalize(lb_p3(P, LB_P_EYE) - x);
    real alpha = P[LB_P_ALPHA];
    real3 t1, t2;
    lb_view_frame(nx, wo, &t1, &t2);
    real ox = dot(wo, t1), oz = dot(wo, nx);
    real area = L.w * L.l;
    real3 o = L.c - L.u * (R(0.5) * L.w) - L.v * (R(0.5) * L.l) - x; /* corner (-u,-v) from x */
    real sum = R(0);
    if (oz > R(0)) {
#if LB_SMC_SAMPLING != 1
        for (int i = 0; i < n; ++i) {
            real3 p = o + L.u * (L.w * st[2 * i]) + L.v * (L.l * st[2 * i + 1]);
            real r2 = dot(p, p);
            if (!(r2 > R(0)))
                continue;
            real r = sqrt(r2);
            real3 w = p / r;
            real iz = dot(w, nx);
            if (!(iz > R(0)))
                continue;
            real ix = dot(w, t1), iy = dot(w, t2);
            real f = lb_ggx_brdf(ix, iy, iz, ox, R(0), oz, alpha);
            real c = lb_intensity_local(lum, lb_to_light_frame(L, -w)) * f * iz / r2;
#if LB_SMC_SAMPLING == 2
            real cl = fabs(dot(L.n, w));
            real pl = cl > R(0) ? r2 / (area * cl) : R(0);
            real pb = lb_ggx_vndf_pdf(ix, iy, iz, ox, R(0), oz, alpha);
            c = pl > R(0) ? c * pl / (pl + pb) : R(0);
#endif
            sum += c;
        }
#endif
#if LB_SMC_SAMPLING != 0
        uint pix = (uint)px;
        for (int i = 0; i < n; ++i) {
            uint h = lb_smc_hash(pix ^ lb_smc_hash((uint)seed * 0x9E3779B9u + (uint)i));
            real u1 = lb_smc_u01(h), u2 = lb_smc_u01(lb_smc_hash(h + 0x68E31DA4u));
            real3 m = lb_ggx_sample_vndf(ox, R(0), oz, alpha, u1, u2);
            real mx = m.x, my = m.y, mz = m.z;
            real dm = ox * mx + oz * mz;
            real ix = R(2) * dm * mx - ox, iy = R(2) * dm * my, iz = R(2) * dm * mz - oz;
            if (!(iz > R(0)))
                continue;
            real3 w = t1 * ix + t2 * iy + nx * iz;
            /* the ray x + tau w against the light's plane and rectangle */
            real dn = dot(L.n, w);
            if (dn == R(0))
                continue;
            real tau = dot(L.n, L.c - x) / dn;
            if (!(tau > R(0)))
                continue;
            real3 p = w * tau;
            real s = dot(p - o, L.u) / L.w, t = dot(p - o, L.v) / L.l;
            if (!(s >= R(0) && s <= R(1) && t >= R(0) && t <= R(1)))
                continue;
            real le = lb_intensity_local(lum, lb_to_light_frame(L, -w)) / (area * fabs(dn));
            real fcos = lb_ggx_brdf(ix, iy, iz, ox, R(0), oz, alpha) * iz;
            real pb = lb_ggx_vndf_pdf(ix, iy, iz, ox, R(0), oz, alpha);
#if LB_SMC_SAMPLING == 1
            sum += pb > R(0) ? le * fcos / pb : R(0);
#else
            real pl = tau * tau / (area * fabs(dn));
            sum += le * fcos / (pl + pb);
#endif
        }
#endif
    }
    out[px] = sum / (real)n;
}
#endif
