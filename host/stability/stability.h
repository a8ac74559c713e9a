// stability.h -- every registered method, in float and double, on a
// catalogue of extreme scenes (`lumibench stability`).
//
// The catalogue (catalogue()) is a table of cases: a scene, a luminaire and
// what is expected of every method there. run() renders each case with the
// double-precision reference and with every family of methods::registry()
// (default parameters) in both precisions, and measures per method and
// precision:
//   nonfinite    pixels that are NaN or infinite (must be 0 everywhere);
//   negative     finite pixels below 0 (must be 0 everywhere);
//   max_rel_err  max_i |A_i - R_i| / max(R_i, floor), R the double reference,
//                floor = 1e-2 max(R): pixels where the reference is (near)
//                zero are judged relative to 1 % of the image maximum, so
//                that the dark fringe of a light does not turn a 1e-9 lux
//                difference into an "error of 1000 %". A black reference
//                (max R = 0) gives the absolute max |A_i| (lux);
//   max_jump     max over 4-neighbour pairs |A_i - A_j| / max|A| (the method's
//                own largest step between neighbouring pixels);
//   jump_excess  max over the same pairs (|A_i - A_j| - |R_i - R_j|) / max(R):
//                how far a step exceeds the reference's own step there, i.e.
//                the spurious discontinuity the method adds;
//   fd_diff      max_i |A_float_i - A_double_i| / max(R): float vs double of
//                the same method, on the scale of the answer (a method that
//                is ~0 everywhere must not turn float noise into 100 %);
//   point_diff   (far-field cases) max_i |A_i - P_i| / max(P), P the double
//                point-light image.
// A case fails when a requirement below is not met; the command then exits 1.
#pragma once

#include "cl/runtime.h"
#include "metrics/image.h"
#include "photometry/table.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace lb::stability {

enum class Expect {
    Finite,  // finite everywhere; errors reported (max_rel_err is a method's inherent error, not bounded)
    PointLimit,  // far field: every method within pointBound of the point light
    Zero,  // the luminaire sends nothing towards the receiver: all pixels exactly 0
    Rejected,  // degenerate light: render() must throw lb::InputError
};
std::string expectName(Expect e);

struct Case {
    std::string name;
    std::string what;  // one line: what the case stresses, the source
    double height = 1, rotation = 3.14159265358979323846, width = 1, length = 1, extent = 5;
    // methods::loadLuminaire name, "stab:<kind>" or "shared:<path>" (a file of
    // ../shared/luminaires; the case is skipped where it is absent): stability::luminaire.
    std::string luminaire;
    Expect expect = Expect::Finite;
    LightShape shape = LightShape::Rect;
    bool oddRes = false;  // force an odd resolution (a pixel row exactly at y = 0)
    bool quick = false;  // part of the --quick subset (CI)
    double maxFd = 0.05;  // bound on fd_diff (float vs double of one method)
    // Bounds on max_rel_err by family name, "*" for every family not named;
    // none: unbounded (a method's inherent error is reported, not judged).
    // Where set they hold each method to its measured error (docs/usage.md,
    // "Numerical stability"), so that garbage or a regression fails.
    std::vector<std::pair<std::string, double>> maxRel;
    // The scene's kind and its values (scene/scene.h); each case runs the
    // methods that render its kind (methods::renders).
    SceneKind kind = SceneKind::Diffuse;
    double alpha = Scene{}.alpha;
    glm::dvec3 eye = Scene{}.eye;
    double albedo = Scene{}.albedo;
};

// The catalogue of extreme scenes (stability.cpp).
const std::vector<Case>& catalogue();
// The case's bound on max_rel_err of `method` (Case::maxRel; +inf when none).
double relBound(const Case& c, const std::string& method);

// Luminaires of the catalogue: "stab:upward" (emits only at gamma > 90),
// "stab:pencil" (Gaussian beam sigma 0.5 deg, measured to gamma 10 deg),
// "shared:<path>" (../shared/luminaires/<path> beside the source tree), else
// methods::loadLuminaire (files, short names, analytic:cos<n>).
photometry::Table luminaire(const std::string& name);
// "" when the case's luminaire can be loaded; else why not (a "shared:" file
// that is absent: the data lie outside the repository, so run() skips the case).
std::string missingLuminaire(const Case& c);

// Metrics of one image A against the reference R (both res x res).
struct Errors {
    long nonfinite = 0;
    long negative = 0;  // finite pixels below 0 (irradiance is never negative)
    double maxRelErr = 0, maxJump = 0, jumpExcess = 0;
};
// Pixels flagged in `skip` (same size, or empty: none) are left out of
// max_rel_err and of the jumps; non-finite and negative pixels count everywhere.
Errors measure(const Image& ref, const Image& A, const std::vector<bool>& skip = {});
// The pixels whose receiver point lies on the light itself (in its plane, to
// 1e-9 of the scene's size, and inside its outline): there the irradiance of
// a light that emits at gamma 90 diverges (logarithmically, as 1 / r^2 over
// the light around the point), so neither the reference nor a method has a
// value to be held to; they must still be finite and not negative.
std::vector<bool> onLight(const Scene& s);
// What a method may give there: the irradiance at eps from the light's plane
// (the plane shift's distance) is at most I_max / A times the integral of
// 1 / r^2 over the plane within the light's diagonal D of the foot point,
// pi ln(1 + D^2 / eps^2).
double onLightBound(const Scene& s, const photometry::Table& t, double eps);
// max_i |A_i - B_i| / scale (absolute when scale <= 0) over the pixels not
// flagged in skip; NaN if any is non-finite.
double maxDiffRel(const Image& A, const Image& B, double scale, const std::vector<bool>& skip = {});

struct Row {
    std::string method, spec, precision;
    Errors err;
    double fdDiff = 0;  // float rows: vs the same method in double; double rows: 0
    double pointDiff = -1;  // PointLimit cases only
    double maxAbs = 0;  // max |A| (lux): Zero cases require exactly 0
    std::vector<std::string> failures;
    Image image;  // kept for the worst-error pictures
};

struct CaseResult {
    Case c;
    int res = 0;
    std::string rejected;  // Rejected cases: the InputError messages (first one)
    std::string skipped;  // why the case did not run (missingLuminaire), "" when it ran
    double refMax = 0, refErrEst = 0;  // max of the double reference off the light (onLight), its error estimate
    Image reference;
    std::vector<Row> rows;
    std::vector<std::string> failures;  // case-level (e.g. not rejected)
    bool ok() const;
};

struct Options {
    int res = 32;
    bool quick = false;
    std::vector<std::string> cases;  // only these (empty: all, or the quick subset)
    std::vector<std::string> methods;  // only these families (empty: every registered family)
    bool progress = false;
};

std::vector<CaseResult> run(ocl::Runtime& rt, const Options& opt);

// The scene of a case at resolution res (odd when the case asks for it).
Scene sceneOf(const Case& c, int res);
// Far-field bound on max|A - P| / max(P), P the point light (derivation in stability.cpp).
double pointBound(const Scene& s, bool dbl);
// The checks of one row of case c on its scene s, failures appended to
// row.failures: non-finite pixels; negative pixels; max_rel_err over
// relBound(c, row.method); a Zero case not exactly 0 (row.maxAbs);
// float vs double (row.fdDiff, NaN included) over c.maxFd; a PointLimit case
// farther than pointBound from `point` (the point light's image; sets
// row.pointDiff). `dbl`: the row is the double one.
void checkRow(const Case& c, const Scene& s, const Image& point, bool dbl, Row& row);

nlohmann::json toJson(const std::vector<CaseResult>& results, const ocl::Runtime& rt, const Options& opt);
// DIR/stability.json, DIR/report.md and DIR/png/<case>_{ref,test,err}.png of the
// worst (largest max_rel_err) method of every case.
void writeReport(const std::string& dir, const std::vector<CaseResult>& results, const ocl::Runtime& rt,
                 const Options& opt);

}  // namespace lb::stability
