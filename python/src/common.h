// common.h -- what the bindings of the Python module share (docs/python.md):
// one OpenCL runtime per device for the life of the process, the numpy <->
// Image conversions and the JSON documents handed to Python as dicts.
#pragma once

#include "cl/runtime.h"
#include "metrics/image.h"

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nlohmann/json.hpp>

#include <mutex>
#include <optional>

namespace lb::py {

namespace nb = nanobind;

// An image handed to Python: C-contiguous, res x res, float32 or float64.
using Array = nb::ndarray<nb::numpy, nb::ndim<2>, nb::c_contig>;

// The runtime of a device (device: an index >= 0, or none for the default
// device, as `--device` and $LUMIBENCH_DEVICE pick it), made on first use and
// kept: its program cache serves every later call. The lock serialises the
// calls that use it (a Runtime is not thread-safe); take both with the GIL
// released.
struct Device {
    ocl::Runtime& rt;
    std::unique_lock<std::mutex> lock;
};
Device device(std::optional<int> index);

// `img` as a numpy array: float64 takes over its pixels (no copy), float32
// converts them (one copy). Called with the GIL held.
Array toNumpy(Image&& img, bool asDouble);

// A 2D float32 or float64 numpy array (any strides) as an Image: one copy.
// InputError naming `what` (the argument) for another dtype, dimension or an
// empty array.
Image fromNumpy(nb::handle array, const char* what);

// str(h) as Python prints it (for messages).
std::string pyStr(nb::handle h);

// A JSON document as Python objects (dict, list, float, ...); NaN as None.
nb::object toPython(const nlohmann::json& j);

}  // namespace lb::py
