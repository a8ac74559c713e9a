// indirect_math.h -- kernels/common/indirect.h (the room of the indirect
// scene, virtual lights, the converged bounce) compiled as C++ in lb::f32 and
// lb::f64, after math/kmath.h, so host tests run the kernels' code.
#pragma once

#include "math/kmath.h"

#define R(x) ((real)(x))
#define R2(x, y) (real2((x), (y)))
#define R3(x, y, z) (real3((x), (y), (z)))

namespace lb::f32 {
#include "../../kernels/common/indirect.h"
}  // namespace lb::f32

namespace lb::f64 {
#include "../../kernels/common/indirect.h"
}  // namespace lb::f64

#undef R
#undef R2
#undef R3
