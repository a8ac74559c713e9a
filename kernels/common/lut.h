/* lut.h -- trig-free intensity lookup. Compiles as OpenCL C and C++.
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
/* 1 / sqrt(x): one hardware instruction on GPUs (NVIDIA: rsqrt.approx, a few
 * ulp), where R(1) / native_sqrt(x) costs an IEEE division as well. */
#define LB_LUT_RSQRT(x) native_rsqrt(x)
#else
#define LB_LUT_SQRT(x) sqrt(x)
#define LB_LUT_RSQRT(x) (R(1) / sqrt(x))
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

/* lb_lut_intensity3(lut, x, y, z): lut_lanes.inc, one pixel per call here. */
#include "lanes1.h"
#include "lut_lanes.inc"
#include "lanes_end.h"

LB_FN real lb_lut_intensity(__global const float* lut, real3 d)
{
    return lb_lut_intensity3(lut, d.x, d.y, d.z);
}
