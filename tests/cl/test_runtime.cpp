// The OpenCL layer: device listing, build errors, program cache, timing.
#include "kernel_args.h"
#include "methods/registry.h"
#include "testutil.h"
#include "util/error.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

namespace lb {
namespace {

TEST(Runtime, ListsAtLeastTheDefaultDevice)
{
    LB_REQUIRE_RUNTIME(rt);
    auto devs = ocl::listDevices();
    ASSERT_FALSE(devs.empty());
    EXPECT_EQ(rt->info().index, ocl::chooseDevice(-1));
    EXPECT_THROW(ocl::chooseDevice(static_cast<int>(devs.size())), InputError);
}

TEST(Runtime, ErrorStringsAreReadable)
{
    EXPECT_EQ(ocl::errorString(CL_OUT_OF_RESOURCES), "CL_OUT_OF_RESOURCES (-5)");
    EXPECT_EQ(ocl::errorString(-9999), "unknown OpenCL error (-9999)");
}

TEST(Runtime, BuildFailureCarriesTheLog)
{
    LB_REQUIRE_RUNTIME(rt);
    // A syntax error injected through -D must surface with the compiler's message.
    try {
        rt->program("selftest.cl", "-Dlb_clip_polygon=1+");
        FAIL() << "build should have failed";
    } catch (const Error& e) {
        std::string m = e.what();
        EXPECT_NE(m.find("selftest.cl"), std::string::npos) << m;
        EXPECT_NE(m.find("CL_BUILD_PROGRAM_FAILURE"), std::string::npos) << m;
        EXPECT_GT(m.size(), 100u) << "the build log is missing: " << m;
    }
}

TEST(Runtime, ProgramCacheReturnsSameProgram)
{
    LB_REQUIRE_RUNTIME(rt);
    cl::Program& a = rt->program("selftest.cl");
    double t = rt->buildSeconds();
    cl::Program& b = rt->program("selftest.cl");
    EXPECT_EQ(a(), b());
    EXPECT_EQ(rt->buildSeconds(), t);  // no second build
}

TEST(Runtime, TimingIsMedianOfRepetitions)
{
    auto t = ocl::summarize({5, 1, 3, 2, 4});
    EXPECT_EQ(t.median_ms, 3);
    EXPECT_EQ(t.min_ms, 1);
    EXPECT_EQ(t.max_ms, 5);
    EXPECT_EQ(t.reps, 5);
    EXPECT_EQ(ocl::summarize({4, 1, 3, 2}).median_ms, 2.5);
}

TEST(Runtime, ProfilingEventsGivePositiveTimes)
{
    LB_REQUIRE_RUNTIME(rt);
    size_t n = 4096;
    std::vector<float> tri(9 * n, 1.0f);
    cl::Buffer in(rt->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, tri.size() * 4, tri.data());
    cl::Buffer out(rt->context(), CL_MEM_WRITE_ONLY, n * 4);
    cl::Kernel k = rt->kernel("selftest.cl", "tri_solid_angle", test::KernelArgs::kArgInfo);
    test::KernelArgs::reported(k).set("tri", in).set("out", out).set("n", static_cast<int>(n));
    auto t = rt->time([&] { return rt->launch1D(k, n); }, 5);
    EXPECT_EQ(t.reps, 5);
    EXPECT_GT(t.min_ms, 0.0);
    EXPECT_LE(t.min_ms, t.median_ms);
}

// The argument names of kernel `name` of a built program (CL_KERNEL_ARG_NAME),
// or nothing where the program has no such kernel.
std::vector<std::string> kernelArgNames(cl::Program& prog, const std::string& name)
{
    std::vector<cl::Kernel> ks;
    prog.createKernels(&ks);
    for (auto& k : ks) {
        if (k.getInfo<CL_KERNEL_FUNCTION_NAME>() == name) return test::KernelArgs::reportedNames(k);
    }
    return {};
}

// Every kernel file declares its structural variants in a comment line
//   @variants: "" | "-DFOO" | "-DFOO -DBAR"
// or takes them from its families' tables with
//   @variants: registry
// (Family::variants, e.g. the cubature's from its form table), and must
// build with each of them (and with -DLB_DOUBLE added where the device has
// fp64, unless the variant already names it). In every variant,
// the kernel of each method family using the file takes exactly the
// arguments the family declares (P, lum, out, row0, then Family::args, by
// name): the host binds by those names, so a reordered or renamed kernel
// argument fails here instead of binding a value to the wrong slot.
// The variants of a kernel file whose @variants line says "registry": those
// of every family using the file (Family::variants), each once.
std::vector<std::string> registryVariants(const std::string& file)
{
    std::vector<std::string> out;
    for (const auto& fam : methods::registry().all())
        if (fam.file == file && fam.variants)
            for (const auto& v : fam.variants())
                if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
    return out;
}

TEST(Runtime, EveryKernelFileBuildsWithEveryVariant)
{
    LB_REQUIRE_RUNTIME(rt);
    namespace fs = std::filesystem;
    int built = 0, checked = 0;
    for (auto& e : fs::directory_iterator(ocl::kernelDir())) {
        if (e.path().extension() != ".cl") continue;
        std::ifstream f(e.path());
        std::string line, variants;
        while (std::getline(f, line))
            if (auto p = line.find("@variants:"); p != std::string::npos) {
                variants = line.substr(p + 10);
                break;
            }
        ASSERT_FALSE(variants.empty()) << e.path() << " declares no @variants line";
        const std::string file = e.path().filename().string();
        std::vector<std::string> list;
        std::regex q("\"([^\"]*)\"");
        for (std::sregex_iterator it(variants.begin(), variants.end(), q), end; it != end; ++it)
            list.push_back((*it)[1]);
        if (variants.find("registry") != std::string::npos) list = registryVariants(file);
        ASSERT_FALSE(list.empty()) << e.path() << ": no variants";
        for (const std::string& opts : list) {
            std::vector<std::string> all = {opts};
            if (rt->fp64() && opts.find("LB_DOUBLE") == std::string::npos) all.push_back(opts + " -DLB_DOUBLE");
            for (auto& o : all) {
                // -cl-kernel-arg-info: OpenCL reports argument names only then
                cl::Program* prog = nullptr;
                EXPECT_NO_THROW(prog = &rt->program(file, o + " -cl-kernel-arg-info")) << e.path() << " " << o;
                ++built;
                if (!prog) continue;
                for (const auto& fam : methods::registry().all()) {
                    if (fam.file != file) continue;
                    std::vector<std::string> want = {"P", "lum", "out", "row0"};
                    want.insert(want.end(), fam.args.begin(), fam.args.end());
                    EXPECT_EQ(kernelArgNames(*prog, fam.kernelName), want)
                        << "method " << fam.name << ": " << file << " " << o;
                    ++checked;
                }
            }
        }
    }
    EXPECT_GE(built, 2);
    EXPECT_GE(checked, static_cast<int>(methods::registry().all().size()));  // every family, at least once
}

}  // namespace
}  // namespace lb
