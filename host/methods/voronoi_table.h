// voronoi_table.h -- the Voronoi cell-fraction table the voronoi kernel reads
// (kernels/common/voronoi.h, thesis 5.1), built with the same header code.
#pragma once

#include <vector>

namespace lb::methods {

// res x res nodes over the dynamic point's position on a w x l light, six
// fractions per node (layout: lb_voronoi_lookup). res >= 2.
std::vector<float> voronoiTable(int res, double w, double l);

}  // namespace lb::methods
