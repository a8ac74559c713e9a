// voronoi: thesis 5.1 -- corners + barycentre + closest point weighted by
// precomputed Voronoi cell fractions (kernels/voronoi.cl, common/voronoi.h,
// the table from voronoi_table.h).
#include "methods/registry.h"
#include "methods/straight.h"
#include "methods/voronoi_table.h"

namespace lb::methods {

void registerVoronoi(Registry& r)
{
    Family f;
    f.name = "voronoi";
    f.summary = "Voronoi cubature (thesis 5.1): tabulated cell areas of corners + barycentre + closest point";
    f.file = "voronoi.cl";
    f.params = {
        Param::integer("table_res", 33, 2, 1025, Scale::Log,
                       "nodes per side of the cell-fraction table over the closest point's position on the light"),
        Param::real("plane_eps", 1e-3, 1e-6, 0.1, Scale::Log,
                    "receivers closer than this (m) to the light's plane are moved to this distance (paper 5.3)"),
    };
    // lookup, specialize, lanes; the straight-line form holds in every
    // scene: the method never clips (common/voronoi_lanes.inc)
    const StraightLine straight =
        addStraightLineOptions(f, "-DLB_VOR_RECT", [](const Scene&, const MethodSpec&) { return true; });
    f.args = {"tab", "tres", "plane_eps"};
    f.plan = [straight](const MethodSpec& s, const Scene& scene, const photometry::Table& t, const ocl::DeviceInfo& dev,
                        Precision p) {
        Plan plan = straight.plan(s, scene, t, dev, p);
        const int res = static_cast<int>(s.integer("table_res"));
        // The table is built for the scene's W x L light on every render (res^2
        // nodes of a closed-form Voronoi clip; ~1 ms at 33^2), untimed.
        plan.args = {PlanArg::floatBuffer("tab", voronoiTable(res, scene.width, scene.length)),
                     PlanArg::integer("tres", res), PlanArg::real("plane_eps", s.num("plane_eps"))};
        return plan;
    };
    r.add(f);
}

}  // namespace lb::methods
