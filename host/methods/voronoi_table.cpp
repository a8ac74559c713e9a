// voronoi_table.cpp -- see voronoi_table.h.
#include "methods/voronoi_table.h"

#include "math/kmath.h"
#include "util/error.h"

namespace lb::methods {

std::vector<float> voronoiTable(int res, double w, double l)
{
    if (res < 2) throw InputError("voronoi: table resolution must be >= 2");
    std::vector<float> t(static_cast<size_t>(res) * res * LB_VOR_SITES);
    for (int jb = 0; jb < res; ++jb)
        for (int ia = 0; ia < res; ++ia) {
            double f[LB_VOR_SITES];
            glm::dvec2 p((double(ia) / (res - 1) - 0.5) * w, (double(jb) / (res - 1) - 0.5) * l);
            f64::lb_voronoi_fractions(p, w, l, f);
            for (int k = 0; k < LB_VOR_SITES; ++k) t[(jb * res + ia) * LB_VOR_SITES + k] = static_cast<float>(f[k]);
        }
    return t;
}

}  // namespace lb::methods
