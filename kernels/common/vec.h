/* vec.h -- the shim that lets every header in kernels/common compile both as
 * OpenCL C (inside a kernel) and as C++ (host code and host unit tests).
 *
 * Conventions for code in kernels/common:
 *   - scalar type `real`, vectors `real2`, `real3`; float or double is chosen by
 *     the includer (OpenCL: -DLB_DOUBLE; host: the namespace lb::f32 / lb::f64,
 *     see host/math/kmath.h);
 *   - literals through R(x) so that float code never silently promotes to
 *     double; vectors built with R3(x, y, z);
 *   - functions declared LB_FN; names are unique (OpenCL C has no overloads);
 *   - tables of constants declared LB_CONSTANT (__constant in OpenCL C);
 *   - only the OpenCL built-ins that GLM / <cmath> also provide under the same
 *     name: dot, cross, normalize, length, clamp, mix, sqrt, fabs, fmin, fmax,
 *     atan2, acos, asin, sin, cos, floor, ceil, copysign;
 *   - global buffers as `__global const float*` (the host defines __global
 *     away);
 *   - the headers have no include guards of their own: kernels include
 *     "common/lbmath.h" exactly once, the host includes it once per precision.
 */
#ifdef __OPENCL_C_VERSION__

#ifdef LB_DOUBLE
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double real;
typedef double2 real2;
typedef double3 real3;
#define LB_REAL_IS_DOUBLE 1
#else
typedef float real;
typedef float2 real2;
typedef float3 real3;
#define LB_REAL_IS_DOUBLE 0
#endif

#define LB_FN static inline
/* A helper PoCL would keep out of line although inlining it pays: a lane
 * struct returned by value goes through the stack, and every call spills the
 * caller's live vectors (measured: the 8-lane fan 13 % faster with its five
 * lookups inlined). */
#define LB_FN_INLINE static inline __attribute__((always_inline))
#define LB_CONSTANT __constant
#define R3(x, y, z) ((real3)((x), (y), (z)))
#define R2(x, y) ((real2)((x), (y)))
#define LB_IMIN(a, b) min((a), (b))
#define LB_IMAX(a, b) max((a), (b))

#else /* C++ host: the includer has defined real, real2, real3 and LB_REAL_IS_DOUBLE */

#define LB_FN inline
#define LB_FN_INLINE inline
#define LB_CONSTANT static const
#define R3(x, y, z) (real3((x), (y), (z)))
#define R2(x, y) (real2((x), (y)))
#define LB_IMIN(a, b) ((a) < (b) ? (a) : (b))
#define LB_IMAX(a, b) ((a) > (b) ? (a) : (b))

#endif

#define R(x) ((real)(x))
#define LB_PI ((real)3.14159265358979323846)
#define LB_TWO_PI ((real)6.28318530717958647692)
#define LB_DEG ((real)57.2957795130823208768)  /* degrees per radian */

/* Largest vertex count of any polygon the kernels handle: a quad clipped by
 * the horizon plane and by the tilted horizon plane has at most 6 vertices,
 * plus room for inserted dynamic points in the triangulation. */
#define LB_MAXV 8
