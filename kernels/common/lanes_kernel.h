/* lanes_kernel.h -- the lane width of a straight-line kernel (common/entry.h):
 * eight pixels of a row per work-item in float8 (lanes8.h, with every lane
 * form of lanes_all.inc) where the host asks for LB_LANES=8 (CPUs, float;
 * it then launches ceil(N / 8) work-items per row), else one (lanes1.h: the
 * one-pixel forms lbmath.h instantiates; GPUs, double, the exact lookup). A
 * double build ignores LB_LANES. The kernel ends with lanes_end.h. */
#if defined(LB_LANES) && LB_LANES == 8 && !defined(LB_DOUBLE)
#include "lanes8.h"
#include "lanes_all.inc"
#else
#include "lanes1.h"
#endif
