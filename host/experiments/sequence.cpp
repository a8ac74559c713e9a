#include "experiments/sequence.h"

#include "metrics/metrics.h"
#include "methods/spec.h"
#include "util/error.h"

#include <fmt/format.h>

#include <memory>

namespace lb::experiments {

Scene sequenceFrame(const Scene& base, const SequencePath& path, int f)
{
    if (path.frames < 2) throw InputError(fmt::format("sequence: frames must be >= 2, got {}", path.frames));
    const double t = path.from + (path.to - path.from) * f / (path.frames - 1);
    Scene s = base;
    if (path.kind == "rotate")
        s.rotation = t;
    else if (path.kind == "lift")
        s.height = t;
    else
        throw InputError(fmt::format("sequence: path '{}' is not one of rotate|lift", path.kind));
    return s;
}

namespace {

// mean_i ((A1 - A0) - (R1 - R0))^2, the numerator of both flicker forms.
double diffMse(const Image& r0, const Image& r1, const Image& a0, const Image& a1)
{
    double sum = 0;
    for (size_t i = 0; i < r1.px.size(); ++i) {
        const double d = (a1.px[i] - a0.px[i]) - (r1.px[i] - r0.px[i]);
        sum += d * d;
    }
    return sum / r1.px.size();
}

double flickerTerm(const Image& r0, const Image& r1, const Image& a0, const Image& a1)
{
    const size_t n = r1.px.size();
    double sum = 0, mr = 0, ma = 0;
    for (size_t i = 0; i < n; ++i) {
        const double d = (a1.px[i] - a0.px[i]) - (r1.px[i] - r0.px[i]);
        sum += d * d;
        mr += r1.px[i];
        ma += a1.px[i];
    }
    mr /= n;
    ma /= n;
    return sum / n / (mr * ma);
}

}  // namespace

nlohmann::json runSequence(ocl::Runtime& rt, const photometry::Table& table, const Scene& base,
                           const SequencePath& path, const std::vector<std::string>& specs, methods::Precision p,
                           const SequenceOptions& opt)
{
    std::vector<methods::MethodSpec> parsed;
    for (auto& s : specs) parsed.push_back(methods::parseSpec(s, base.kind));
    const methods::MethodSpec refSpec = methods::parseSpec(opt.referenceSpec, base.kind);
    for (int f = 0; f < path.frames; ++f) sequenceFrame(base, path, f).validate();  // every frame, before any work

    std::vector<std::unique_ptr<methods::Prepared>> preps;
    for (auto& s : parsed) {
        preps.push_back(std::make_unique<methods::Prepared>(rt, table, sequenceFrame(base, path, 0), s, p));
        preps.back()->reset();
    }
    nlohmann::json frames = nlohmann::json::array();
    std::vector<Image> prevA(parsed.size());
    Image prevR;
    std::vector<double> flicker(parsed.size(), 0.0), nmseSum(parsed.size(), 0.0), timeSum(parsed.size(), 0.0),
        diffSum(parsed.size(), 0.0);
    double refMeanSum = 0;
    for (int f = 0; f < path.frames; ++f) {
        const Scene sc = sequenceFrame(base, path, f);
        methods::RenderOptions ro = opt.render;
        ro.reps = 1;
        Image ref = methods::render(rt, table, sc, refSpec, p, ro).image;
        nlohmann::json per = nlohmann::json::object();
        for (size_t m = 0; m < parsed.size(); ++m) {
            auto& prep = *preps[m];
            if (f > 0) prep.setScene(sc);
            double ms = prep.launchMs();
            Image img = prep.image();
            metrics::Metrics mt = metrics::compare(ref, img);
            nlohmann::json j = mt;
            j["time_ms"] = ms;
            nmseSum[m] += mt.nmse;
            timeSum[m] += ms;
            if (f > 0) {
                double fl = flickerTerm(prevR, ref, prevA[m], img);
                j["flicker"] = fl;
                flicker[m] += fl;
                diffSum[m] += diffMse(prevR, ref, prevA[m], img);
            }
            per[specs[m]] = j;
            prevA[m] = std::move(img);
        }
        double mr = 0;
        for (double v : ref.px) mr += v;
        refMeanSum += mr / ref.px.size();
        prevR = std::move(ref);
        frames.push_back({{"frame", f}, {"param", path.kind == "rotate" ? sc.rotation : sc.height}, {"methods", per}});
    }
    nlohmann::json fl = nlohmann::json::object(), fls = nlohmann::json::object(), mean = nlohmann::json::object();
    const double seqMean = refMeanSum / path.frames;
    for (size_t m = 0; m < parsed.size(); ++m) {
        fl[specs[m]] = flicker[m] / (path.frames - 1);
        fls[specs[m]] = diffSum[m] / (path.frames - 1) / (seqMean * seqMean);
        mean[specs[m]] = {{"nmse", nmseSum[m] / path.frames}, {"time_ms", timeSum[m] / path.frames}};
    }
    return {{"path", {{"kind", path.kind}, {"from", path.from}, {"to", path.to}, {"frames", path.frames}}},
            {"scene", base.describe()},
            {"frames", frames},
            {"flicker", fl},
            {"flicker_seq", fls},
            {"mean", mean}};
}

}  // namespace lb::experiments
