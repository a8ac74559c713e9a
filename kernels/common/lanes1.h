/* lanes1.h, lanes8.h, lanes_end.h -- lane-generic code, written once.
 *
 * A *_lanes.inc file in this directory is written over the macros below and
 * included once per lane width, the way host/math/kmath.h includes the whole
 * math once per precision:
 *   lanes1.h  one pixel per work-item (C++ host and every OpenCL device):
 *             the value type is `real`, the functions keep their names;
 *   lanes8.h  eight pixels per work-item in float8 (OpenCL, float only):
 *             names get the suffix _x8. PoCL's work-item loop vectoriser
 *             gives up on code whose (u, v) pairs its SLP pass has already
 *             packed into 2-wide vectors; explicit float8 does not depend on it.
 * Macros: LB_V value, LB_I integer, LB_M comparison result (bool / int8: both
 * work with ?:, && and ||), LB_VFN(name), LB_TO_I / LB_TO_V conversions
 * (float -> int truncates, as (int)), LB_U the unsigned 32-bit integer with
 * LB_TO_U (from LB_I) and LB_U_TO_V (to the value type), LB_GATHER(p, i) = p[i] per lane, and
 * LB_VINTENSITY3(lum, x, y, z) the intensity lookup of the lane type,
 * LB_NLANES the pixels per call and LB_LANE_INDEX their column offsets,
 * LB_ANY(m) whether any lane's m holds (a branch uniform over the lanes),
 * LB_STORE(out, i, left, e) writes the pixels' values e at out[i ..], only the
 * first `left` of them (a row's end).
 * lanes_end.h undefines them again. */
#define LB_V real
#define LB_I int
#define LB_M bool
#define LB_VFN(name) name
#define LB_TO_I(x) ((int)(x))
#define LB_TO_V(x) ((real)(x))
#define LB_U lb_u32
#define LB_TO_U(x) ((lb_u32)(x))
#define LB_U_TO_V(x) ((real)(x))
#define LB_GATHER(p, i) ((real)(p)[(i)])
#define LB_VINTENSITY3(lum, x, y, z) LB_INTENSITY3((lum), (x), (y), (z))
#define LB_NLANES 1
#define LB_ANY(m) (m)
#define LB_LANE_INDEX R(0)
#define LB_STORE(out, i, left, e) ((void)(left), (out)[(i)] = (e))
