// bind_luminaire.cpp -- lb.Luminaire: a luminaire file read as `lumibench
// render --luminaire` reads it (methods::loadLuminaire), its table as
// read-only numpy views that keep the Luminaire alive.
#include "common.h"

#include "methods/analytic.h"
#include "photometry/opening.h"
#include "photometry/table.h"

#include <nanobind/stl/string.h>

namespace lb::py {

namespace {

using photometry::Table;
using View1 = nb::ndarray<nb::numpy, const double, nb::ndim<1>, nb::c_contig>;
using View2 = nb::ndarray<nb::numpy, const double, nb::ndim<2>, nb::c_contig>;

// A read-only view of one of the table's vectors that keeps `self` alive.
View1 view1(nb::handle self, std::vector<double> Table::*member)
{
    const std::vector<double>& v = nb::cast<const Table&>(self).*member;
    return View1(v.data(), {v.size()}, self);
}

const char* kLuminaireDoc = R"(A luminaire: an IES LM-63 or EULUMDAT file, or 'analytic:cos<n>[:two]',
unfolded into one table of absolute candela over C in [0, 360] and gamma
(degrees; docs/design.md section 3). `candela[i, j]` is the intensity at
C = c[i], gamma = gamma[j]; the arrays are read-only views of the table.)";

const char* kLoadDoc = R"(Reads an IES or LDT file (or 'analytic:cos<n>[:two]') as `lumibench render
--luminaire` does. Raises ValueError with "FILE:LINE: expected ..., got ..."
for a bad file, naming it when it is missing.)";

}  // namespace

void bindLuminaire(nb::module_& m)
{
    nb::class_<Table>(m, "Luminaire", kLuminaireDoc)
        .def_static(
            "load",
            [](const std::string& path) {
                nb::gil_scoped_release unlocked;
                return methods::loadLuminaire(path);
            },
            nb::arg("path"), kLoadDoc)
        .def_prop_ro(
            "path", [](const Table& t) { return t.source; }, "The file read ('' if synthesised).")
        .def_prop_ro(
            "format", [](const Table& t) { return t.format; }, "'ldt', 'ies' or 'synth'.")
        .def_prop_ro(
            "symmetry", [](const Table& t) { return t.symmetry; },
            "'none', 'rotational', 'C0-C180', 'C90-C270' or 'quadrant'.")
        .def_prop_ro(
            "isym", [](const Table& t) { return t.isym; }, "EULUMDAT symmetry indicator 0..4 (-1 unknown).")
        .def_prop_ro(
            "flux_lm", [](const Table& t) { return t.fluxLm(); }, "Luminous flux integrated from the table (lm).")
        .def_prop_ro(
            "declared_flux_lm", [](const Table& t) { return t.declaredFluxLm > 0 ? t.declaredFluxLm : NAN; },
            "Flux the file declares (lm), nan if none.")
        .def_prop_ro(
            "max_cd", [](const Table& t) { return t.maxCd(); }, "Largest intensity (cd).")
        .def_prop_ro(
            "opening_shape", [](const Table& t) { return std::string(photometry::shapeName(t.opening.shape)); },
            "Luminous opening the file declares: 'point', 'rectangle', 'circle', 'ellipse', ...")
        .def_prop_ro(
            "opening_size",
            [](const Table& t) { return nb::make_tuple(t.opening.lengthM, t.opening.widthM, t.opening.heightM); },
            "(length along C0-C180, width along C90-C270, height) of the opening in metres.")
        .def_prop_ro(
            "c", [](nb::handle self) { return view1(self, &Table::c); }, "C angles (degrees, ascending, 0 .. 360).")
        .def_prop_ro(
            "gamma", [](nb::handle self) { return view1(self, &Table::gamma); }, "Gamma angles (degrees, ascending).")
        .def_prop_ro(
            "candela",
            [](nb::handle self) {
                const Table& t = nb::cast<const Table&>(self);
                return View2(t.cd.data(), {t.nc(), t.ng()}, self);
            },
            "Absolute intensity (cd), shape (len(c), len(gamma)).")
        .def(
            "intensity", [](const Table& t, double cDeg, double gammaDeg) { return t.intensity(cDeg, gammaDeg); },
            nb::arg("c"), nb::arg("gamma"),
            "Bilinear intensity (cd) at (C, gamma) in degrees, as the kernels look it up.")
        .def("__repr__", [](const Table& t) {
            return "lumibench.Luminaire('" + t.source + "', " + t.format + ", " + t.symmetry + ")";
        });
}

}  // namespace lb::py
