#include "equaltime/protocol.h"

#include "cl/runtime.h"
#include "methods/mc_denoise.h"
#include "methods/spec.h"
#include "util/error.h"
#include "util/json_file.h"

#include <fmt/format.h>

#include <memory>

namespace lb::equaltime {

Options Protocol::options() const
{
    Options o;
    o.tolerance = tolerance;
    o.rounds = rounds;
    o.mode = mode;
    o.minScale = methods::kMinScale;
    return o;
}

nlohmann::json Protocol::json() const
{
    return {
        {"time_res", timeRes}, {"reps", reps},           {"rounds", rounds},    {"tolerance", tolerance}, {"mc", mc},
        {"fit", fit},          {"mode", modeName(mode)}, {"subpixel", subpixel}};
}

const std::vector<std::string>& protocolKeys()
{
    static const std::vector<std::string> keys = {"time_res", "reps", "rounds", "tolerance",
                                                  "mc",       "fit",  "mode",   "subpixel"};
    return keys;
}

Mode parseMode(const std::string& text, const std::string& where)
{
    if (text == "search") return Mode::Search;
    if (text == "aim") return Mode::Aim;
    throw InputError(fmt::format("{}: expected search or aim, found '{}'", where, text));
}

const char* modeName(Mode m) { return m == Mode::Aim ? "aim" : "search"; }

namespace {

// "mc" of the protocol: an mc SPEC without n or extra (the search sets them).
std::string readPartner(const util::JsonKeys& r, SceneKind kind)
{
    const std::string s = r.string("mc");
    methods::MethodSpec spec;
    try {
        spec = methods::parseSpec(s, kind);
    } catch (const InputError& err) {
        r.fail("mc", fmt::format("'{}': {}", s, err.what()));
    }
    if (spec.name != "mc" || spec.given.count("n") || spec.given.count("extra"))
        r.fail("mc", fmt::format("'{}': expected an mc SPEC without n or extra (the search sets them)", s));
    return s;
}

}  // namespace

void readProtocol(const util::JsonKeys& r, Protocol& p, const ReadRules& rules)
{
    for (const auto& [key, where] : rules.elsewhere)
        if (r.has(key)) r.fail(key, fmt::format("set by {}, not here", where));
    if (r.has("time_res")) p.timeRes = static_cast<int>(r.integer("time_res", rules.minTimeRes, rules.maxTimeRes));
    if (r.has("reps")) p.reps = static_cast<int>(r.integer("reps", rules.minReps, ocl::kMaxReps));
    if (r.has("rounds")) p.rounds = static_cast<int>(r.integer("rounds", rules.minReps, ocl::kMaxReps));
    if (r.has("tolerance")) p.tolerance = r.number("tolerance", 0.001, 10);
    if (r.has("mc")) p.mc = readPartner(r, rules.kind);
    if (r.has("fit")) {
        p.fit = r.integers("fit", 1, kMaxN);
        if (p.fit.size() < 2) r.fail("fit", "expected at least two sample counts to fit t(N)");
    }
    if (r.has("mode")) p.mode = parseMode(r.string("mode"), r.name("mode"));
    if (r.has("subpixel")) p.subpixel = r.boolean("subpixel");
}

std::string specAt(const std::string& mc, long n, double extra, double scale)
{
    std::string s = mc + (mc.find(':') == std::string::npos ? ":" : ",") + "n=" + std::to_string(n);
    if (extra > 0) s += fmt::format(",extra={:.3f}", extra);
    if (scale < 1) s += fmt::format(",scale={:.3f}", scale);
    return s;
}

Frames preparedFrames(ocl::Runtime& rt, const photometry::Table& table, const Scene& timed, methods::Precision prec,
                      size_t lx, size_t ly)
{
    return [&rt, &table, timed, prec, lx, ly](const methods::MethodSpec& spec) -> Launch {
        auto p = std::make_shared<methods::Prepared>(rt, table, timed, spec, prec);
        p->setLocal(lx, ly);
        return [p] { return p->launchMs(); };  // whole frames: a multi-pass method's passes count
    };
}

Result pairUp(const Protocol& p, const Frames& frames, const methods::MethodSpec& method, const McAt& mcAt,
              const Curve& fit, double targetMs)
{
    Sides sides;
    sides.method = frames(method);
    sides.mc = [&](long n, double extra) { return frames(mcAt(n, extra)); };
    sides.fractional = mcAt(1, 0).has("extra");
    if (p.subpixel && mcAt(1, 0).has("scale"))
        sides.scaled = [&](double scale) { return frames(mcAt(1, 0).with("scale", fmt::format("{:.3f}", scale))); };
    return search(sides, p.options(), fit, targetMs);
}

}  // namespace lb::equaltime
