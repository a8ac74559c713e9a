/* lbmath.h -- the one include for all shared math, in dependency order.
 * Kernels: #include "common/lbmath.h" once. Host: host/math/kmath.h. */
#include "vec.h"
#include "spherical.h"
#include "polygon.h"
#include "lut.h"
#include "photometry.h"
#include "scene.h"
#include "dynamic.h"
#include "cubature.h"
#include "voronoi.h"
#include "ggx.h"
#include "ltc.h"
#include "adaptive.h"
#include "specref.h"
#include "mc_sample.h"
#include "mc_table.h"
#include "denoise_math.h"
#include "sh.h"
/* The point-sample baselines', the LTC's and the specular MC's straight-line
 * forms, one pixel per call (lanes_all.inc lists every form in this order). */
#include "lanes1.h"
#include "dynamic_lanes.inc"
#include "engine_lanes.inc"
#include "ltc_lanes.inc"
#include "smc_lanes.inc"
#include "lanes_end.h"
/* The disk light: uses the polynomial sin / cos / atan2 above. */
#include "disk.h"
/* Solid-angle sampling of the disk light: uses mc_sample.h's sampler parts. */
#include "disk_sample.h"
