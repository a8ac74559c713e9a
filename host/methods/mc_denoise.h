// mc_denoise.h -- MC + an image filter as one method: the post-passes of
// kernels/common/denoise.h after mc.cl's render kernel (Family::postPasses).
#pragma once

#include "methods/mc_options.h"
#include "methods/registry.h"

#include <vector>

namespace lb::methods {

// The filters' footprint is fixed in metres, set at the timing resolution
// (512 pixels over the image's side, DESIGN 6): gauss16 sigma = 4 pixels
// there (taps -8 .. 8, the paper's 2 x 16), the a-trous filter 5 levels
// (steps 1 .. 16 pixels); at res pixels per side they scale by res / 512
// (sigma), by log2(res / 512) (levels), so an error image at another
// resolution sees the same filter in metres.
inline constexpr int kDenoiseRes = 512;
double gaussSigmaPx(int res);
int atrousLevels(int res);

// Binds the filters' buffers (named "tmp", "var2") once, in the plan's bind.
void bindDenoise(LaunchContext& c, const McOptions& o);
// The post-passes of o.denoise (none: no events).
std::vector<StageEvent> denoisePasses(LaunchContext& c, const McOptions& o, double sigmaL);

}  // namespace lb::methods
