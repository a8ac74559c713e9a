// common.cpp -- runtimes per device, numpy <-> Image, JSON -> Python (common.h).
#include "common.h"

#include "util/error.h"

#include <fmt/format.h>
#include <nanobind/stl/string.h>

#include <map>
#include <memory>
#include <vector>

namespace lb::py {

namespace {

struct Slot {
    std::unique_ptr<ocl::Runtime> rt;
    std::mutex use;
};

}  // namespace

Device device(std::optional<int> index)
{
    // Never destroyed: an OpenCL context torn down while the interpreter
    // exits can outlive its driver's own static state.
    static auto* slots = new std::map<int, Slot>();
    static std::mutex guard;
    const int i = ocl::chooseDevice(index ? *index : -1);  // InputError for a bad index
    std::unique_lock<std::mutex> g(guard);
    Slot& s = (*slots)[i];
    if (!s.rt) s.rt = std::make_unique<ocl::Runtime>(i);
    g.unlock();
    return {*s.rt, std::unique_lock<std::mutex>(s.use)};
}

Array toNumpy(Image&& img, bool asDouble)
{
    const size_t h = static_cast<size_t>(img.height), w = static_cast<size_t>(img.width);
    if (asDouble) {
        auto* px = new std::vector<double>(std::move(img.px));
        nb::capsule owner(px, [](void* p) noexcept { delete static_cast<std::vector<double>*>(p); });
        return Array(px->data(), {h, w}, owner, {}, nb::dtype<double>());
    }
    auto* px = new std::vector<float>(img.px.begin(), img.px.end());
    nb::capsule owner(px, [](void* p) noexcept { delete static_cast<std::vector<float>*>(p); });
    return Array(px->data(), {h, w}, owner, {}, nb::dtype<float>());
}

Image fromNumpy(nb::handle array, const char* what)
{
    nb::ndarray<nb::ro, nb::device::cpu> a;
    if (!nb::try_cast(array, a, false))
        throw InputError(fmt::format("{}: expected a 2D numpy array of float32 or float64, got {}", what,
                                     nb::type_name(array.type()).c_str()));
    const bool f32 = a.dtype() == nb::dtype<float>(), f64 = a.dtype() == nb::dtype<double>();
    if (!f32 && !f64) {
        const std::string dt = pyStr(array.attr("dtype"));
        throw InputError(fmt::format("{}: expected an array of float32 or float64, got dtype {}", what, dt));
    }
    if (a.ndim() != 2)
        throw InputError(fmt::format("{}: expected a 2D array (rows x columns), got {} dimensions", what, a.ndim()));
    if (a.shape(0) == 0 || a.shape(1) == 0)
        throw InputError(fmt::format("{}: expected at least 1 x 1 pixels, got {} x {}", what, a.shape(0), a.shape(1)));
    Image img(static_cast<int>(a.shape(1)), static_cast<int>(a.shape(0)));
    const auto* base = static_cast<const char*>(a.data());
    const size_t item = f32 ? sizeof(float) : sizeof(double);
    for (size_t r = 0; r < a.shape(0); ++r)
        for (size_t c = 0; c < a.shape(1); ++c) {
            const char* p = base + (r * a.stride(0) + c * a.stride(1)) * static_cast<int64_t>(item);
            img.px[r * a.shape(1) + c] = f32 ? *reinterpret_cast<const float*>(p) : *reinterpret_cast<const double*>(p);
        }
    return img;
}

std::string pyStr(nb::handle h)
{
    nb::object s = nb::steal(PyObject_Str(h.ptr()));
    if (!s.is_valid()) {
        PyErr_Clear();
        return "?";
    }
    return nb::cast<std::string>(s);
}

nb::object toPython(const nlohmann::json& j) { return nb::module_::import_("json").attr("loads")(j.dump()); }

}  // namespace lb::py
