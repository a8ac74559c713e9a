/* lut.h -- trig-free intensity lookup (issue 9). Compiles as OpenCL C and C++.
 *
 * The exact lookup (photometry.h) needs acos/atan2 and two binary searches per
 * sample. Here the luminaire is resampled once (host/photometry/lut.h) on a
 * uniform grid over two "diamond" pseudo-angles that need one sqrt and one
 * (shared) division, no trigonometry and no search:
 *
 *   q = rho / (rho + |z|)       for z >= 0,   2 - rho / (rho + |z|) for z < 0,
 *       rho = sqrt(x^2 + y^2): q in [0, 2] grows monotonically with gamma
 *       (q = 1 at gamma = 90 deg); dgamma/dq lies in [1, 2] rad;
 *   a = y / (|x| + |y|)         for x >= 0,   2 - y / (|x| + |y|) for x < 0,
 *       plus 4 when negative: a in [0, 4) grows monotonically with C;
 *       dC/da lies in [1, 2] rad.
 *
 * Packed buffer (floats):
 *   lut[0] = ng   gamma cells (ng + 1 nodes spanning the measured gamma range)
 *   lut[1] = na   azimuth cells (na + 1 nodes over a in [0, 4], node na == node 0)
 *   lut[2] = q0, lut[3] = q1   pseudo-gamma of the first / last measured gamma
 *   lut[4] = ng / (q1 - q0),   lut[5] = na / 4
 *   lut[6], lut[7]  unused
 *   lut[LB_LUT_HEADER + ia * (ng + 1) + ig]   cd at azimuth node ia, gamma node ig
 * Outside [q0, q1] the intensity is 0, as for the exact lookup, so the jump at
 * the end of the measured range stays sharp.
 *
 * -DLB_LUT_1D (rotationally symmetric luminaires): only azimuth column 0 is read.
 * -DLB_LUT in a kernel makes lb_intensity_local (photometry.h) use this lookup;
 * the kernel's `lum` buffer must then be the packed LUT. */

#define LB_LUT_HEADER 8

/* The lookup is written with plain arithmetic and selects (no fabs, fmin,
 * mix, min built-ins) and native_sqrt for float: PoCL's CPU library
 * implements those built-ins with 4-wide SSE values, which stops its
 * work-item loop vectoriser ("instruction return type cannot be
 * vectorized"). native_sqrt is the hardware square root there; on GPUs it is
 * within a few ulp, far below the table's own error. */
#if defined(__OPENCL_C_VERSION__) && !LB_REAL_IS_DOUBLE
#define LB_LUT_SQRT(x) native_sqrt(x)
#else
#define LB_LUT_SQRT(x) sqrt(x)
#endif

/* Pseudo-gamma q in [0, 2] of a direction (x, y, z) in the luminaire frame. */
LB_FN real lb_lut_q(real rho, real z)
{
    real s = rho + fabs(z);
    real t = s > R(0) ? rho / s : R(0);
    return z >= R(0) ? t : R(2) - t;
}

/* Pseudo-azimuth a in [0, 4) of (x, y); 0 on the axis. */
LB_FN real lb_lut_a(real x, real y)
{
    real s = fabs(x) + fabs(y);
    real p = s > R(0) ? y / s : R(0);
    real a = x >= R(0) ? p : R(2) - p;
    return a < R(0) ? a + R(4) : a;
}

/* Intensity (cd) in direction (x, y, z) of the luminaire frame, not
 * necessarily normalised. Bilinear on the uniform (q, a) grid. */
LB_FN real lb_lut_intensity3(__global const float* lut, real x, real y, real z)
{
    int ng = (int)lut[0];
    real rho = LB_LUT_SQRT(x * x + y * y);
    real sg = rho + (z < R(0) ? -z : z);
    /* q and a share one division: 1 / ((rho + |z|) (|x| + |y|)). On the axis
     * (|x| + |y| = 0, so rho = 0) both pseudo-angles are 0 / q(z). The 1D
     * variant computes q the same way, so that it equals the 2D one to the
     * last bit. */
    real sa = (x < R(0) ? -x : x) + (y < R(0) ? -y : y);
    real inv = R(1) / (sg * sa);
    real t = sa > R(0) ? rho * sa * inv : R(0);
    real q = z >= R(0) ? t : R(2) - t;
#ifndef LB_LUT_1D
    real p = sa > R(0) ? y * sg * inv : R(0);
    real a = x >= R(0) ? p : R(2) - p;
    a = a < R(0) ? a + R(4) : a;
#endif
    real fg = (q - (real)lut[2]) * (real)lut[4];
    /* Branch-free (the loop vectoriser if-converts no loads): read a clamped
     * cell, then zero the result outside the measured range. */
    real keep = (fg >= R(0) && fg <= (real)ng) ? R(1) : R(0);
    fg = fg < R(0) ? R(0) : fg;
    fg = fg > (real)ng ? (real)ng : fg;
    int ig = (int)fg;
    ig = ig > ng - 1 ? ng - 1 : ig;
    real tg = fg - (real)ig;
#ifdef LB_LUT_1D
    __global const float* c0 = lut + LB_LUT_HEADER + ig;
    return keep * ((real)c0[0] + ((real)c0[1] - (real)c0[0]) * tg);
#else
    int na = (int)lut[1];
    real fa = a * (real)lut[5];
    int ia = (int)fa;
    ia = ia > na - 1 ? na - 1 : ia;
    real ta = fa - (real)ia;
    __global const float* c0 = lut + LB_LUT_HEADER + ia * (ng + 1) + ig;
    __global const float* c1 = c0 + (ng + 1);
    real lo = (real)c0[0] + ((real)c0[1] - (real)c0[0]) * tg;
    real hi = (real)c1[0] + ((real)c1[1] - (real)c1[0]) * tg;
    return keep * (lo + (hi - lo) * ta);
#endif
}

LB_FN real lb_lut_intensity(__global const float* lut, real3 d)
{
    return lb_lut_intensity3(lut, d.x, d.y, d.z);
}
