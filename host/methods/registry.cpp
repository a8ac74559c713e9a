#include "methods/registry.h"

#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>

namespace lb::methods {

// One line per family (host/methods/family_*.cpp).
void registerReference(Registry& r);
void registerDynamic(Registry& r);
void registerStructured(Registry& r);
void registerMc(Registry& r);
void registerCubature(Registry& r);
void registerVoronoi(Registry& r);
void registerIndirect(Registry& r);
void registerSpecular(Registry& r);
void registerRobust(Registry& r);
void registerEngine(Registry& r);
void registerSh(Registry& r);

namespace {
Registry builtinFamilies()
{
    Registry r;
    registerReference(r);
    registerDynamic(r);  // point, cp, np, mrp
    registerStructured(r);
    registerMc(r);
    registerCubature(r);
    registerVoronoi(r);
    registerIndirect(r);  // reference (indirect), vpl, kmeans, acrsm (and mc: VPLs)
    registerSpecular(r);  // reference, mc, ltc of the specular scene
    registerRobust(r);
    registerEngine(r);
    registerSh(r);
    return r;
}
}  // namespace

std::string kernelForm(const Family& f, const std::string& defines)
{
    if (f.straightDefines.empty()) return "";
    for (const auto& d : f.straightDefines) {
        // whole words only: "-DLB_CUB_RECT_FAN" is not in "-DLB_CUB_RECT_FANX"
        for (size_t at = defines.find(d); at != std::string::npos; at = defines.find(d, at + 1)) {
            size_t end = at + d.size();
            if (end == defines.size() || defines[end] == ' ' || defines[end] == '=') return "straight-line";
        }
    }
    return "general";
}

Plan planFor(const Family& f, const MethodSpec& spec, const Scene& scene, const photometry::Table& table,
             const ocl::DeviceInfo& device, Precision precision)
{
    if (!f.plan) throw Error(fmt::format("method {}: the family has no plan (Family::plan)", f.name));
    return f.plan(spec, scene, table, device, precision);
}

void bindPlan(LaunchContext& c, const Plan& plan)
{
    for (const auto& a : plan.args) {
        switch (a.kind) {
        case PlanArg::Kind::Real:
            c.realArg(a.name, a.value);
            break;
        case PlanArg::Kind::Int:
            c.arg(a.name, cl_int(a.value));
            break;
        case PlanArg::Kind::Float:
            c.arg(a.name, cl_float(a.value));
            break;
        case PlanArg::Kind::Reals:
            c.arg(a.name, c.realBuffer(a.reals));
            break;
        case PlanArg::Kind::Floats: {
            std::vector<float> f = a.floats;
            f.resize(std::max<size_t>(f.size(), 1), 0.0f);
            cl::Buffer b(c.rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, f.size() * sizeof(float), f.data());
            c.buffers.push_back(b);
            c.arg(a.name, b);
            break;
        }
        case PlanArg::Kind::OutputInts:
            c.named[a.name] = c.outputInts(a.count);
            c.arg(a.name, c.named[a.name]);
            break;
        case PlanArg::Kind::OutputReals:
            c.named[a.name] = c.outputReals(a.count);
            c.arg(a.name, c.named[a.name]);
            break;
        case PlanArg::Kind::Device:  // plan.bind's
            if (!plan.bind)
                throw Error(
                    fmt::format("method {}: argument '{}' is left to a plan without bind", c.family.name, a.name));
            break;
        }
    }
    if (plan.bind) plan.bind(c);
}

std::string precisionName(Precision p) { return p == Precision::Double ? "double" : "float"; }

Precision parsePrecision(const std::string& s)
{
    if (s == "float") return Precision::Float;
    if (s == "double") return Precision::Double;
    throw InputError(fmt::format("expected float or double, got '{}'", s));
}

bool renders(const Family& f, SceneKind kind)
{
    return std::find(f.scenes.begin(), f.scenes.end(), kind) != f.scenes.end();
}

void Registry::add(Family f)
{
    for (SceneKind k : f.scenes)
        if (find(f.name, k))
            throw Error(fmt::format("method {} registered twice for the {} scene", f.name, sceneKindName(k)));
    families_.push_back(std::move(f));
}

const Family* Registry::find(const std::string& name, SceneKind kind) const
{
    for (auto& f : families_)
        if (f.name == name && renders(f, kind)) return &f;
    return nullptr;
}

std::string Registry::names(SceneKind kind) const
{
    std::vector<std::string> n;
    for (auto& f : families_)
        if (renders(f, kind)) n.push_back(f.name);
    return fmt::format("{}", fmt::join(n, "|"));
}

const Registry& registry()
{
    static const Registry r = builtinFamilies();
    return r;
}

const Family& family(const std::string& name, SceneKind kind)
{
    const Family* f = registry().find(name, kind);
    if (f) return *f;
    if (kind != SceneKind::Diffuse || registry().find(name, SceneKind::Specular) ||
        registry().find(name, SceneKind::Indirect)) {
        bool known = false;
        for (auto& g : registry().all()) known = known || g.name == name;
        if (known)
            throw InputError(fmt::format("method '{}' does not render the {} scene (methods that do: {})", name,
                                         sceneKindName(kind), registry().names(kind)));
    }
    throw InputError(fmt::format("unknown method '{}'; valid methods{}: {}", name,
                                 kind == SceneKind::Diffuse ? "" : " for the " + sceneKindName(kind) + " scene",
                                 registry().names(kind)));
}

cl::Buffer LaunchContext::realBuffer(const std::vector<double>& v)
{
    size_t n = std::max<size_t>(v.size(), 1);
    cl::Buffer b;
    if (dbl()) {
        std::vector<double> d(v);
        d.resize(n, 0.0);
        b = cl::Buffer(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n * sizeof(double), d.data());
    } else {
        std::vector<float> f(v.begin(), v.end());
        f.resize(n, 0.0f);
        b = cl::Buffer(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n * sizeof(float), f.data());
    }
    buffers.push_back(b);
    return b;
}

cl::Kernel& LaunchContext::pass(const std::string& name)
{
    auto it = passKernels.find(name);
    if (it == passKernels.end()) it = passKernels.emplace(name, rt.kernel(family.file, name, options)).first;
    return it->second;
}

cl::Buffer LaunchContext::outputReals(size_t n)
{
    cl::Buffer b(rt.context(), CL_MEM_READ_WRITE, std::max<size_t>(n, 1) * (dbl() ? sizeof(double) : sizeof(float)));
    buffers.push_back(b);
    return b;
}

cl::Buffer LaunchContext::outputInts(size_t n)
{
    cl::Buffer b(rt.context(), CL_MEM_READ_WRITE, std::max<size_t>(n, 1) * sizeof(cl_int));
    buffers.push_back(b);
    return b;
}

cl_uint LaunchContext::argIndex(const std::string& name) const
{
    for (size_t i = 0; i < family.args.size(); ++i)
        if (family.args[i] == name) return kCommonArgs + static_cast<cl_uint>(i);
    throw Error(fmt::format("method {}: kernel argument '{}' is not declared in Family::args", family.name, name));
}

void LaunchContext::realArg(const std::string& name, double value)
{
    ocl::setReal(kernel, argIndex(name), value, dbl());
}

std::vector<double> LaunchContext::readReals(cl::Buffer& b, size_t n)
{
    std::vector<double> out(n);
    if (dbl()) {
        rt.queue().enqueueReadBuffer(b, CL_TRUE, 0, n * sizeof(double), out.data());
    } else {
        std::vector<float> f(n);
        rt.queue().enqueueReadBuffer(b, CL_TRUE, 0, n * sizeof(float), f.data());
        for (size_t i = 0; i < n; ++i) out[i] = f[i];
    }
    return out;
}

void checkShape(const Family& f, const Scene& scene)
{
    if (std::find(f.shapes.begin(), f.shapes.end(), scene.shape) != f.shapes.end()) return;
    std::string names;
    for (const auto& g : registry().all())
        if (renders(g, scene.kind) && std::find(g.shapes.begin(), g.shapes.end(), scene.shape) != g.shapes.end())
            names += (names.empty() ? "" : ", ") + g.name;
    throw InputError(fmt::format("method {}: renders a rectangular light only, not shape={}; methods for it: {}",
                                 f.name, lightShapeName(scene.shape), names));
}

}  // namespace lb::methods
