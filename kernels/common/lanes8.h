/* lanes8.h -- eight lanes of float (see lanes1.h). OpenCL only; needs the
 * trig-free table (-DLB_LUT): the exact lookup's binary search has no lane
 * form. */
#define LB_V float8
#define LB_I int8
#define LB_M int8
#define LB_VFN(name) name##_x8
#define LB_TO_I(x) convert_int8(x)
#define LB_TO_V(x) convert_float8(x)
#define LB_U uint8
#define LB_TO_U(x) as_uint8(x)
#define LB_U_TO_V(x) convert_float8(x)
#define LB_GATHER(p, i)                                                                                        \
    ((float8)((p)[(i).s0], (p)[(i).s1], (p)[(i).s2], (p)[(i).s3], (p)[(i).s4], (p)[(i).s5], (p)[(i).s6],    \
              (p)[(i).s7]))
#define LB_VINTENSITY3(lum, x, y, z) lb_lut_intensity3_x8((lum), (x), (y), (z))
#define LB_NLANES 8
#define LB_ANY(m) any(m)
#define LB_LANE_INDEX ((float8)(0, 1, 2, 3, 4, 5, 6, 7))
#define LB_STORE(out, i, left, e) lb_store_x8((out), (i), (left), (e))
