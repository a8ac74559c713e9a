// mc_denoise.h -- MC + an image filter as one method: the post-passes of
// kernels/common/denoise.h after mc.cl's render kernel (Family::postPasses).
#pragma once

#include "methods/mc_options.h"
#include "methods/registry.h"

#include <vector>

namespace lb::methods {

// The default footprint is fixed in metres, set at the timing resolution
// (512 pixels over the image's side, DESIGN 6): gauss16 sigma = 4 pixels
// there (taps -8 .. 8), the a-trous filter 5 levels (steps 1 .. 16 pixels);
// at res pixels per side they scale by res / 512 (sigma), by log2(res / 512)
// (levels), so an error image at another resolution sees the same filter in
// metres. At 1080 lines the default Gaussian's radius is ceil(8 x 1080 / 512)
// = 17 pixels, the paper's 16 (its DN 2 x 16 at 1920 x 1080).
// gauss_radius / gauss_sigma (> 0) set the Gaussian in pixels of the image it
// filters, unscaled: the published filter as it ran (gauss_radius=16 alone:
// sigma = radius / 2); where error images and timing differ in resolution
// they differ in metres too.
inline constexpr int kDenoiseRes = 512;
double gaussSigmaPx(int res);
int atrousLevels(int res);

struct GaussShape {
    double sigma;  // pixels
    int radius;  // taps -radius .. radius
};
// The Gaussian of spec keys (gauss_sigma, gauss_radius: 0 = the default) at res.
GaussShape gaussShape(double sigmaKey, int radiusKey, int res);
// Its weights w[0 .. radius] (w[|d|]), summing to 1 over the 2 radius + 1 taps.
std::vector<double> gaussWeights(const GaussShape& g);

// InputError where gauss_sigma / gauss_radius are given without denoise=gauss16.
void validateDenoise(const MethodSpec& s);

// Binds the filters' buffers (named "tmp", "var2", "gw") once, in the plan's bind.
void bindDenoise(LaunchContext& c, const McOptions& o);
// The post-passes of o.denoise (none: no events), stages "denoise_row" and
// "denoise_col" (gauss16), "denoise_var" (a-trous at n = 1: the spatial
// variance), "denoise_l1" .. (a-trous levels, the last one's copy included).
std::vector<StageEvent> denoisePasses(LaunchContext& c, const McOptions& o, double sigmaL, int n);

// MC below one sample per pixel (mc's scale): the render's pixels per side
// at `scale` of res, round(scale res), at least 1; kMinScale the key's least.
inline constexpr double kMinScale = 0.05;
int mcRenderRes(double scale, int res);
// The bilinear upsampling (kernels/common/denoise.h, lb_upsample) of the
// image rendered at c.res() to named["image"] at c.imageRes, stage "upsample".
StageEvent upsamplePass(LaunchContext& c);

}  // namespace lb::methods
