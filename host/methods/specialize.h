// specialize.h -- "leave out what a given scene does not need": the
// host analyses one scene and luminaire and picks the smallest kernel variant.
//
// Rules (each one only drops work whose result is known to be 0 or the
// identity, so the specialised kernel equals the general one up to rounding;
// tests/methods/test_specialize.cpp checks <= 1e-6 relative):
//   noHorizon  every light corner lies strictly above the receiver plane of
//              every image pixel (n_x . (p - x) > 0 at the 4 light corners x
//              the 4 image corners; both are linear, so the extremes are
//              there): the light is convex, so every sample has a positive
//              receiver cosine and the clip / max(0, cos) path goes.
//   noBack     the luminaire emits nothing at gamma >= 90 deg: a pixel on or
//              behind the light's plane receives nothing; mc.cl skips the loop
//              of every work-group whose whole tile lies there (group-uniform,
//              because of its per-sample barrier).
//   lut1d      (with the LUT) every C plane is equal: 1D table over gamma,
//              no azimuth computation.
//   fan        (cubature) triangulation=fan: no flip machinery (already a
//              structural define of cubature.cl, LB_CUB_TRI=0).
//   rectFan    (cubature) nothing is clipped -- every light corner lies more
//              than horizon_eps + plane_eps above the receiver plane of every
//              pixel (the plane shift moves a receiver by up to plane_eps
//              before the tilted-horizon clip) --, and the method is a fan
//              around CP or corner 0 (any weighting, normalize none or
//              formfactor), or Delaunay over corners + CP, which never flips
//              there (below); `blend` (LB_CUB_BLEND) where some pixel lies
//              beyond blend_dist from the light's centre (the pixel farthest
//              away is an image corner), the far-field blend in the same
//              straight-line code:
//              LB_CUB_RECT_FAN, the straight-line
//              lb_cub_rect_fan of common/cubature.h (no clip, no
//              triangulation structure, no loops; PoCL vectorises it).
//              Why Delaunay over corners + CP is the fan around CP: the
//              general code's in-circle test on the lifts r = |p| (p relative
//              to the receiver, r = sqrt(u^2 + v^2 + h^2) over the light's
//              plane) keeps an edge iff each opposite vertex lies strictly
//              above the plane through the lifts of the other triangle, and r
//              is strictly convex (h != 0) with CP its minimum over the
//              rectangle. Two facts: (i) in a rectangle inside one quadrant
//              around the receiver's foot O, r_uv = -uv / r^3 <= 0, so r
//              of the diagonal through the corner nearest O sums below the
//              other diagonal's (submodularity); (ii) r - (a plane) is convex
//              along any line. CP at a corner: (i) on the light itself, so the
//              diagonal from CP is Delaunay. CP inside (CP = O) and edge CP-c
//              of the fan with neighbours c-, c+: let E, M be the feet of c
//              on the two axes through O (on the edges through c); plane P
//              through CP, c-, c and plane Q through CP, E, c agree on the
//              line O-c, and P >= Q on E's side (r - P <= 0 at E by (ii)
//              between c- and c), so P <= Q < r at M by (i) on the rectangle
//              O, E, c, M; then (ii) along the edge c-M-c+ (r - P = 0 at c,
//              > 0 at M) gives r > P at c+: no flip. CP on an edge (O
//              outside): the same with E = c- on CP's edge. The argument is
//              exact for CP itself; CP snapped onto an edge or corner within
//              eps (the foot then lies up to eps inside) is covered by test,
//              not by it: tests/cubature (DelaunayCornersAndCpNeverFlipOn-
//              UnclippedRectangle) finds no flip in 23,000 random receivers,
//              most of them within a few eps of an edge or corner, and
//              tests/methods/test_specialize.cpp holds the images and flip
//              counts to the general kernel.
//   rectClip   (cubature) rectFan, rectDel and rectDelAll also where the
//              horizon cuts the light (h < 0, or horizon_eps + plane_eps
//              above the lowest corner), if it cuts along the light's u
//              edges: the receiver normal is perpendicular to u (au = 0
//              exactly, as in every normalized scene), so n_x . p does not
//              depend on u and what is left is again a rectangle, on which
//              the same straight-line code runs (LB_CUB_RECT_CLIP, lb_cub_rect_clip of
//              common/cubature_lanes.inc). Not for dynamic=none (its fan
//              starts at the clipped polygon's first vertex), nor for
//              normalize=formfactor (the clipped Lambert edge sum in float
//              measured 4x the general kernel's error at grazing receivers).
//   rectDel    (cubature) as rectFan, for triangulation=delaunay with
//              dynamic=cp+barycentre: LB_CUB_RECT_DEL, lb_cub_rect_del of
//              common/cubature_lanes.inc (the two edges that can flip decided
//              by the same in-circle test, no loops).
//   rectDelAll (cubature) triangulation=delaunay with dynamic=cp+np+mrp+
//              barycentre where the receiver normal is perpendicular to the
//              light's u axis (horizonAlongU: then NP, MRP and CP lie on one
//              line of constant u), on the light or on what rectClip leaves
//              of it (the barycentre and NP's clamp are the clipped
//              rectangle's, as the general code's clipped polygon):
//              LB_CUB_RECT_DELALL,
//              lb_cub_rect_delall of common/cubature_lanes.inc (two ladders
//              of two decisions each and the barycentre's cavity; the
//              structure and its brute-force checks are described there).
//   rectDelStatic (cubature) triangulation=delaunay with dynamic=cp and 1 to 4
//              static samples where nothing is clipped and each sample lies
//              at least 1 % of the light's size inside it (so that it never
//              merges with a corner or splits a hull edge):
//              LB_CUB_RECT_DELST, lb_cub_rect_delst (one sample) and
//              lb_cub_rect_delstk of common/cubature_lanes.inc (the fan
//              around CP and each sample's cavity in turn).
#pragma once

#include "methods/cubature_options.h"

#include "photometry/table.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <string>

namespace lb::methods {

struct Specialization {
    bool lut = false;  // LB_LUT: trig-free table (common/lut.h)
    bool lut1d = false;  // LB_LUT_1D
    bool noHorizon = false;  // LB_NO_HORIZON
    bool noBack = false;  // LB_NO_BACK
    bool rectFan = false;  // LB_CUB_RECT_FAN (cubature only)
    bool rectDel = false;  // LB_CUB_RECT_DEL (cubature only)
    bool rectDelAll = false;  // LB_CUB_RECT_DELALL (cubature only)
    bool rectDelStatic = false;  // LB_CUB_RECT_DELST (cubature only)
    bool rectClip = false;  // LB_CUB_RECT_CLIP: with rectFan / rectDel / rectDelAll, the horizon cuts along u
    bool blend = false;  // LB_CUB_BLEND: some pixel blends (with a straight-line form)

    std::string defines() const;  // " -DLB_LUT ..." (leading space when not empty)
    // Whether a straight-line cubature form runs (any rect* rule but rectClip).
    bool rectForm() const { return rectFan || rectDel || rectDelAll || rectDelStatic; }
    nlohmann::json json() const;
};

// The analysis above; `lut` says whether the trig-free table is wanted, and
// `specialize` = false gives the general kernel (only the lookup choice).
Specialization analyse(const Scene& scene, const photometry::Table& table, bool lut, bool specialize = true);

// The cubature's analysis: lookup, lut1d and rectFan (the other rules do not
// apply to cubature.cl). o.lut and o.specialize choose as for mc.
Specialization analyseCubature(const Scene& scene, const photometry::Table& table, const CubatureOptions& o);

// Pixels per work-item for the cubature: o.lanes (lanesFor, methods/straight.h)
// where a straight-line form (rectForm) runs in float with the LUT, else 1.
int cubatureLanes(const Specialization& s, const CubatureOptions& o, const std::string& deviceType, bool dbl);

// Whether the receiver normal is perpendicular to the light's u axis, exactly
// in float and double (every normalized scene): the horizon then cuts the
// light along its u edges (rule rectClip).
bool horizonAlongU(const Scene& scene);

// Whether every light corner is more than `margin` (m) above the receiver of
// every pixel.
bool lightAboveEveryHorizon(const Scene& scene, double margin = 0);

}  // namespace lb::methods
