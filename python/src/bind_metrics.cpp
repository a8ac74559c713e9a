// bind_metrics.cpp -- lb.compare, lb.read_exr and lb.write_exr: the metrics
// of `lumibench compare` (metrics::compare, metrics::flip) on numpy arrays,
// and the EXR files the CLI reads and writes.
#include "common.h"

#include "metrics/flip.h"
#include "metrics/metrics.h"
#include "util/error.h"

#include <fmt/format.h>
#include <nanobind/stl/string.h>

namespace lb::py {

namespace {

nb::object compare(nb::handle ref, nb::handle img, bool withFlip)
{
    const Image R = fromNumpy(ref, "ref"), A = fromNumpy(img, "img");
    metrics::Metrics m;
    {
        nb::gil_scoped_release unlocked;
        try {
            m = metrics::compare(R, A);
        } catch (const InputError& e) {
            throw InputError(fmt::format("ref vs img: {}", e.what()));
        }
        if (withFlip) m.flip = metrics::flip(R, A);
    }
    nlohmann::json j = m;
    j["width"] = R.width;
    j["height"] = R.height;
    return toPython(j);
}

nb::object readExr(const std::string& path)
{
    Image img;
    {
        nb::gil_scoped_release unlocked;
        img = lb::readExr(path);
    }
    // The file's channel is FLOAT: float32 holds every value exactly.
    return nb::cast(toNumpy(std::move(img), false));
}

void writeExr(const std::string& path, nb::handle array)
{
    const Image img = fromNumpy(array, "array");
    nb::gil_scoped_release unlocked;
    lb::writeExr(path, img);
}

const char* kCompareDoc = R"(The metrics of `lumibench compare REF TEST --json` (docs/design.md section 5)
of the image `img` against the reference `ref`, both 2D numpy arrays of
float32 or float64 of one shape: nmse, nrmse, relmse, ueb, leb, nonfinite,
pixels, mean_ref, mean_test, grad_nmse, grad_pairs, flip (None when
flip-evaluator is not available, or flip=False), width, height. The values
equal `compare` on the arrays written as EXR files (float32).)";

}  // namespace

void bindMetrics(nb::module_& m)
{
    m.def("compare", &compare, nb::arg("ref"), nb::arg("img"), nb::kw_only(), nb::arg("flip") = true, kCompareDoc);
    m.def("read_exr", &readExr, nb::arg("path"),
          "Channel Y of an OpenEXR file as a float32 array (rows x columns, row 0 "
          "at the top). ValueError naming the file when it is missing, unreadable or has no channel Y.");
    m.def("write_exr", &writeExr, nb::arg("path"), nb::arg("array"),
          "Writes a 2D float32 or float64 array as a single-channel FLOAT OpenEXR "
          "file (channel Y), as `lumibench render --out` does, atomically: nothing is left behind when the write "
          "fails.");
}

}  // namespace lb::py
