#include "methods/family.h"

#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

namespace lb::methods {

const Family& MethodSpec::family() const
{
    if (!fam) throw Error(fmt::format("method {}: a spec without its family (made by parseSpec)", name));
    return *fam;
}

Plan MethodSpec::plan(const Scene& scene, const photometry::Table& table, const ocl::DeviceInfo& device,
                      Precision precision) const
{
    const Family& f = family();
    if (!f.plan) throw Error(fmt::format("method {}: the family has no plan (Family::plan)", f.name));
    return f.plan(*this, scene, table, device, precision);
}

double MethodSpec::num(const std::string& key) const { return std::strtod(str(key).c_str(), nullptr); }
long MethodSpec::integer(const std::string& key) const { return std::strtol(str(key).c_str(), nullptr, 10); }

const std::string& MethodSpec::str(const std::string& key) const
{
    auto it = values.find(key);
    if (it == values.end()) throw Error(fmt::format("method {} has no parameter {}", name, key));
    return it->second;
}

std::vector<std::string> MethodSpec::list(const std::string& key) const
{
    std::vector<std::string> items;
    const std::string& v = str(key);
    size_t b = 0;
    while (true) {
        size_t e = v.find('+', b);
        items.push_back(v.substr(b, e == std::string::npos ? std::string::npos : e - b));
        if (e == std::string::npos) break;
        b = e + 1;
    }
    return items;
}

MethodSpec MethodSpec::with(const std::string& key, const std::string& value) const
{
    const Family& f = family();
    MethodSpec r = *this;
    r.values[key] = f.param(key).canonical(f.name, value);
    r.given.insert(key);
    f.validate(r);
    return r;
}

std::string MethodSpec::canonical() const
{
    std::string out = name;
    char sep = ':';
    for (auto& [k, v] : values) {  // std::map: sorted keys
        out += sep + k + "=" + v;
        sep = ',';
    }
    return out;
}

nlohmann::json MethodSpec::paramsJson() const
{
    nlohmann::json j = nlohmann::json::object();
    for (auto& p : family().params) {
        const std::string& v = str(p.name);
        if (p.kind == Kind::Int)
            j[p.name] = integer(p.name);
        else if (p.kind == Kind::Real)
            j[p.name] = num(p.name);
        else
            j[p.name] = v;
    }
    return j;
}

const Param& Family::param(const std::string& key) const
{
    for (auto& p : params)
        if (p.name == key) return p;
    std::vector<std::string> names;
    for (auto& p : params) names.push_back(p.name);
    throw InputError(fmt::format("method {}: unknown parameter '{}'; valid: {}", name, key,
                                 names.empty() ? std::string("(none)") : fmt::format("{}", fmt::join(names, ", "))));
}

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

}  // namespace lb::methods
