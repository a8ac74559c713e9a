// kernel_args.h -- tests bind kernel arguments by name, never by position: a
// family's render kernel by its declared list (P, lum, out, row0, then
// Family::args, which Runtime.EveryKernelFileBuildsWithEveryVariant holds to
// the kernel's own names), any other kernel by the names its program reports
// (built with -cl-kernel-arg-info). A name the kernel does not have fails.
#pragma once

#include "cl/runtime.h"
#include "methods/registry.h"
#include "util/error.h"

#include <fmt/format.h>

#include <string>
#include <vector>

namespace lb::test {

class KernelArgs {
public:
    KernelArgs(cl::Kernel& k, std::vector<std::string> names, bool dbl) : k_(k), names_(std::move(names)), dbl_(dbl) {}

    // The render kernel of family f (real arguments in double where dbl).
    static KernelArgs of(cl::Kernel& k, const methods::Family& f, bool dbl)
    {
        std::vector<std::string> names = {"P", "lum", "out", "row0"};
        names.insert(names.end(), f.args.begin(), f.args.end());
        return KernelArgs(k, names, dbl);
    }
    // Any kernel, by CL_KERNEL_ARG_NAME: its program must be built with
    // -cl-kernel-arg-info (kArgInfo).
    static KernelArgs reported(cl::Kernel& k, bool dbl = false) { return KernelArgs(k, reportedNames(k), dbl); }
    static std::vector<std::string> reportedNames(cl::Kernel& k)
    {
        std::vector<std::string> names;
        for (cl_uint i = 0; i < k.getInfo<CL_KERNEL_NUM_ARGS>(); ++i)
            names.push_back(k.getArgInfo<CL_KERNEL_ARG_NAME>(i).c_str());  // drop a trailing NUL some drivers count
        return names;
    }
    static constexpr const char* kArgInfo = "-cl-kernel-arg-info";

    template <class T>
    KernelArgs& set(const std::string& name, const T& v)
    {
        k_.setArg(index(name), v);
        return *this;
    }
    // A `real` argument: float or double as the program was built.
    KernelArgs& real(const std::string& name, double v)
    {
        ocl::setReal(k_, index(name), v, dbl_);
        return *this;
    }
    cl_uint index(const std::string& name) const
    {
        for (size_t i = 0; i < names_.size(); ++i)
            if (names_[i] == name) return static_cast<cl_uint>(i);
        throw Error(fmt::format("kernel has no argument '{}' (it has {})", name, fmt::join(names_, ", ")));
    }

private:
    cl::Kernel& k_;
    std::vector<std::string> names_;
    bool dbl_;
};

// The program options the plan of spec's family gives spec on scene and
// table (a CPU device, float): the structural and per-scene defines.
inline std::string planDefines(const methods::MethodSpec& spec, const Scene& scene, const photometry::Table& t)
{
    ocl::DeviceInfo cpu;
    cpu.type = "CPU";
    return spec.plan(scene, t, cpu, methods::Precision::Float).defines;
}

}  // namespace lb::test
