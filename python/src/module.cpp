// module.cpp -- lumibench._core, the extension behind the Python package
// `lumibench` (docs/python.md): a thin shell over the libraries the CLI
// links, like host/cli. Bad input (lb::InputError) raises
// lumibench.InputError, a ValueError, with the library's message; device and
// internal failures (lb::Error, cl::Error) lumibench.Error, a RuntimeError.
#include "common.h"
#include "scene_args.h"

#include "lb_build_config.h"
#include "util/error.h"

#include <fmt/format.h>

namespace lb::py {

void bindLuminaire(nb::module_& m);
void bindRender(nb::module_& m);
void bindMetrics(nb::module_& m);
void bindRun(nb::module_& m);

namespace {

PyObject* gInputError = nullptr;
PyObject* gError = nullptr;

void translate(const std::exception_ptr& p, void*)
{
    try {
        std::rethrow_exception(p);
    } catch (const InputError& e) {
        PyErr_SetString(gInputError, e.what());
    } catch (const Error& e) {
        PyErr_SetString(gError, e.what());
    } catch (const cl::Error& e) {
        PyErr_SetString(gError,
                        fmt::format("OpenCL error: {} failed: {}", e.what(), ocl::errorString(e.err())).c_str());
    }
}

}  // namespace

}  // namespace lb::py

NB_MODULE(_core, m)
{
    using namespace lb::py;
    m.doc() = "lumibench._core: the compiled part of the lumibench package (import lumibench).";
    gInputError = PyErr_NewExceptionWithDoc("lumibench.InputError",
                                            "Bad input: a file, a SPEC, a keyword's value (the CLI's exit code 2).",
                                            PyExc_ValueError, nullptr);
    gError =
        PyErr_NewExceptionWithDoc("lumibench.Error", "A device, internal or output failure (the CLI's exit code 1).",
                                  PyExc_RuntimeError, nullptr);
    m.attr("__version__") = LB_VERSION;
    m.attr("InputError") = nb::handle(gInputError);
    m.attr("Error") = nb::handle(gError);
    nb::register_exception_translator(&translate);
    bindLuminaire(m);
    bindScene(m);
    bindRender(m);
    bindMetrics(m);
    bindRun(m);
}
