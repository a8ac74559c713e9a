// family.h -- a method family and one method resolved from it: what the
// registry holds (methods/registry.h, which says how to add a family), what
// parseSpec returns (methods/spec.h) and what a render is planned from.
#pragma once

#include "cl/runtime.h"
#include "methods/param.h"
#include "metrics/image.h"
#include "photometry/table.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace lb::methods {

enum class Precision { Float, Double };
std::string precisionName(Precision p);
Precision parsePrecision(const std::string& s);  // "float" | "double", else InputError (the caller names the source)

struct Family;
struct Plan;

// One method resolved: its family (found once, by parseSpec in methods/spec.h)
// and the values of its parameters, checked against the family's table.
struct MethodSpec {
    std::string name;
    SceneKind kind = SceneKind::Diffuse;  // the scene its family renders
    std::map<std::string, std::string> values;  // every parameter, canonical text, defaults filled in
    std::set<std::string> given;  // the keys the SPEC named

    // The family parseSpec resolved; Error for a spec no parser made.
    const Family& family() const;
    // What the family decides for one render (Family::plan).
    Plan plan(const Scene& scene, const photometry::Table& table, const ocl::DeviceInfo& device,
              Precision precision) const;

    double num(const std::string& key) const;  // Real / Int parameters
    long integer(const std::string& key) const;
    const std::string& str(const std::string& key) const;  // Choice parameters
    std::vector<std::string> list(const std::string& key) const;  // List parameters
    bool has(const std::string& key) const { return values.count(key) != 0; }
    // A copy with `key` set to `value` (the keys given stay given), checked
    // as parseSpec checks a SPEC: InputError for a key the family lacks or a
    // bad value.
    MethodSpec with(const std::string& key, const std::string& value) const;

    // name:key=value,... with every parameter, keys sorted (cache keys, logs).
    std::string canonical() const;
    // {key: value}, numbers as JSON numbers (result files).
    nlohmann::json paramsJson() const;

    const Family* fam = nullptr;  // set by parseSpec
};

// One pre-pass kernel's event and the stage it belongs to.
struct StageEvent {
    std::string stage;
    cl::Event event;
};

// The arguments every family's kernel starts with: P, lum, out, row0.
inline constexpr cl_uint kCommonArgs = 4;

// What a family sees while it sets up and finishes one render.
struct LaunchContext {
    const Family& family;
    ocl::Runtime& rt;
    const MethodSpec& spec;
    const Scene& scene;
    const photometry::Table& table;
    Precision precision;
    cl::Kernel kernel;
    std::vector<cl::Buffer> buffers;  // kept alive until the render ends
    std::map<std::string, Image> extraImages;  // e.g. "err" for the reference
    std::map<std::string, cl::Buffer> named;  // buffers the plan hands to finish (e.g. "stats")
    nlohmann::json stats = nlohmann::json::object();  // named counters for the result file
    int lanes = 1;  // pixels of a row per work-item (Plan::lanes)
    std::string options{};  // the program's -D options
    std::map<std::string, cl::Kernel> passKernels{};
    int frame = 0;  // launches since the last reset (stateful methods)
    int imageRes = 0;  // pixels per side of the image; scene.res where Plan::renderRes renders fewer
    // A kernel of the family's program (Family::file built with `options`) by
    // name, made once: the pre-passes' kernels.
    cl::Kernel& pass(const std::string& name);

    bool dbl() const { return precision == Precision::Double; }
    int res() const { return scene.res; }  // the render kernel's pixels per side (Plan::renderRes)
    // A read-only buffer of reals (float or double as the kernel was built).
    cl::Buffer realBuffer(const std::vector<double>& v);
    // A device buffer of n reals / ints to be written by the kernel.
    cl::Buffer outputReals(size_t n);
    cl::Buffer outputInts(size_t n);
    // Reads back n reals as doubles.
    std::vector<double> readReals(cl::Buffer& b, size_t n);
    // Binds the family's argument `name` (one of Family::args); Error when the
    // family declares no such argument.
    template <class T>
    void arg(const std::string& name, const T& value)
    {
        kernel.setArg(argIndex(name), value);
    }
    void realArg(const std::string& name, double value);  // float or double as the program was built
    cl_uint argIndex(const std::string& name) const;

    // A `real` argument of bind(): float or double as the program was built.
    struct Real {
        double v;
    };
    // Binds a pass kernel's arguments 0, 1, ... in order (buffers, cl_int,
    // Real{x}); returns the kernel.
    template <class... A>
    cl::Kernel& bind(cl::Kernel& k, const A&... a)
    {
        cl_uint i = 0;
        (bindOne(k, i++, a), ...);
        return k;
    }

private:
    template <class T>
    void bindOne(cl::Kernel& k, cl_uint i, const T& v)
    {
        k.setArg(i, v);
    }
    void bindOne(cl::Kernel& k, cl_uint i, Real r) { ocl::setReal(k, i, r.v, dbl()); }
};

// One kernel argument a plan binds, by its name in Family::args: a real
// (float or double as the program is built), an int, a float, a read-only
// buffer of reals or floats, an output buffer of `count` ints or reals (kept
// in LaunchContext::named under the argument's name, for `finish` and the
// passes), or a device buffer of the family's own that Plan::bind makes and
// binds (Device: the pre-passes' buffers).
struct PlanArg {
    enum class Kind { Real, Int, Float, Reals, Floats, OutputInts, OutputReals, Device };
    std::string name;
    Kind kind = Kind::Real;
    double value = 0;  // Real, Int, Float
    std::vector<double> reals{};  // Reals
    std::vector<float> floats{};  // Floats
    size_t count = 0;  // OutputInts, OutputReals

    static PlanArg real(const std::string& name, double v) { return {name, Kind::Real, v}; }
    static PlanArg integer(const std::string& name, long v) { return {name, Kind::Int, static_cast<double>(v)}; }
    static PlanArg single(const std::string& name, double v) { return {name, Kind::Float, v}; }
    static PlanArg realBuffer(const std::string& name, std::vector<double> v)
    {
        return {name, Kind::Reals, 0, std::move(v)};
    }
    static PlanArg floatBuffer(const std::string& name, std::vector<float> v)
    {
        return {name, Kind::Floats, 0, {}, std::move(v)};
    }
    static PlanArg outputInts(const std::string& name, size_t n) { return {name, Kind::OutputInts, 0, {}, {}, n}; }
    static PlanArg outputReals(const std::string& name, size_t n) { return {name, Kind::OutputReals, 0, {}, {}, n}; }
    static PlanArg device(const std::string& name) { return {name, Kind::Device}; }
};

// What a family decides for one render of spec on scene and table, on a
// device in a precision, before any device work (so a test can read it
// without a device): the program's -D options (structural and per scene;
// render adds LB_DOUBLE and LB_LANES), pixels per work-item (with n > 1 the
// program gets -DLB_LANES=n and the launch ceil(N / n) work-items per row),
// the `lum` buffer (made on demand, while the table lives: a LUT costs more
// than the rest of the plan; empty: table.packed()), every argument of
// Family::args by name, in order, and optionally:
// - bind: a binder for what a plan cannot hold (device buffers of its own,
//   the pre-passes' kernels);
// - finish: after the timed runs and the statistics launch, reads extra
//   buffers, fills stats / extraImages;
// - statsSwitch: the int argument (one of Family::args) that switches
//   per-pixel statistics on. Timed launches run with it 0, exactly the kernel
//   a renderer runs; one more, untimed launch with 1 feeds finish;
// - prePasses (multi-pass methods, methods/registry.h): the kernels run
//   before Family::kernelName on every launch of the image's first rows;
// - postPasses (an image filter): kernels run after Family::kernelName on
//   every launch that reaches the image's last row, timed with it like the
//   pre-passes; they find the image as named["out"] and leave the result
//   there;
// - renderRes (0: the scene's res): the render kernel and the passes run on
//   a renderRes x renderRes image of the same receiver (LaunchContext::scene
//   is that scene, named["out"] its image), and the post-passes leave the
//   scene's image in named["image"] (mc's scale: MC below one sample per
//   pixel, upsampled).
struct Plan {
    using Passes = std::function<std::vector<StageEvent>(LaunchContext&)>;
    std::string defines;
    int lanes = 1;
    std::function<std::vector<float>()> lum;
    std::vector<PlanArg> args;
    std::function<void(LaunchContext&)> bind;
    std::function<void(LaunchContext&)> finish;
    std::string statsSwitch;
    Passes prePasses;
    Passes postPasses;
    int renderRes = 0;
};

using PlanHook =
    std::function<Plan(const MethodSpec&, const Scene&, const photometry::Table&, const ocl::DeviceInfo&, Precision)>;

// A method family: its name, the scenes and light shapes it renders, its
// kernel and parameter table, and `plan`, which decides each render. The
// rest has defaults (nothing to check, every parameter used, one form, no
// frames to settle, cheap), so a family sets only what it needs.
struct Family {
    std::string name;
    std::string summary;  // one line for --help and docs/methods.md
    // The scenes it renders (docs/design.md sections 2, 8, 9). A name may be registered once per
    // scene kind: e.g. a "reference" for the specular scene in its own family
    // file and kernel, beside the diffuse one.
    std::vector<SceneKind> scenes{SceneKind::Diffuse};
    // The light shapes it renders (docs/design.md section 2); render refuses
    // any other with an InputError naming the methods that do.
    std::vector<LightShape> shapes{LightShape::Rect};
    std::string file;  // kernels/<file>
    std::string kernelName = "render";
    std::vector<Param> params;
    // The kernel's arguments after P, lum, out, row0, by name, in order.
    std::vector<std::string> args;
    // Decides one render (Plan): defines, lanes, lum, the arguments, passes, finish.
    PlanHook plan;

    // Check of a whole spec after its values are parsed (combinations a
    // single parameter cannot reject); throws InputError.
    std::function<void(const MethodSpec&)> validate = [](const MethodSpec&) {};
    // Whether parameter `name` has no effect under spec s (e.g. the
    // cubature's s3 with static=2); a tuner does not search such a parameter.
    std::function<bool(const MethodSpec&, const std::string&)> unused = [](const MethodSpec&, const std::string&) {
        return false;
    };
    // Stateful methods: launches of a static scene from a reset before
    // render() reads the image (the steady state of the method); 0: none.
    std::function<int(const MethodSpec&)> settleFrames = [](const MethodSpec&) { return 0; };
    // The program options its kernel file must build with, for a file whose
    // @variants line says "registry" (the test that builds every variant),
    // derived from the family's tables (e.g. the cubature's forms).
    std::function<std::vector<std::string>()> variants = [] { return std::vector<std::string>{}; };
    // Specs `lumibench bench` times besides the family's default (and its
    // specialize=none form): the structural variants worth a verdict.
    std::vector<std::string> benchSpecs;
    // The -D names that mark a straight-line form of this family's kernel
    // (empty: the family has one form, e.g. mc). kernelForm() reads them.
    std::vector<std::string> straightDefines;
    // Expensive (the reference): one untimed-warm-up-free run in bands of
    // bandRows rows with progress on stderr, cached on disk.
    bool expensive = false;
    int bandRows = 0;

    // The parameter `key`; InputError naming the valid ones otherwise.
    const Param& param(const std::string& key) const;
};

// The adaptive references (family_reference.cpp: the diffuse, specular and
// indirect scenes'): their kernels take errout, splits_out, rel_tol (spec
// "tol") and max_splits among Family::args.
void referenceArgs(Plan& p, const MethodSpec& s, const Scene& scene);  // the four arguments
void finishReference(LaunchContext& c);  // extra image "err", the split statistics
// Both for a kernel whose arguments are just those four; no defines, expensive.
void referenceIo(Family& f);

// The plan of `robust` at its defaults (family_cubature.cpp): the fallback
// of `sh` (family_sh.cpp).
Plan robustPlan(const Scene& scene, const photometry::Table& table, const ocl::DeviceInfo& device, Precision precision);

// Binds a plan's arguments by name (LaunchContext::arg), then plan.bind.
void bindPlan(LaunchContext& c, const Plan& plan);

// "straight-line" when the kernel built with `defines` is one of the family's
// straight-line forms, "general" when the family has such forms but this
// build is its general kernel, "" for a family with one form. Records carry
// it (stats.form), so a report can say which verdicts a general kernel made.
std::string kernelForm(const Family& f, const std::string& defines);
bool renders(const Family& f, SceneKind kind);

}  // namespace lb::methods
