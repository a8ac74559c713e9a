// metrics.h -- error of an approximation image A against a reference image R
// (docs/design.md section 5, thesis 6.2).
//
// All sums run in double over the pixels where A is finite; pixels where A is
// NaN or infinite are counted in `nonfinite` and left out of every average,
// the means included (so NMSE compares the same pixel set in numerator and
// denominator). A non-finite pixel in the reference is bad input.
//
//   NMSE   = (1/P) sum_i (R_i - A_i)^2 / (mean(R) mean(A))
//            thesis Eq. 6.7 (000_*.txt line 1137: "NMSE = 1/N sum_i (x_{R,i} -
//            x_{A,i})^2 / (\bar{R} \bar{A})", N the number of pixels, \bar{R},
//            \bar{A} the means of the reference and the approximation).
//   NRMSE  = sqrt(mean((R - A)^2)) / mean(R)
//   relMSE = mean((R - A)^2 / (R^2 + 1e-2 mean(R)^2))
//   UEB    = max(0, max_i (A_i - R_i))   largest over-estimate, >= 0, in lux
//   LEB    = min(0, min_i (A_i - R_i))   largest under-estimate, <= 0, in lux
//   grad_nmse = (1/M) sum_(i,j) (dR_ij - dA_ij)^2 / (mean(R) mean(A)) over
//            the M pairs (i, j) of horizontally or vertically neighbouring
//            pixels (both directions pooled), dR_ij = R_j - R_i and dA_ij =
//            A_j - A_i: it sees ripples and bumps, and not a smooth bias (a
//            constant offset gives 0). A pair that touches a non-finite test
//            pixel is left out of M; the means are NMSE's.
//   flip   = mean HDR-FLIP of A against R (metrics/flip.h); compare() leaves
//            it NaN, since it needs the Python co-process of flip.h.
//
// Sign convention of the bounds: both are values of the signed error A - R,
// as in the thesis' tables (e.g. Table B.1: UEB 160.25, LEB -8.4375), so LEB
// is negative (or zero when nothing is under-estimated) and |LEB| is the
// magnitude of the largest under-estimate.
//
// Undefined ratios (mean(R) = 0, mean(A) = 0, every pixel non-finite) come out
// as NaN or infinity, which the JSON form writes as null: never a made-up 0.
#pragma once

#include "metrics/image.h"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace lb::metrics {

struct Metrics {
    double nmse = 0, nrmse = 0, relmse = 0;
    double ueb = 0;  // >= 0, lux
    double leb = 0;  // <= 0, lux
    int64_t nonfinite = 0;  // test pixels that are NaN or +-inf (excluded)
    int64_t pixels = 0;  // all pixels of the image, non-finite ones included
    double mean_ref = 0, mean_test = 0;  // over the finite pixels, lux
    double grad_nmse = 0;
    int64_t grad_pairs = 0;  // neighbour pairs in grad_nmse (those touching non-finite pixels left out)
    double flip = std::numeric_limits<double>::quiet_NaN();  // NaN: not computed or not available
};

// Throws lb::InputError when the sizes differ, the images are empty or the
// reference holds a non-finite pixel.
void checkComparable(const Image& reference, const Image& test);

// Every metric but flip; throws as checkComparable.
Metrics compare(const Image& reference, const Image& test);

// The metrics of several images of equal kind pooled into one, as if they
// were stitched side by side into one image (the thesis computes its figures
// and appendix B on the rotations of a scene stitched this way; docs/
// thesis-sct-vs-mci.md): with P_i the finite pixels of part i,
//   mean_ref, mean_test = the pixel-weighted means sum P_i mean_i / sum P_i,
//   SSE_i = nmse_i P_i mean_ref_i mean_test_i (Eq. 6.7 solved for the sum),
//   nmse  = (sum SSE_i / sum P_i) / (mean_ref mean_test),
//   nrmse = sqrt(sum SSE_i / sum P_i) / mean_ref,
//   grad_nmse the same over the neighbour pairs of each part (pairs across
//   the seams are not made up), flip the pixel-weighted mean, ueb the
//   largest, leb the smallest, pixels, nonfinite and grad_pairs summed.
// relmse, which divides by each part's own mean, is not poolable: NaN.
// Parts with equal pixel counts give mean(SSE/P) / (mean(mean_ref)
// mean(mean_test)), the form plots/stitched_table.py computes.
Metrics pooled(const std::vector<Metrics>& parts);

// The metrics of R renders that differ only in their seed (a Monte Carlo
// method's draws), as an expectation: each real-valued metric the mean over
// the draws with its two-sided 95 % Student-t interval, mean -+ t(0.975,
// R - 1) s / sqrt(R) with s the draws' sample standard deviation (R >= 2;
// t from a table, exact to 3 digits). nonfinite is the largest of the
// draws' (one draw's non-finite pixel is a defect of the method), pixels
// the first's, grad_pairs the smallest. mean_ref, the same in every draw,
// gets no interval. flip's interval is left out when a draw has no FLIP.
struct SeedSummary {
    Metrics mean;
    int seeds = 1;
    std::map<std::string, std::array<double, 2>> ci95;  // metric key (to_json) -> [lo, hi]
};
// Throws lb::InputError for no draws.
SeedSummary overSeeds(const std::vector<Metrics>& draws);
// t(0.975, dof): the 97.5 % quantile of Student's t with dof >= 1 degrees of
// freedom (1.96 beyond 120).
double studentT975(int dof);

// The record keys of the metrics a search can minimise (tune's "metric"):
// nmse, nrmse, relmse, grad_nmse, flip, ueb, leb.
const std::vector<std::string>& minimisableMetrics();
// Metric `key` of m as a quantity to minimise: its value, for leb its
// magnitude -leb (LEB is <= 0). Throws lb::InputError for a key not in
// minimisableMetrics().
double minimisable(const Metrics& m, const std::string& key);

// JSON object with the keys nmse, nrmse, relmse, ueb, leb, nonfinite, pixels,
// mean_ref, mean_test, grad_nmse, grad_pairs, flip (non-finite numbers become
// null). from_json reads files written before grad_nmse and flip existed:
// those keys missing read as NaN (grad_pairs as 0).
void to_json(nlohmann::json& j, const Metrics& m);
void from_json(const nlohmann::json& j, Metrics& m);

}  // namespace lb::metrics
