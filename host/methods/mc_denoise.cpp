#include "methods/mc_denoise.h"

#include <algorithm>
#include <cmath>

namespace lb::methods {

double gaussSigmaPx(int res) { return 4.0 * res / kDenoiseRes; }

int atrousLevels(int res)
{
    return std::max(1, 5 + static_cast<int>(std::lround(std::log2(double(res) / kDenoiseRes))));
}

void bindDenoise(LaunchContext& c, const McOptions& o)
{
    if (o.denoise == "none") return;
    const size_t npx = static_cast<size_t>(c.res()) * c.res();
    c.named["tmp"] = c.outputReals(npx);
    if (o.denoise == "atrous") c.named["var2"] = c.outputReals(npx);
}

std::vector<StageEvent> denoisePasses(LaunchContext& c, const McOptions& o, double sigmaL)
{
    std::vector<StageEvent> ev;
    if (o.denoise == "none") return ev;
    const int res = c.res();
    const size_t lx = 8, ly = 8;
    cl::Buffer out = c.named.at("out"), tmp = c.named.at("tmp");
    auto launch = [&](cl::Kernel& k) { ev.push_back({"denoise", c.rt.launch2D(k, res, res, lx, ly)}); };
    if (o.denoise == "gauss16") {
        const double sigma = gaussSigmaPx(res);
        const int radius = std::max(1, static_cast<int>(std::ceil(2 * sigma)));
        using R = LaunchContext::Real;
        launch(c.bind(c.pass("lb_gauss"), out, tmp, cl_int(res), R{sigma}, cl_int(radius), cl_int(0)));
        launch(c.bind(c.pass("lb_gauss"), tmp, out, cl_int(res), R{sigma}, cl_int(radius), cl_int(1)));
        return ev;
    }
    // a-trous: levels ping-pong between (out, var) and (tmp, var2); an odd
    // count ends in tmp, copied back (its time counts too)
    cl::Buffer img[2] = {out, tmp}, var[2] = {c.named.at("var"), c.named.at("var2")};
    const int levels = atrousLevels(res);
    for (int i = 0; i < levels; ++i) {
        const int a = i & 1, b = a ^ 1;
        // (arguments are captured when a launch is enqueued: one kernel object serves every level)
        launch(c.bind(c.pass("lb_atrous"), img[a], var[a], img[b], var[b], cl_int(res), cl_int(1 << i),
                      LaunchContext::Real{sigmaL}));
    }
    if (levels & 1) {
        cl::Event e;
        c.rt.queue().enqueueCopyBuffer(
            tmp, out, 0, 0, static_cast<size_t>(res) * res * (c.dbl() ? sizeof(double) : sizeof(float)), nullptr, &e);
        ev.push_back({"denoise", e});
    }
    return ev;
}

}  // namespace lb::methods
