// kmath.h -- the kernels' shared math (kernels/common/*.h) compiled as C++.
//
// GLM supplies the OpenCL vector types and built-ins under OpenCL's names, so
// the host and its unit tests run exactly the code the kernels run. The
// headers are included twice: lb::f32 is what a float kernel computes,
// lb::f64 what a -DLB_DOUBLE kernel computes.
#pragma once

#include <cmath>
#include <glm/glm.hpp>

#ifndef __global
#define __global
#endif

#define LB_KMATH_USING    \
    using glm::clamp;     \
    using glm::cross;     \
    using glm::dot;       \
    using glm::length;    \
    using glm::mix;       \
    using glm::normalize; \
    using std::acos;      \
    using std::asin;      \
    using std::atan2;     \
    using std::ceil;      \
    using std::copysign;  \
    using std::cos;       \
    using std::fabs;      \
    using std::floor;     \
    using std::fmax;      \
    using std::fmin;      \
    using std::sin;       \
    using std::sqrt;

namespace lb::f32 {
using real = float;
using real2 = glm::vec2;
using real3 = glm::vec3;
LB_KMATH_USING
#define LB_REAL_IS_DOUBLE 0
#include "../../kernels/common/lbmath.h"
#undef LB_REAL_IS_DOUBLE
}  // namespace lb::f32

namespace lb::f64 {
using real = double;
using real2 = glm::dvec2;
using real3 = glm::dvec3;
LB_KMATH_USING
#define LB_REAL_IS_DOUBLE 1
#include "../../kernels/common/lbmath.h"
#undef LB_REAL_IS_DOUBLE
}  // namespace lb::f64

#undef LB_KMATH_USING
// The short literal macros are for kernel code only; keep them out of C++.
#undef R
#undef R2
#undef R3
