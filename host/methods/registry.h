// registry.h -- method families: one .cl file plus one host file each.
//
// To add a family (say cubature): write kernels/cubature.cl with a kernel
//   __kernel void render(__global const real* P, __global const float* lum,
//                        __global real* out, int row0, <your arguments>)
// that fills out[row * res + col] for rows row0 .. row0 + get_global_size(1),
// then host/methods/family_cubature.cpp defining
//   void registerCubature(Registry& r) { r.add(Family{...}); }
// with Family::args naming <your arguments> in order (a test holds the list
// to the kernel's CL_KERNEL_ARG_NAME) and Family::plan, the one hook that
// decides a render: it parses the spec once into the program's defines, the
// lanes, the `lum` buffer, every argument of Family::args by name (PlanArg),
// and the finish (Plan, below); a test builds the plan of every method
// without a device. Add its one line to builtinFamilies() in registry.cpp.
// render(), `run`, `tune`, `stability` and `bench` all launch it through
// prepare() (methods/render.h), so the new family is rendered, timed and
// benchmarked without more code.
//
// Multi-pass methods (the indirect scene's RSM, clustering and evaluation)
// add, beside the one `render` kernel, Family::prePasses: a function that
// enqueues the kernels to run before `render` on each launch of the image's
// first rows -- any number, in order, each taken from the family's own
// program by LaunchContext::pass(name) (same file, same options) -- and
// returns their events with a stage name ("rsm", "cluster"). The method's
// device time is the sum of those events and the render kernel's (profiling
// events, Prepared::time), so render(), the runner, tune, stability and bench
// time the whole method through the same Prepared path, and
// Prepared::stageMs() gives the per-stage medians (bench's breakdown).
// Their pass kernels and own device buffers are bound by Plan::bind.
// Stateful methods (acrsm keeps its clusters from frame to frame) count their
// launches in LaunchContext::frame, which Prepared::reset() sets back to 0;
// Family::settleFrames says how many launches of a static scene render()
// makes from a reset before it reads the image.
#pragma once

#include "cl/runtime.h"
#include "metrics/image.h"
#include "methods/spec.h"
#include "methods/tunables.h"
#include "photometry/table.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace lb::methods {

enum class Precision { Float, Double };
std::string precisionName(Precision p);
Precision parsePrecision(const std::string& s);  // "float" | "double", else InputError (the caller names the source)

struct Family;

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
    // A kernel of the family's program (Family::file built with `options`) by
    // name, made once: the pre-passes' kernels.
    cl::Kernel& pass(const std::string& name);

    bool dbl() const { return precision == Precision::Double; }
    int res() const { return scene.res; }
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
// Family::args by name, in order, and optionally a binder for what a plan
// cannot hold (device buffers of its own, the pre-passes' kernels) and the
// finish (after the timed runs and the statistics launch: read extra
// buffers, fill stats / extraImages).
struct Plan {
    std::string defines;
    int lanes = 1;
    std::function<std::vector<float>()> lum;
    std::vector<PlanArg> args;
    std::function<void(LaunchContext&)> bind;
    std::function<void(LaunchContext&)> finish;
};

using PlanHook =
    std::function<Plan(const MethodSpec&, const Scene&, const photometry::Table&, const ocl::DeviceInfo&, Precision)>;

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
    // Optional check of a whole spec after its values are parsed (combinations
    // a single parameter cannot reject); throws InputError.
    std::function<void(const MethodSpec&)> validate;
    // Optional: whether parameter `name` has no effect under spec s (e.g. the
    // cubature's s3 with static=2); a tuner does not search such a parameter.
    std::function<bool(const MethodSpec&, const std::string&)> unused;
    // The kernel's arguments after P, lum, out, row0, by name, in order.
    std::vector<std::string> args;
    // Decides one render (Plan): defines, lanes, lum, the arguments, finish.
    PlanHook plan;
    // Optional: the int argument (one of args) that switches per-pixel
    // statistics on. Timed launches run with it 0, exactly the kernel a
    // renderer runs; one more, untimed launch with 1 feeds Plan::finish.
    std::string statsSwitch;
    // Specs `lumibench bench` times besides the family's default (and its
    // specialize=none form): the structural variants worth a verdict.
    std::vector<std::string> benchSpecs;
    // The -D names that mark a straight-line form of this family's kernel
    // (empty: the family has one form, e.g. mc). kernelForm() reads them.
    std::vector<std::string> straightDefines;
    // Optional: the program options its kernel file must build with, for a
    // file whose @variants line says "registry" (the test that builds every
    // variant), derived from the family's tables (e.g. the cubature's forms).
    std::function<std::vector<std::string>()> variants;
    // Optional multi-pass methods (see the top of this file): the kernels run
    // before `kernelName` on every launch of the image's first rows.
    std::function<std::vector<StageEvent>(LaunchContext&)> prePasses;
    // Optional post-passes (an image filter): kernels run after `kernelName`
    // on every launch that reaches the image's last row, timed with it like
    // the pre-passes; they find the image as named["out"] and leave the
    // result there.
    std::function<std::vector<StageEvent>(LaunchContext&)> postPasses;
    // Optional, stateful methods: launches of a static scene from a reset
    // before render() reads the image (the steady state of the method).
    std::function<int(const MethodSpec&)> settleFrames;
    // Expensive (the reference): one untimed-warm-up-free run in bands of
    // bandRows rows with progress on stderr, cached on disk.
    bool expensive = false;
    int bandRows = 0;
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

// The family's plan (Family::plan); Error for a family without one.
Plan planFor(const Family& f, const MethodSpec& spec, const Scene& scene, const photometry::Table& table,
             const ocl::DeviceInfo& device, Precision precision);
// Binds a plan's arguments by name (LaunchContext::arg), then plan.bind.
void bindPlan(LaunchContext& c, const Plan& plan);

// "straight-line" when the kernel built with `defines` is one of the family's
// straight-line forms, "general" when the family has such forms but this
// build is its general kernel, "" for a family with one form. Records carry
// it (stats.form), so a report can say which verdicts a general kernel made.
std::string kernelForm(const Family& f, const std::string& defines);

class Registry {
public:
    void add(Family f);  // Error when a name is registered twice for one scene kind
    const Family* find(const std::string& name, SceneKind kind = SceneKind::Diffuse) const;
    const std::vector<Family>& all() const { return families_; }
    std::string names(SceneKind kind = SceneKind::Diffuse) const;  // "reference|point|..."

private:
    std::vector<Family> families_;
};

// The registry with every built-in family (built once, on first use).
const Registry& registry();
// The family of `name` for scenes of `kind`; InputError listing the valid
// names for that kind when unknown.
const Family& family(const std::string& name, SceneKind kind = SceneKind::Diffuse);
// InputError unless the family renders the scene's light shape (Family::shapes),
// naming the methods that do.
void checkShape(const Family& f, const Scene& scene);
bool renders(const Family& f, SceneKind kind);

}  // namespace lb::methods
