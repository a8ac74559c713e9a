#include "methods/mc_denoise.h"

#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lb::methods {

double gaussSigmaPx(int res) { return 4.0 * res / kDenoiseRes; }

int atrousLevels(int res)
{
    return std::max(1, 5 + static_cast<int>(std::lround(std::log2(double(res) / kDenoiseRes))));
}

GaussShape gaussShape(double sigmaKey, int radiusKey, int res)
{
    double sigma = sigmaKey > 0 ? sigmaKey : radiusKey > 0 ? radiusKey / 2.0 : gaussSigmaPx(res);
    int radius = radiusKey > 0 ? radiusKey : std::max(1, static_cast<int>(std::ceil(2 * sigma)));
    return {sigma, radius};
}

std::vector<double> gaussWeights(const GaussShape& g)
{
    std::vector<double> w(g.radius + 1);
    double sum = 0;
    for (int d = 0; d <= g.radius; ++d) {
        w[d] = std::exp(-0.5 * d * d / (g.sigma * g.sigma));
        sum += d == 0 ? w[d] : 2 * w[d];
    }
    for (double& x : w) x /= sum;
    return w;
}

void validateDenoise(const MethodSpec& s)
{
    for (const char* k : {"gauss_sigma", "gauss_radius"})
        if (s.given.count(k) && s.num(k) > 0 && s.str("denoise") != "gauss16")
            throw InputError(fmt::format("method mc: {}={} shapes the Gaussian of denoise=gauss16, but denoise={}; "
                                         "add denoise=gauss16 or drop {}=",
                                         k, s.values.at(k), s.str("denoise"), k));
}

void bindDenoise(LaunchContext& c, const McOptions& o)
{
    if (o.denoise == "none") return;
    const size_t npx = static_cast<size_t>(c.res()) * c.res();
    c.named["tmp"] = c.outputReals(npx);
    if (o.denoise == "atrous") c.named["var2"] = c.outputReals(npx);
    if (o.denoise == "gauss16")
        c.named["gw"] = c.realBuffer(gaussWeights(gaussShape(o.gaussSigma, o.gaussRadius, c.res())));
}

std::vector<StageEvent> denoisePasses(LaunchContext& c, const McOptions& o, double sigmaL, int n)
{
    std::vector<StageEvent> ev;
    if (o.denoise == "none") return ev;
    const int res = c.res();
    // eight pixels of a row per work-item (kernels/common/denoise.h)
    const size_t gx = (static_cast<size_t>(res) + 7) / 8, lx = 8, ly = 8;
    cl::Buffer out = c.named.at("out"), tmp = c.named.at("tmp");
    auto launch = [&](const std::string& stage, cl::Kernel& k) {
        ev.push_back({stage, c.rt.launch2D(k, gx, res, lx, ly)});
    };
    if (o.denoise == "gauss16") {
        const cl_int radius = gaussShape(o.gaussSigma, o.gaussRadius, res).radius;
        cl::Buffer w = c.named.at("gw");
        launch("denoise_row", c.bind(c.pass("lb_gauss"), out, tmp, cl_int(res), w, radius, cl_int(0)));
        launch("denoise_col", c.bind(c.pass("lb_gauss"), tmp, out, cl_int(res), w, radius, cl_int(1)));
        return ev;
    }
    // one sample: no variance from the render (-1), SVGF's spatial estimate
    if (n < 2) launch("denoise_var", c.bind(c.pass("lb_var_spatial"), out, c.named.at("var"), cl_int(res)));
    // a-trous: levels ping-pong between (out, var) and (tmp, var2); an odd
    // count ends in tmp, copied back (its time counts too)
    cl::Buffer img[2] = {out, tmp}, var[2] = {c.named.at("var"), c.named.at("var2")};
    const int levels = atrousLevels(res);
    for (int i = 0; i < levels; ++i) {
        const int a = i & 1, b = a ^ 1;
        // (arguments are captured when a launch is enqueued: one kernel object serves every level);
        // the last level's variance is not read: not filtered
        launch(fmt::format("denoise_l{}", i + 1),
               c.bind(c.pass("lb_atrous"), img[a], var[a], img[b], var[b], cl_int(res), cl_int(1 << i),
                      LaunchContext::Real{sigmaL}, cl_int(i + 1 < levels)));
    }
    if (levels & 1) {
        cl::Event e;
        c.rt.queue().enqueueCopyBuffer(
            tmp, out, 0, 0, static_cast<size_t>(res) * res * (c.dbl() ? sizeof(double) : sizeof(float)), nullptr, &e);
        ev.push_back({fmt::format("denoise_l{}", levels), e});
    }
    return ev;
}

int mcRenderRes(double scale, int res)
{
    return std::clamp(static_cast<int>(std::lround(scale * res)), 1, std::max(1, res));
}

StageEvent upsamplePass(LaunchContext& c)
{
    cl::Kernel& k =
        c.bind(c.pass("lb_upsample"), c.named.at("out"), cl_int(c.res()), c.named.at("image"), cl_int(c.imageRes));
    // eight pixels of a row per work-item (kernels/common/denoise.h)
    return {"upsample", c.rt.launch2D(k, (static_cast<size_t>(c.imageRes) + 7) / 8, c.imageRes, 8, 8)};
}

}  // namespace lb::methods
