/* mc_sample.h -- sampling the light for Monte Carlo (kernels/mc.cl):
 * per-pixel sequences in [0,1)^2 and the maps from them to directions or
 * points on the light. Compiles as OpenCL C and C++ (vec.h); the host tests
 * (tests/methods/test_mc_sampling.cpp) run this code.
 *
 * Geometry is in the light's frame (u, v, n_L) with the receiver point at the
 * origin: the light's corner (-u, -v) lies at (ou, ov, on) (scene_lanes.inc),
 * a point (s, t) of the light at (ou + W s, ov + L t, on); the receiver
 * normal is (au, av, an) there (lb_receiver_normal_local). */

typedef unsigned int lb_u32;

/* The per-sample code is written with plain arithmetic and selects (no
 * fabs, fmin, fmax, clamp, copysign, mix built-ins), and in float OpenCL
 * with the hardware sqrt / cos / sin: PoCL's CPU library implements the
 * built-ins with 4-wide SSE values, which stops its work-item loop
 * vectoriser (as common/lut.h says; measured here: solid-angle sampling 80x
 * area sampling with them); a few ulp are far below the estimators' noise. */
#define LB_MC_CLAMP(x, lo, hi) ((x) < (lo) ? (lo) : ((x) > (hi) ? (hi) : (x)))

#if defined(__OPENCL_C_VERSION__) && !LB_REAL_IS_DOUBLE
#define LB_MC_SQRT(x) native_sqrt(x)
#define LB_MC_SINCOS(x, c) lb_mc_sincos_poly(x, c)
#else
#define LB_MC_SQRT(x) sqrt(x)
#define LB_MC_SINCOS(x, c) (*(c) = cos(x), sin(x))
#endif

/* ---- integer hashing and sequences ---------------------------------------- */

#include "lanes1.h" /* the lane-generic integer and trig helpers, one pixel */
#include "mc_lanes.inc"
#include "lanes_end.h"

/* (u0, u1) uniform in [0,1]^2 to a point uniform on the disk inscribed in
 * [0,1]^2, in place: Shirley and Chiu's (1997) concentric map, continuous
 * and area-preserving up to a constant (strata stay strata). The disk
 * light's area samples (mc on LB_SHAPE_DISK: on the host for the shared
 * set, in mc.cl's extended path per pixel). */
LB_FN void lb_mc_concentric(real* u0, real* u1)
{
    real a = R(2) * *u0 - R(1), b = R(2) * *u1 - R(1);
    real r = R(0), phi = R(0);
    if (fabs(a) > fabs(b)) {
        r = a;
        phi = R(0.25) * LB_PI * (b / a);
    } else if (b != R(0)) {
        r = b;
        phi = R(0.5) * LB_PI - R(0.25) * LB_PI * (a / b);
    }
    real c, s = LB_MC_SINCOS(phi, &c);
    *u0 = R(0.5) + R(0.5) * r * c;
    *u1 = R(0.5) + R(0.5) * r * s;
}

/* Sobol, ZSobol, the bilinear warp, solid angle (spherical rectangles) and
 * projected solid angle: common/mc_lanes.inc and common/proj_lanes.inc. */
