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
/* The point-sample baselines' straight-line forms, one pixel per call (they
 * use cubature_lanes.inc's sample and triangle helpers). */
#include "lanes1.h"
#include "dynamic_lanes.inc"
#include "lanes_end.h"
